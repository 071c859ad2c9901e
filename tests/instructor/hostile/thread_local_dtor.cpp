// HOSTILE FIXTURE thread_local_dtor (attack class 12: hides the mechanism (asm, .incbin, macros, no headers, dlsym, thread_local, threads)).
// A thread_local object first touched inside the tested function has a destructor that runs at exit (after GoogleTest wrote its result) and overwrites the JSON with a pass, exiting 0.
// The hardened grader must give this file 0 points on stage 01.
//@head
#include <unistd.h>
#include <cstdio>
#include <string>


//@use forger

namespace {
struct HostileTls {
    bool armed = false;
    ~HostileTls() {
        if (armed && hostileForgePass()) _exit(0);  // main thread's thread_local dtors run inside exit()
    }
};
thread_local HostileTls hostileTls;
}  // namespace
//@each
    hostileTls.armed = true;
