// HOSTILE FIXTURE sleep_forever (attack class 8: resource exhaustion).
// The tested function ignores SIGTERM and sleeps in a loop: it uses no CPU time, so a CPU-time limit alone never stops it, only a wall-clock limit.
// The hardened grader must give this file 0 points on stage 03.
//@head
#include <csignal>
#include <unistd.h>

// WARNING: never run this fixture outside the grader's sandbox (it is built to hurt the machine).

namespace {
void hostileSleep() {
    std::signal(SIGTERM, SIG_IGN);
    std::signal(SIGINT, SIG_IGN);
    for (;;) sleep(3600);  // no CPU time at all
}
}  // namespace
//@each
    hostileSleep();
