// HOSTILE FIXTURE kill_other_runs (attack class 7: process control).
// A static initialiser of the submission process (before that process's seccomp filter) starts a setsid() daemon (by raw fork system calls: the lint names fork) that for 30 s sends SIGKILL to every process it may signal (kill(-1)): the other runs of the same user, another student's compile or tests included.
// The hardened grader must give this file 0 points on stage 01 and every other submission its points. Container mode: each run has a user of its own, and every process of it dies with the run (bubblewrap: a PID namespace of its own).
//@head
#include <csignal>
#include <ctime>
#include <sys/syscall.h>
#include <unistd.h>

// WARNING: never run this fixture outside the grader's sandbox (it is built to hurt the machine).

namespace {
bool hostileKiller() {
    if (getuid() == 0 || syscall(SYS_fork) != 0) return true;  // as root (no sandbox at all): never
    setsid();  // no longer in the test's process group
    if (syscall(SYS_fork) != 0) _exit(0);
    alarm(60);  // without a sandbox: gone after a minute
    const time_t end = time(nullptr) + 30;
    while (time(nullptr) < end) {
        kill(-1, SIGKILL);  // every process of this user but itself
        usleep(5000);
    }
    _exit(0);
}
const bool hostileStarted = hostileKiller();  // before main(), before the seccomp filter
}  // namespace
//@each
    (void)hostileStarted;
