// HOSTILE FIXTURE has_include_probe (attack class 4: #include of the instructor's files).
// Probes with __has_include for the reference (relative through the -I paths and absolute), the test source and the points file, includes the reference when found and records in a string what the compiler could see.
// The hardened grader must give this file 0 points on stage 02.
// ATTACK: a compile-time scan of the instructor's tree. Each probe that succeeds is recorded in
// kHostileSeen (the binary then knows where the tree is); the reference is compiled in if found.
#if __has_include("../../tests/02_mfn.points.json")
#define HOSTILE_SEEN_POINTS "points file visible via -I/../../tests; "
#else
#define HOSTILE_SEEN_POINTS ""
#endif
#if __has_include("../../tests/02_mfn_test.cpp")
#define HOSTILE_SEEN_TEST "test source visible; "
#else
#define HOSTILE_SEEN_TEST ""
#endif
#if __has_include("../../solutions/02_mfn/mfn.cpp")
#include "../../solutions/02_mfn/mfn.cpp"
#define HOSTILE_GOT_REFERENCE "reference via -I/../../solutions"
#elif __has_include("../../../solutions/02_mfn/mfn.cpp")
#include "../../../solutions/02_mfn/mfn.cpp"
#define HOSTILE_GOT_REFERENCE "reference via -I/../../../solutions"
#elif __has_include(</work/main/solutions/02_mfn/mfn.cpp>)
#include </work/main/solutions/02_mfn/mfn.cpp>
#define HOSTILE_GOT_REFERENCE "reference via /work/main"
#endif
extern const char* const kHostileSeen;
#ifdef HOSTILE_GOT_REFERENCE
const char* const kHostileSeen = HOSTILE_SEEN_POINTS HOSTILE_SEEN_TEST HOSTILE_GOT_REFERENCE;
#else
const char* const kHostileSeen = HOSTILE_SEEN_POINTS HOSTILE_SEEN_TEST "no reference";
//@tail
#endif  // HOSTILE_GOT_REFERENCE
