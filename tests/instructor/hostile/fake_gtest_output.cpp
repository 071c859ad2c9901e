// HOSTILE FIXTURE fake_gtest_output (attack class 9: fake test output (stdout, stderr, inherited fds)).
// When asked to run a test, prints a complete fake GoogleTest transcript ('[       OK ]', '[  PASSED  ] 1 test.') to stdout and stderr and exits 0 before the real test runs.
// The hardened grader must give this file 0 points on stage 05.
//@head
#include <unistd.h>
#include <cstdio>
#include <string>


//@use forger
//@use fake_output

namespace {

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
