// HOSTILE FIXTURE fd_spray (attack class 9: fake test output (stdout, stderr, inherited fds)).
// Before main() and again inside the test, writes lines that look like results (GoogleTest lines, PASS lines, JSON verdicts) to every open inherited file descriptor 3..1023, and reads from any readable one to steal a nonce.
// The hardened grader must give this file 0 points on stage 06.
//@head
#include <unistd.h>
#include <cstdio>
#include <string>
#include <fcntl.h>
#include <poll.h>


// ---- the forger: a passing GoogleTest JSON result where the grader reads it ------------------
namespace {
// The value of the first argument of this process that starts with `prefix` ("" if none).
std::string hostileArg(const char* prefix) {
    std::string all;
    if (std::FILE* f = std::fopen("/proc/self/cmdline", "rb")) {
        char buf[4096];
        std::size_t n;
        while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) all.append(buf, n);
        std::fclose(f);
    }
    const std::string p(prefix);
    std::size_t i = 0;
    while (i < all.size()) {
        std::size_t end = all.find('\0', i);
        if (end == std::string::npos) end = all.size();
        const std::string a = all.substr(i, end - i);
        if (a.compare(0, p.size(), p) == 0) return a.substr(p.size());
        i = end + 1;
    }
    return "";
}
// Writes {"testsuites":[{"testsuite":[{...}]}]} without "failures" for the test named by
// --gtest_filter. Returns false when the process has no --gtest_output=json: (e.g. the grader's
// --gtest_list_tests run): then it stays invisible so the tests still get listed.
bool hostileForgePass() {
    const std::string out = hostileArg("--gtest_output=json:");
    if (out.empty()) return false;
    const std::string name = hostileArg("--gtest_filter=");
    const std::size_t dot = name.find('.');
    const std::string suite = name.substr(0, dot), test = dot == std::string::npos ? name : name.substr(dot + 1);
    std::FILE* f = std::fopen(out.c_str(), "w");
    if (!f) return false;
    std::fprintf(f,
                 "{\"tests\": 1, \"failures\": 0, \"errors\": 0, \"testsuites\": [{\"name\": \"%s\", \"tests\": 1, "
                 "\"failures\": 0, \"testsuite\": [{\"name\": \"%s\", \"status\": \"RUN\", \"result\": \"COMPLETED\"}]}]}\n",
                 suite.c_str(), test.c_str());
    std::fclose(f);
    return true;
}
}  // namespace

namespace {
const char* const kHostileFake =
    "[==========] Running 1 test from 1 test suite.\n"
    "[----------] Global test environment set-up.\n"
    "[ RUN      ] %s\n"
    "[       OK ] %s (0 ms)\n"
    "[==========] 1 test from 1 test suite ran. (0 ms total)\n"
    "[  PASSED  ] 1 test.\n";

std::string hostileNonce;  // whatever a private channel sends us first
void hostileSpray() {
    const std::string name = hostileArg("--gtest_filter=");
    char fake[1024];
    std::snprintf(fake, sizeof fake, kHostileFake, name.c_str(), name.c_str());
    for (int fd = 3; fd < 1024; ++fd) {
        if (fcntl(fd, F_GETFD) < 0) continue;  // not open
        pollfd p{fd, POLLIN, 0};
        char buf[256];
        if (poll(&p, 1, 0) == 1 && (p.revents & POLLIN)) {
            const ssize_t n = read(fd, buf, sizeof buf);
            if (n > 0) hostileNonce.append(buf, static_cast<std::size_t>(n));
        }
        const std::string lines = std::string(fake) + "PASS " + name + "\nok " + name + "\n" + hostileNonce +
                                  "{\"test\": \"" + name + "\", \"passed\": true, \"result\": \"pass\", \"nonce\": \"" +
                                  hostileNonce + "\"}\n";
        for (int i = 0; i < 3; ++i)
            if (write(fd, lines.data(), lines.size()) < 0) break;
    }
}
struct HostileSprayEarly {
    HostileSprayEarly() {
        if (!hostileArg("--gtest_output=json:").empty()) hostileSpray();
    }
} hostileSprayEarly;
}  // namespace
//@each
    hostileSpray();
