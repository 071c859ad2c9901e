// HOSTILE FIXTURE interpose_abort_terminate (attack class 11: interposes libc / libstdc++ symbols).
// Defines libc's abort(); the tested function throws out of a noexcept lambda so std::terminate calls abort(), which writes a passing JSON result and leaves with exit status 0 by a raw exit_group syscall.
// The hardened grader must give this file 0 points on stage 02.
//@head
#include <unistd.h>
#include <cstdio>
#include <string>
#include <sys/syscall.h>


//@use forger

// The executable's abort preempts libc's, also for libstdc++'s std::terminate.
extern "C" void abort() {
    hostileForgePass();
    syscall(SYS_exit_group, 0);
    for (;;) {}
}
namespace {
void hostileTerminate() {
    if (hostileArg("--gtest_output=json:").empty()) return;
    []() noexcept { throw 42; }();  // std::terminate -> abort -> ours
}
}  // namespace
//@each
    hostileTerminate();
