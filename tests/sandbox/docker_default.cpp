// docker_default [--no-landlock] COMMAND [ARG...]: runs COMMAND (as root) under what Docker's default
// confinement leaves a container (issue 45), so that the grader's container mode can be tested here.
//
//  - Capabilities: the bounding set keeps only Docker's default ones (below); effective and permitted
//    become that set, inheritable and ambient empty. Root stays root, without CAP_SYS_ADMIN.
//  - seccomp, as Docker's default profile: unshare, setns, mount, umount2 and pivot_root fail with
//    EPERM, clone with any CLONE_NEW* flag fails with EPERM, clone3 with ENOSYS (so that the C library
//    falls back to clone, whose flags a filter can read). With --no-landlock the three landlock_*
//    calls fail with EPERM too: Docker versions whose profile predates moby/moby#43199 do not list them.
//    No no_new_privs (Docker does not set it by default), unless this already runs in a container
//    without CAP_SYS_ADMIN, where a seccomp filter needs it.
// Check: `docker_default bwrap --dev-bind / / true` prints "bwrap: Creating new namespace failed".
// A test tool (tests/sandbox/CMakeLists.txt), never part of the grader.
#include <linux/capability.h>
#include <sched.h>
#include <seccomp.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <initializer_list>

namespace {

/// Docker's default capabilities (moby's oci/caps/defaults.go).
constexpr int kDockerCaps[] = {CAP_CHOWN,  CAP_DAC_OVERRIDE, CAP_FSETID,     CAP_FOWNER,           CAP_MKNOD,
                               CAP_NET_RAW, CAP_SETGID,       CAP_SETUID,     CAP_SETFCAP,          CAP_SETPCAP,
                               CAP_NET_BIND_SERVICE,          CAP_SYS_CHROOT, CAP_KILL,             CAP_AUDIT_WRITE};

int fail(const char* what) {
    std::fprintf(stderr, "error: docker_default: %s: %s\n", what, std::strerror(errno));
    return 125;
}

}  // namespace

int main(int argc, char** argv) {
    int first = 1;
    const bool landlock = !(argc > 1 && std::strcmp(argv[1], "--no-landlock") == 0);
    if (!landlock) ++first;
    if (first >= argc) {
        std::fprintf(stderr, "usage: docker_default [--no-landlock] COMMAND [ARG...]\n");
        return 2;
    }
    if (::geteuid() != 0) {
        std::fprintf(stderr, "error: docker_default: run it as root (a container's root is what it simulates)\n");
        return 125;
    }
    scmp_filter_ctx ctx = seccomp_init(SCMP_ACT_ALLOW);
    bool ok = ctx && seccomp_attr_set(ctx, SCMP_FLTATR_CTL_NNP, 0) == 0;
    for (int sys : {SCMP_SYS(unshare), SCMP_SYS(setns), SCMP_SYS(mount), SCMP_SYS(umount2), SCMP_SYS(pivot_root)})
        ok = ok && seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EPERM), sys, 0) == 0;
    for (scmp_datum_t flag : {CLONE_NEWNS, CLONE_NEWCGROUP, CLONE_NEWUTS, CLONE_NEWIPC, CLONE_NEWUSER, CLONE_NEWPID, CLONE_NEWNET})
        ok = ok && seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EPERM), SCMP_SYS(clone), 1, SCMP_A0(SCMP_CMP_MASKED_EQ, flag, flag)) == 0;
    ok = ok && seccomp_rule_add(ctx, SCMP_ACT_ERRNO(ENOSYS), SCMP_SYS(clone3), 0) == 0;
    if (!landlock)
        for (int sys : {SCMP_SYS(landlock_create_ruleset), SCMP_SYS(landlock_add_rule), SCMP_SYS(landlock_restrict_self)})
            ok = ok && seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EPERM), sys, 0) == 0;
    if (!ok) return fail("cannot build the seccomp filter");

    // Drop from the bounding set what Docker does not grant (needs CAP_SETPCAP), then load the filter
    // (without no_new_privs that needs CAP_SYS_ADMIN, still held), then shrink the process's own sets.
    __u32 keep[2] = {0, 0};
    for (int cap : kDockerCaps) keep[cap / 32] |= 1u << (cap % 32);
    for (int cap = 0; cap <= CAP_LAST_CAP; ++cap)
        if (!(keep[cap / 32] & (1u << (cap % 32))) && ::prctl(PR_CAPBSET_DROP, cap, 0, 0, 0) != 0) return fail("PR_CAPBSET_DROP");
    if (seccomp_load(ctx) != 0) {  // already in a container without CAP_SYS_ADMIN: with no_new_privs, then
        if (seccomp_attr_set(ctx, SCMP_FLTATR_CTL_NNP, 1) != 0 || seccomp_load(ctx) != 0) return fail("cannot load the seccomp filter");
    }
    seccomp_release(ctx);
    __user_cap_header_struct header{_LINUX_CAPABILITY_VERSION_3, 0};
    __user_cap_data_struct data[2] = {{keep[0], keep[0], 0}, {keep[1], keep[1], 0}};
    if (::syscall(SYS_capset, &header, data) != 0) return fail("capset");
    if (::prctl(PR_CAP_AMBIENT, PR_CAP_AMBIENT_CLEAR_ALL, 0, 0, 0) != 0) return fail("PR_CAP_AMBIENT_CLEAR_ALL");
    ::execvp(argv[first], argv + first);
    return fail(argv[first]);
}
