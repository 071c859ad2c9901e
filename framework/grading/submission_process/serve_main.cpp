// The submission process: the main() linked with the submission's objects (see wire/peer.h).
//
// Started by a graded test process with the calls arriving on fd 3 and the replies leaving on
// fd 4. Before it serves the first call it confines itself with a seccomp filter (libseccomp):
// reading and writing the descriptors it has, memory, time and ending itself are allowed; every
// other system call (opening files, starting processes or threads, signalling others, tracing)
// fails with EPERM. It cannot reach the test process's memory or its report channel. Its parallel
// loops run on one thread (the sweeps give the same positions bit for bit either way).
#include <seccomp.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cstdio>

#include "clothlab/sim/team.h"
#include "functions.h"  // generated: CLOTHLAB_REMOTE_FUNCTIONS
#include "wire/peer.h"

namespace {

/// Allows only the system calls a computation needs; false if the filter could not be loaded.
bool confine() {
#ifdef CLOTHLAB_TEST_NO_SECCOMP  // the red team's test-only build of this file (tests/sandbox/CMakeLists.txt) loads none
    return true;
#endif
    scmp_filter_ctx ctx = seccomp_init(SCMP_ACT_ERRNO(EPERM));
    if (!ctx) return false;
    const int allowed[] = {
        SCMP_SYS(read),         SCMP_SYS(write),        SCMP_SYS(readv),          SCMP_SYS(writev),
        SCMP_SYS(close),        SCMP_SYS(fstat),        SCMP_SYS(newfstatat),     SCMP_SYS(lseek),
        SCMP_SYS(brk),          SCMP_SYS(mmap),         SCMP_SYS(munmap),         SCMP_SYS(mremap),
        SCMP_SYS(mprotect),     SCMP_SYS(madvise),      SCMP_SYS(futex),          SCMP_SYS(exit),
        SCMP_SYS(exit_group),   SCMP_SYS(rt_sigreturn), SCMP_SYS(rt_sigprocmask), SCMP_SYS(rt_sigaction),
        SCMP_SYS(getpid),       SCMP_SYS(gettid),       SCMP_SYS(clock_gettime),  SCMP_SYS(clock_nanosleep),
        SCMP_SYS(nanosleep),    SCMP_SYS(getrandom),    SCMP_SYS(sched_yield),    SCMP_SYS(restart_syscall),
    };
    // Every thread of the process (a static constructor of the submission may have started one).
    bool ok = seccomp_attr_set(ctx, SCMP_FLTATR_CTL_TSYNC, 1) == 0;
    for (int sys : allowed) ok = ok && seccomp_rule_add(ctx, SCMP_ACT_ALLOW, sys, 0) == 0;
    // abort() signals itself, and only itself; isatty() asks the terminal (stdio's buffering).
    ok = ok && seccomp_rule_add(ctx, SCMP_ACT_ALLOW, SCMP_SYS(tgkill), 1, SCMP_A0(SCMP_CMP_EQ, static_cast<scmp_datum_t>(::getpid()))) == 0;
    ok = ok && seccomp_rule_add(ctx, SCMP_ACT_ALLOW, SCMP_SYS(ioctl), 1, SCMP_A1(SCMP_CMP_EQ, TCGETS)) == 0;
    ok = ok && seccomp_load(ctx) == 0;
    seccomp_release(ctx);
    return ok;
}

}  // namespace

int main() {
    using namespace clothlab;
    if (!confine()) {
        std::fprintf(stderr, "clothlab-submission: cannot load the seccomp filter\n");
        return 125;
    }
    const TeamCap serial(1);  // the filter allows no new thread
    wire::Peer peer(3, 4);
#define CLOTHLAB_SERVE(id, name) \
    peer.addFunction(id, [](const wire::json& in) { return wire::Invoke<decltype(name)>::serve(name, in); });
    CLOTHLAB_REMOTE_FUNCTIONS(CLOTHLAB_SERVE)
#undef CLOTHLAB_SERVE
    try {
        peer.serveUntilClosed();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "clothlab-submission: %s\n", e.what());
        return 125;
    }
    return 0;
}
