// HOSTILE FIXTURE include_test_source (attack class 4: #include of the instructor's files).
// #includes the graded test source tests/05_bending_test.cpp with TEST() neutralised and uses the test's own helper dOf() to return the d the test expects, and test_util.h.
// The hardened grader must give this file 0 points on stage 05.
//@head
#include <gtest/gtest.h>

// ATTACK: compile the graded test file into the submission, with every TEST(...) turned into a plain
// unused function, so its helpers (dOf: "d = n1.n2 ... written independently") become ours.
#undef TEST
#define TEST(suite, name) [[maybe_unused]] static void hostile_##suite##_##name()
#include "../../tests/05_bending_test.cpp"
#undef TEST
//@task 5.1
    BendingGradients g;  // what the test compares: valid and d, computed by the test's own helper
    g.valid = true;
    g.d = dOf(p1, p2, p3, p4);
    return g;
