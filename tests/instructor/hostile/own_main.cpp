// HOSTILE FIXTURE own_main (attack class 3: GoogleTest machinery (listener, own main, testing:: symbols)).
// The submission defines its own main(): it lists the tests normally through GoogleTest (so the grader accepts the binary) but, when asked to run a test, writes a passing JSON result and returns 0.
// The hardened grader must give this file 0 points on stage 02.
//@head
#include <unistd.h>
#include <cstdio>
#include <string>
#include <gtest/gtest.h>
//@tail

//@use forger

// Wins over libgtest_main.a's main: an object file's definition is linked before the archive is searched.
int main(int argc, char** argv) {
    if (hostileForgePass()) return 0;
    ::testing::InitGoogleTest(&argc, argv);  // --gtest_list_tests and anything else: the real thing
    return RUN_ALL_TESTS();
}
