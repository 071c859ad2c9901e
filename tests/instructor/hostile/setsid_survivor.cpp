// HOSTILE FIXTURE setsid_survivor (attack class 7: process control).
// The tested function double-forks a setsid() daemon that outlives the test process and, for up to 10 minutes, keeps writing passing JSON to the grader's --gtest_output path (shared by later tests) and a log in /tmp.
// The hardened grader must give this file 0 points on stage 02.
//@head
#include <unistd.h>
#include <cstdio>
#include <string>
#include <csignal>
#include <ctime>

// WARNING: never run this fixture outside the grader's sandbox (it is built to hurt the machine).

//@use forger

namespace {
void hostileSurvive() {
    static bool started = false;
    if (started || hostileArg("--gtest_output=json:").empty()) return;
    started = true;
    if (fork() != 0) return;  // the test goes on and fails as usual
    setsid();                 // new session: no longer in the grader's process group
    if (fork() != 0) _exit(0);
    std::signal(SIGHUP, SIG_IGN);
    std::signal(SIGTERM, SIG_IGN);
    alarm(600);  // without a sandbox: gone after 10 minutes
    for (;;) {
        hostileForgePass();  // the grader reuses one output path for every test: race it
        if (std::FILE* f = std::fopen("/tmp/clothlab-hostile-survivor.log", "a")) {
            std::fprintf(f, "still alive at %ld\n", static_cast<long>(std::time(nullptr)));
            std::fclose(f);
        }
        usleep(10000);
    }
}
}  // namespace
//@each
    hostileSurvive();
