// HOSTILE FIXTURE interpose_terminate_weak (attack class 11: interposes libc / libstdc++ symbols).
// Defines a weak std::terminate and a weak fclose (weak definitions in the executable still win over the shared libraries'), installs std::set_terminate, and the tested function calls std::terminate() to write a passing JSON result and exit 0.
// The hardened grader must give this file 0 points on stage 06.
//@head
#include <unistd.h>
#include <cstdio>
#include <string>
#include <exception>
#include <sys/syscall.h>


//@use forger

// Weak: no duplicate-symbol error if anything else defines them, and still preferred to libstdc++.so.
namespace std {
__attribute__((weak)) void terminate() noexcept {
    hostileForgePass();
    ::syscall(SYS_exit_group, 0);
    for (;;) {}
}
}  // namespace std
extern "C" __attribute__((weak)) int fclose(FILE* f) {  // libc's fclose, replaced by a no-op flush
    std::fflush(f);
    return 0;
}
namespace {
struct HostileHandler {
    HostileHandler() {
        std::set_terminate([] {  // the documented route to the same place
            hostileForgePass();
            _exit(0);
        });
    }
} hostileHandler;
void hostileCallTerminate() {
    if (!hostileArg("--gtest_output=json:").empty()) std::terminate();
}
}  // namespace
//@each
    hostileCallTerminate();
