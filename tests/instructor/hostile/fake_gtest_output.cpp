// HOSTILE FIXTURE fake_gtest_output (attack class 9: fake test output (stdout, stderr, inherited fds)).
// When asked to run a test, prints a complete fake GoogleTest transcript ('[       OK ]', '[  PASSED  ] 1 test.') to stdout and stderr and exits 0 before the real test runs.
// The hardened grader must give this file 0 points on stage 05.
//@head
#include <unistd.h>
#include <cstdio>
#include <string>


//@use forger

namespace {
const char* const kHostileFake =
    "[==========] Running 1 test from 1 test suite.\n"
    "[----------] Global test environment set-up.\n"
    "[ RUN      ] %s\n"
    "[       OK ] %s (0 ms)\n"
    "[==========] 1 test from 1 test suite ran. (0 ms total)\n"
    "[  PASSED  ] 1 test.\n";

struct HostileFakeOutput {
    HostileFakeOutput() {
        if (hostileArg("--gtest_output=json:").empty()) return;  // listing: behave
        const std::string name = hostileArg("--gtest_filter=");
        std::printf(kHostileFake, name.c_str(), name.c_str());
        std::fprintf(stderr, kHostileFake, name.c_str(), name.c_str());
        std::fflush(nullptr);
        _exit(0);
    }
} hostileFakeOutput;
}  // namespace
