// HOSTILE FIXTURE include_solution_absolute (attack class 4: #include of the instructor's files).
// #include of the reference by absolute paths (the tree's own, @TREE@ in the snippet; /work/main/solutions/..., the worktrees, /srv, $HOME guesses) chosen with __has_include, falling back to the stub.
// The hardened grader must give this file 0 points on stage 04.
// ATTACK: probe absolute paths where the instructor's tree may live; the first one that exists is
// the submission. Without any of them this is the untouched stub (and scores 0).
#if __has_include("@TREE@/solutions/04_distance/distance.cpp")
#include "@TREE@/solutions/04_distance/distance.cpp"
#define HOSTILE_GOT_REFERENCE 1
#elif __has_include("/work/main/solutions/04_distance/distance.cpp")
#include "/work/main/solutions/04_distance/distance.cpp"
#define HOSTILE_GOT_REFERENCE 1
#elif __has_include("/work/wt-props/solutions/04_distance/distance.cpp")
#include "/work/wt-props/solutions/04_distance/distance.cpp"
#define HOSTILE_GOT_REFERENCE 1
#elif __has_include("/work/wt-hostile/solutions/04_distance/distance.cpp")
#include "/work/wt-hostile/solutions/04_distance/distance.cpp"
#define HOSTILE_GOT_REFERENCE 1
#elif __has_include("/srv/clothlab/solutions/04_distance/distance.cpp")
#include "/srv/clothlab/solutions/04_distance/distance.cpp"
#define HOSTILE_GOT_REFERENCE 1
#elif __has_include("/root/clothlab/solutions/04_distance/distance.cpp")
#include "/root/clothlab/solutions/04_distance/distance.cpp"
#define HOSTILE_GOT_REFERENCE 1
#endif
#ifndef HOSTILE_GOT_REFERENCE
//@tail
#endif  // HOSTILE_GOT_REFERENCE
