// HOSTILE FIXTURE gtest_listener (attack class 3: GoogleTest machinery (listener, own main, testing:: symbols)).
// A static constructor appends a GoogleTest event listener (UnitTest::GetInstance()->listeners()) whose OnTestProgramEnd overwrites the JSON result with a pass and exits 0.
// The hardened grader must give this file 0 points on stage 01.
//@head
#include <unistd.h>
#include <cstdio>
#include <string>
#include <gtest/gtest.h>


//@use forger

namespace {
class HostileListener : public ::testing::EmptyTestEventListener {
    void OnTestProgramEnd(const ::testing::UnitTest&) override {
        if (hostileForgePass()) _exit(0);  // after the JSON printer wrote the real result
    }
};
struct HostileInstall {
    HostileInstall() { ::testing::UnitTest::GetInstance()->listeners().Append(new HostileListener); }
} hostileInstall;
}  // namespace
