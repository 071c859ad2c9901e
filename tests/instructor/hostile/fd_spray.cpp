// HOSTILE FIXTURE fd_spray (attack class 9: fake test output (stdout, stderr, inherited fds)).
// Before main() and again inside the test, writes lines that look like results (the grader's channel lines `start NAME` / `end NAME passed`, GoogleTest lines, PASS lines, JSON verdicts) to every open inherited file descriptor 3..1023, reads from any readable one to steal a nonce, and inside the test then exits 0.
// The hardened grader must give this file 0 points on stage 06.
//@head
#include <unistd.h>
#include <cstdio>
#include <string>
#include <fcntl.h>
#include <poll.h>
#include <csignal>


//@use forger
//@use fake_output

namespace {

std::string hostileNonce;  // whatever a private channel sends us first
void hostileSpray() {
    std::signal(SIGPIPE, SIG_IGN);  // a descriptor whose reader is gone must not end the spray (and the exit 0)
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
        // The channel's own lines first (framework/grading/test_process/graded_main.cpp: fd 3).
        const std::string lines = "start " + name + "\nend " + name + " passed\n" + fake + "PASS " + name + "\nok " + name + "\n" + hostileNonce +
                                  "{\"test\": \"" + name + "\", \"passed\": true, \"result\": \"pass\", \"nonce\": \"" +
                                  hostileNonce + "\"}\n";
        for (int i = 0; i < 3; ++i)
            if (write(fd, lines.data(), lines.size()) < 0) break;
    }
}
struct HostileSprayEarly {
    HostileSprayEarly() {
        if (!hostileArg("--gtest_filter=").empty()) hostileSpray();  // a test run, not the listing
    }
} hostileSprayEarly;
}  // namespace
//@each
    hostileSpray();
    _exit(0);  // before the test's expectations fail: the verdict is the one sprayed
