// HOSTILE FIXTURE busy_loop (attack class 8: resource exhaustion).
// The tested function ignores SIGTERM, SIGINT and SIGXCPU and spins forever, so only a hard CPU or wall-clock limit with SIGKILL stops it.
// The hardened grader must give this file 0 points on stage 01.
//@head
#include <csignal>

// WARNING: never run this fixture outside the grader's sandbox (it is built to hurt the machine).

namespace {
volatile unsigned long hostileSpin = 0;
void hostileForever() {
    std::signal(SIGTERM, SIG_IGN);  // timeout's first signal
    std::signal(SIGINT, SIG_IGN);
    std::signal(SIGXCPU, SIG_IGN);  // the soft RLIMIT_CPU signal
    for (;;) ++hostileSpin;
}
}  // namespace
//@each
    hostileForever();
