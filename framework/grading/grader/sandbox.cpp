#include "sandbox.h"

#include <fcntl.h>
#include <linux/filter.h>
#include <linux/landlock.h>
#include <linux/seccomp.h>
#include <poll.h>
#include <sched.h>
#include <seccomp.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <fstream>
#include <mutex>
#include <set>
#include <thread>

#include "common.h"

namespace grade {

namespace {

// Landlock access rights newer than Debian 12's kernel headers (the kernel says which it has):
// LANDLOCK_ACCESS_FS_REFER, _TRUNCATE and _IOCTL_DEV.
constexpr uint64_t kLandlockRefer = 1ULL << 13, kLandlockTruncate = 1ULL << 14, kLandlockIoctlDev = 1ULL << 15;

Confinement g_confinement = Confinement::bubblewrap;
/// The user bubblewrap runs the programs as when the grader is root: nobody (test tool only, `pid`
/// off: a user of the test's own, so that what an attack kills without the PID namespace is this
/// test's runs, never another program's of user nobody).
uid_t bubblewrapUser() { return weakened("pid") ? 64198 : 65534; }

/// Processes the user `uid` has now (RLIMIT_NPROC counts them all, so the limit is this + allowance).
int processesOf(uid_t uid) {
    int n = 0;
    forEachEntry("/proc", false, [&](const fs::path& p, const struct stat& st) {
        n += p.filename().string().find_first_not_of("0123456789") == std::string::npos && st.st_uid == uid;
    });
    return n;
}

/// Outside bubblewrap's mounts the program sees the host's paths: a path inside a mount (at the start
/// of an argument, after the '=' of --NAME=, or after -I) becomes the mount's host path.
std::string outside(const std::string& arg, const std::vector<Mount>& mounts) {
    const size_t at = arg.rfind("--", 0) == 0 && arg.find('=') != std::string::npos ? arg.find('=') + 1 : arg.rfind("-I", 0) == 0 ? 2 : 0;
    for (const auto& m : mounts) {
        const std::string in = m.inside.string();
        if (arg.compare(at, in.size(), in) == 0 && (arg.size() == at + in.size() || arg[at + in.size()] == '/'))
            return arg.substr(0, at) + m.host.string() + arg.substr(at + in.size());
    }
    return arg;
}

/// The bwrap command line. Run by an ordinary user, bwrap makes a user namespace and drops every
/// capability. Run by root, bwrap keeps root (so it can reach paths only root may traverse) but the
/// program itself starts through setpriv as user nobody, with no capabilities and no way to gain any:
/// then the process limit counts nobody's processes (root is exempt from it).
std::vector<std::string> bwrapArgs(const SandboxRun& run) {
    const bool root = ::geteuid() == 0, host = weakened("view");  // test tool only: the host's files, as far as nobody may go
    const auto path = [&](const std::string& p) { return host ? outside(p, run.mounts) : p; };
    std::vector<std::string> a = {"bwrap", "--die-with-parent", "--new-session", "--hostname", "grader", "--clearenv",
                                  "--setenv", "PATH", "/usr/bin", "--setenv", "HOME", "/tmp", "--ro-bind", "/usr", "/usr"};
    for (const auto& [name, value] : run.env) a.insert(a.end(), {"--setenv", name, path(value)});
    if (root) a.insert(a.begin() + 1, {"--unshare-ipc", "--unshare-uts", "--unshare-cgroup-try"});
    else a.insert(a.begin() + 1, {"--unshare-all", "--cap-drop", "ALL"});
    if (root && !weakened("pid")) a.insert(a.begin() + 1, "--unshare-pid");  // test tool only: the machine's processes
    if (!weakened("network")) a.insert(a.begin() + 1, "--unshare-net");  // test tool only: the machine's network
    else if (!root) a.push_back("--share-net");  // after --unshare-all
    if (host) a.insert(a.end(), {"--ro-bind", "/", "/", "--dev", "/dev", "--bind", "/tmp", "/tmp", "--bind", "/var/tmp", "/var/tmp"});
    for (const std::string l : {"/lib", "/lib64", "/bin", "/sbin"})
        if (host) break;
        else if (fs::is_symlink(l)) a.insert(a.end(), {"--symlink", fs::read_symlink(l).string(), l});
        else if (fs::exists(l)) a.insert(a.end(), {"--ro-bind", l, l});
    if (!host && fs::exists("/etc/ld.so.cache")) a.insert(a.end(), {"--ro-bind", "/etc/ld.so.cache", "/etc/ld.so.cache"});
    if (!host) a.insert(a.end(), {"--dev", "/dev", "--perms", "1777", "--size", std::to_string(run.limits.file_size * 2), "--tmpfs", "/tmp"});
    if (!host && weakened("proc")) a.insert(a.end(), {"--proc", "/proc"});  // test tool only: the process's /proc
    std::set<std::string> parents;  // the folders the mounts sit in, world-readable (bwrap would make them for root alone)
    for (const auto& m : run.mounts)
        for (fs::path p = m.inside.parent_path(); !host && p != p.root_path() && !p.empty(); p = p.parent_path()) parents.insert(p.string());
    for (const auto& p : parents)  // sorted: a parent before its children
        if (p != "/usr" && p.rfind("/usr/", 0) != 0 && p != "/tmp") a.insert(a.end(), {"--perms", "0755", "--dir", p});
    for (const auto& m : run.mounts)
        if (!host || m.writable) a.insert(a.end(), {m.writable ? "--bind" : "--ro-bind", m.host.string(), path(m.inside.string())});
    a.insert(a.end(), {"--chdir", path(run.workdir.string()), "--"});
    if (root && !weakened("nobody"))  // test tool only: the program runs as root (bubblewrap's own user)
        a.insert(a.end(), {"/usr/bin/setpriv", "--reuid=" + std::to_string(bubblewrapUser()), "--regid=" + std::to_string(bubblewrapUser()),
                           "--clear-groups", "--no-new-privs", "--inh-caps=-all", "--bounding-set=-all", "--"});
    for (const auto& arg : run.argv) a.push_back(path(arg));
    return a;
}

// ---- container mode ----------------------------------------------------------------------------

/// Root's own folder of the container mode: a lock file per user (which run holds it) and the runs'
/// scratch folders. Mode 0711: a run reaches its scratch folder, lists nothing, creates nothing here.
const fs::path kSandboxDir = "/tmp/clothlab-sandbox";
/// The users of the runs: kUsers ids from kFirstUid, in Debian's range of globally allocated system
/// ids (60000-64999, below nobody), inside the 65536 ids a user-namespaced Docker maps.
constexpr uid_t kFirstUid = 64200;
constexpr int kUsers = 512;

/// The real and saved user of the child that kills the processes of run user `uid`: an id of its own
/// (never a run's, never root), kUsers above the runs' ids.
uid_t killerOf(uid_t uid) { return uid + kUsers; }

/// Kills every process of `uid`: a child with `uid` as its effective user and killerOf(uid) as its real
/// and saved one sends SIGKILL to every process it may signal (kill(-1)). A signal needs the sender's
/// real or effective user to be the target's real or saved one, and a process whose three users are
/// not root has no capability: so exactly `uid`'s processes die, and none of them may signal the
/// killer back. Never root as a real user here: kill(-1) would reach every root process.
void killAllOf(uid_t uid) {
    const uid_t killer = killerOf(uid);
    if (uid == 0 || killer == 0) die("container mode: refusing to kill the processes of root");
    const pid_t pid = ::fork();
    if (pid == 0) {
        if (::syscall(SYS_setresuid, killer, uid, killer) != 0 || ::getuid() != killer || ::geteuid() != uid || ::getuid() == 0) ::_exit(1);
        const struct timespec ms {0, 1000000};
        for (int round = 0; round < 3 && ::kill(-1, SIGKILL) == 0; ++round) ::nanosleep(&ms, nullptr);  // ESRCH: nobody left
        ::_exit(0);
    }
    if (pid > 0) ::waitpid(pid, nullptr, 0);
}

/// Removes what `uid` owns at the top of the world-writable folders and of kSandboxDir.
void removeLeftovers(uid_t uid) {
    for (const char* dir : {"/tmp", "/var/tmp", "/dev/shm", "/tmp/clothlab-sandbox"})
        forEachEntry(dir, false, [&](const fs::path& p, const struct stat& st) {
            std::error_code ec;
            if (st.st_uid == uid) fs::remove_all(p, ec);
        });
}

/// Hands a folder a run wrote (and everything in it) to root, without group or world write permission
/// and set-id bits: no later run (another user) can change what this one wrote.
void handToRoot(const fs::path& dir) {
    const auto seal = [](const fs::path& p, const struct stat& st) {
        if (::lchown(p.c_str(), 0, 0) != 0) die(p.string() + ": (file): cannot hand it back to root");
        if (!S_ISLNK(st.st_mode)) ::chmod(p.c_str(), st.st_mode & 0755);
    };
    forEachEntry(dir, true, seal);
    struct stat st {};
    if (::lstat(dir.c_str(), &st) == 0) seal(dir, st);
}

/// The ids a run may use: not a user or group this machine names (/etc/passwd, /etc/group).
bool idIsFree(uid_t id) {
    static const std::set<unsigned> named = [] {
        std::set<unsigned> s;
        for (const char* file : {"/etc/passwd", "/etc/group"}) {
            std::ifstream in(file);
            for (std::string line; std::getline(in, line);)
                if (const size_t a = line.find(':'), b = a == std::string::npos ? a : line.find(':', a + 1); b != std::string::npos)
                    s.insert(static_cast<unsigned>(std::strtoul(line.c_str() + b + 1, nullptr, 10)));
        }
        return s;
    }();
    return !named.count(id);
}

/// The user (and group, the same number) of one run in container mode, held while the run lasts: a
/// lock (flock) on kSandboxDir/ID.lock keeps every other run, of this grader or another, off it.
struct RunUser {
    uid_t uid = 0;
    int lock = -1;
    fs::path scratch;  ///< its own folder: HOME, TMPDIR and working folder
};

RunUser leaseUser() {
    static std::once_flag once;
    std::call_once(once, [] {
        ::mkdir(kSandboxDir.c_str(), 0711);
        struct stat st {};  // not ours (made by someone else, or a link): never use it
        if (::lstat(kSandboxDir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode) || st.st_uid != 0 || (st.st_mode & 07777) != 0711)
            die(kSandboxDir.string() + ": (folder): must be root's own folder with mode 0711 (container mode); remove it and grade again");
    });
    static std::atomic<unsigned> runs{0};
    RunUser u;
    const unsigned n = runs++;
    u.scratch = kSandboxDir / ("run-" + std::to_string(::getpid()) + "-" + std::to_string(n));
    if (weakened("uid")) {  // test tool only: every run as one user (bubblewrap's nobody, without a PID namespace)
        u.uid = kFirstUid - 1;
    } else {
        for (int attempt = 0; u.lock < 0; ++attempt) {
            for (int i = 0; i < kUsers && u.lock < 0; ++i) {
                const uid_t id = kFirstUid + static_cast<uid_t>((static_cast<unsigned>(::getpid()) + n + i) % kUsers);
                if (!idIsFree(id) || !idIsFree(killerOf(id))) continue;
                const int fd = ::open((kSandboxDir / (std::to_string(id) + ".lock")).c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0600);
                if (fd >= 0 && ::flock(fd, LOCK_EX | LOCK_NB) == 0) u.uid = id, u.lock = fd;
                else if (fd >= 0) ::close(fd);
            }
            if (u.lock < 0 && attempt > 6000) die("container mode: no free user for a run (" + std::to_string(kUsers) + " runs at once?)");
            if (u.lock < 0) std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        killAllOf(u.uid);  // what a grader that died left running
        removeLeftovers(u.uid);
    }
    if (::mkdir(u.scratch.c_str(), 0700) != 0 || ::lchown(u.scratch.c_str(), u.uid, u.uid) != 0)
        die(u.scratch.string() + ": (folder): cannot make the run's scratch folder");
    return u;
}

/// Ends a run's hold on its user. No PID namespace dies with the run: every process of the user is
/// killed first; then what it wrote in `mounts` becomes root's, before anything reads it; what it left
/// elsewhere is removed.
void releaseUser(RunUser& u, const std::vector<Mount>& mounts) {
    if (u.lock >= 0) killAllOf(u.uid);
    for (const auto& m : mounts)
        if (m.writable) handToRoot(m.host);
    if (u.lock >= 0) removeLeftovers(u.uid), ::close(u.lock);  // unlocks
    std::error_code ec;
    fs::remove_all(u.scratch, ec);
}

int landlockAbi() {
    static const int abi = std::max(0L, ::syscall(SYS_landlock_create_ruleset, nullptr, 0, LANDLOCK_CREATE_RULESET_VERSION));
    return abi;
}

/// The run's Landlock rules (-1: no Landlock here): read and execute the system's programs and
/// libraries and the read-only mounts, read and write the writable mounts and the scratch folder.
int landlockRules(const SandboxRun& run, const fs::path& scratch) {
    if (landlockAbi() == 0 || weakened("landlock")) return -1;
    const int abi = landlockAbi();
    const uint64_t handled = ((LANDLOCK_ACCESS_FS_MAKE_SYM << 1) - 1) | (abi >= 2 ? kLandlockRefer : 0) |
                             (abi >= 3 ? kLandlockTruncate : 0) | (abi >= 5 ? kLandlockIoctlDev : 0);
    constexpr uint64_t read = LANDLOCK_ACCESS_FS_READ_FILE | LANDLOCK_ACCESS_FS_READ_DIR, execute = LANDLOCK_ACCESS_FS_EXECUTE;
    constexpr uint64_t write = LANDLOCK_ACCESS_FS_WRITE_FILE | kLandlockTruncate | kLandlockIoctlDev |
                               LANDLOCK_ACCESS_FS_REMOVE_DIR | LANDLOCK_ACCESS_FS_REMOVE_FILE | LANDLOCK_ACCESS_FS_MAKE_DIR |
                               LANDLOCK_ACCESS_FS_MAKE_REG | LANDLOCK_ACCESS_FS_MAKE_SYM | LANDLOCK_ACCESS_FS_MAKE_FIFO |
                               LANDLOCK_ACCESS_FS_MAKE_SOCK | kLandlockRefer;
    constexpr uint64_t fileRights = LANDLOCK_ACCESS_FS_EXECUTE | LANDLOCK_ACCESS_FS_READ_FILE | LANDLOCK_ACCESS_FS_WRITE_FILE |
                                    kLandlockTruncate | kLandlockIoctlDev;  // the others are about folders
    struct landlock_ruleset_attr attr {};
    attr.handled_access_fs = handled;
    const int ruleset = static_cast<int>(::syscall(SYS_landlock_create_ruleset, &attr, sizeof attr, 0));
    if (ruleset < 0) die(std::string("container mode: cannot make a Landlock ruleset: ") + std::strerror(errno));
    const auto allow = [&](const fs::path& path, uint64_t rights) {  // a path that does not exist is left out
        const int fd = ::open(path.c_str(), O_PATH | O_CLOEXEC);
        struct stat st {};
        if (fd < 0) return;
        if (::fstat(fd, &st) == 0) {
            struct landlock_path_beneath_attr rule {};
            rule.allowed_access = rights & handled & (S_ISDIR(st.st_mode) ? ~0ULL : fileRights);
            rule.parent_fd = fd;
            if (::syscall(SYS_landlock_add_rule, ruleset, LANDLOCK_RULE_PATH_BENEATH, &rule, 0) != 0)
                die(path.string() + ": (Landlock): cannot add the rule: " + std::strerror(errno));
        }
        ::close(fd);
    };
    for (const char* sys : {"/usr", "/lib", "/lib32", "/lib64", "/libx32", "/bin", "/sbin", "/etc/ld.so.cache"}) allow(sys, read | execute);
    allow("/dev/null", read | write);
    for (const char* dev : {"/dev/zero", "/dev/random", "/dev/urandom"}) allow(dev, read);
    for (const auto& m : run.mounts) allow(m.host, m.writable ? read | write : read | execute);
    allow(scratch, read | write);
    return ruleset;
}

/// The container mode's seccomp filter, as a BPF program made once (a child after fork() may not
/// allocate: the grader has threads). Every system call is allowed except: sockets (no network; a
/// socketpair stays allowed), tracing and reading other processes' memory, namespaces and mounts,
/// io_uring (its requests would pass the filter unseen), eBPF, perf events, userfaultfd, keyrings,
/// System V IPC and POSIX message queues (no IPC namespace). clone3 fails with ENOSYS (so that the C
/// library falls back to clone, whose flags the filter reads), clone with a CLONE_NEW* flag with EPERM.
const struct sock_fprog* containerFilter() {
    static std::vector<struct sock_filter> code;
    static struct sock_fprog prog {};
    static std::once_flag once;
    std::call_once(once, [] {
        scmp_filter_ctx ctx = seccomp_init(SCMP_ACT_ALLOW);
        bool ok = ctx && seccomp_attr_set(ctx, SCMP_FLTATR_CTL_NNP, 0) == 0;  // the child sets no_new_privs itself
        for (int sys : {SCMP_SYS(socket), SCMP_SYS(ptrace), SCMP_SYS(process_vm_readv), SCMP_SYS(process_vm_writev),
                        SCMP_SYS(pidfd_getfd), SCMP_SYS(kcmp), SCMP_SYS(unshare), SCMP_SYS(setns), SCMP_SYS(mount),
                        SCMP_SYS(umount2), SCMP_SYS(pivot_root), SCMP_SYS(chroot), SCMP_SYS(open_tree), SCMP_SYS(move_mount),
                        SCMP_SYS(fsopen), SCMP_SYS(fsconfig), SCMP_SYS(fsmount), SCMP_SYS(fspick), SCMP_SYS(mount_setattr),
                        SCMP_SYS(io_uring_setup), SCMP_SYS(io_uring_enter), SCMP_SYS(io_uring_register), SCMP_SYS(bpf),
                        SCMP_SYS(perf_event_open), SCMP_SYS(userfaultfd), SCMP_SYS(keyctl), SCMP_SYS(add_key),
                        SCMP_SYS(request_key), SCMP_SYS(shmget), SCMP_SYS(shmat), SCMP_SYS(semget), SCMP_SYS(msgget), SCMP_SYS(mq_open)})
            ok = ok && seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EPERM), sys, 0) == 0;
        for (scmp_datum_t flag : {CLONE_NEWNS, CLONE_NEWCGROUP, CLONE_NEWUTS, CLONE_NEWIPC, CLONE_NEWUSER, CLONE_NEWPID, CLONE_NEWNET})
            ok = ok && seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EPERM), SCMP_SYS(clone), 1, SCMP_A0(SCMP_CMP_MASKED_EQ, flag, flag)) == 0;
        ok = ok && seccomp_rule_add(ctx, SCMP_ACT_ERRNO(ENOSYS), SCMP_SYS(clone3), 0) == 0;
        int pipe_fds[2];  // the program as bytes: through a pipe (libseccomp 2.5 exports to a descriptor only)
        if ((ok = ok && ::pipe2(pipe_fds, O_CLOEXEC) == 0)) {
            ok = seccomp_export_bpf(ctx, pipe_fds[1]) == 0;
            ::close(pipe_fds[1]);
            std::string bytes;
            char buf[4096];
            for (ssize_t n; (n = ::read(pipe_fds[0], buf, sizeof buf)) > 0;) bytes.append(buf, static_cast<size_t>(n));
            ::close(pipe_fds[0]);
            code.resize(bytes.size() / sizeof(struct sock_filter));
            std::memcpy(code.data(), bytes.data(), code.size() * sizeof(struct sock_filter));
            ok = ok && !code.empty() && bytes.size() % sizeof(struct sock_filter) == 0;
        }
        if (ctx) seccomp_release(ctx);
        if (!ok) die("container mode: cannot build the seccomp filter (libseccomp)");
        prog.len = static_cast<unsigned short>(code.size());
        prog.filter = code.data();
    });
    return &prog;
}

/// Runs a probe under confinement `c` with a log of its own: its outcome and log.
std::pair<RunOutcome, std::string> runProbe(SandboxRun probe, Confinement c, const std::string& name) {
    probe.log = fs::temp_directory_path() / ("clothlab-" + name + "-" + std::to_string(::getpid()) + ".log");
    const Confinement was = g_confinement;
    g_confinement = c;
    const RunOutcome r = runSandboxed(probe);
    g_confinement = was;
    std::string log = readFile(probe.log, 1u << 20);
    fs::remove(probe.log);
    return {r, log};
}

/// Empty when container mode holds here (chooseConfinement), else why not, as one line.
std::string containerProblem(const Protected& p) {
    if (::geteuid() != 0) return "container mode needs the grader to run as root (it runs each program as a user of its own)";
    const std::string mode = landlockAbi() > 0 ? "container mode" : "container mode without Landlock";
    if (weakened("")) {  // test tool only (any CLOTHLAB_WEAKEN): a defence is off on purpose, no probe
        std::fprintf(stderr, "warning: clothlab-grade-weakened: CLOTHLAB_WEAKEN=%s: %s is not probed\n", std::getenv("CLOTHLAB_WEAKEN"), mode.c_str());
        return "";
    }
    for (const auto& path : p.needed)  // Landlock adds no permission: a run's user must pass every folder above
        for (fs::path q = fs::absolute(path); !q.empty(); q = q.parent_path()) {
            struct stat st {};
            if (::stat(q.c_str(), &st) == 0 && S_ISDIR(st.st_mode) && !(st.st_mode & S_IXOTH))
                return mode + ": the programs cannot reach " + path.string() + ": " + q.string() + " lets no other user pass (chmod o+x it)";
            if (q == q.root_path()) break;
        }
    if (p.students_apart && landlockAbi() == 0)
        return mode + ": a class cannot be graded, one student's code could read another's files (grade one submission at a time)";
    SandboxRun probe;
    const fs::path self = fs::canonical("/proc/self/exe");
    probe.argv = {self.string(), "--container-probe"};
    for (const auto& f : p.unreadable) probe.argv.insert(probe.argv.end(), {"r", f.string()});
    for (const auto& f : p.unwritable) probe.argv.insert(probe.argv.end(), {"w", f.string()});
    probe.mounts = {{self, self, false}};
    probe.timeout_seconds = 30;
    const auto [r, log] = runProbe(probe, Confinement::container, "container-probe");
    if (r.exit_code == 0 && log.find("probe: every guarantee holds") != std::string::npos) return "";
    const size_t hole = log.find("hole: ");
    if (hole == std::string::npos) return mode + ": the probe did not run (exit " + std::to_string(r.exit_code) + "): " + firstLines(log, 1, "");
    return mode + ": " + log.substr(hole + 6, log.find('\n', hole) - hole - 6) +
           (landlockAbi() > 0 ? "" : " (make it unreachable for other users, e.g. chmod o-rwx, or grade where Landlock or bubblewrap works)");
}

/// Writes a line to stderr from a child after fork() (async-signal-safe), then ends it with 126.
[[noreturn]] void childFails(const char* step) {
    const char* what = "clothlab-grade: cannot confine the program: ";
    (void)!::write(2, what, std::strlen(what));
    (void)!::write(2, step, std::strlen(step));
    (void)!::write(2, "\n", 1);
    ::_exit(126);
}

}  // namespace

void setConfinement(Confinement c) { g_confinement = c; }
Confinement confinement() { return g_confinement; }

std::string confinementName() {
    if (g_confinement == Confinement::bubblewrap) return "bubblewrap";
    if (g_confinement == Confinement::none) return "none (the programs run unconfined, with limits only)";
    return landlockAbi() > 0 ? "container mode (a user of its own per program, Landlock, seccomp; lacks PID and network namespaces and "
                               "a size limit on the scratch folder)"
                             : "container mode without Landlock (a user of its own per program, seccomp, reads confined by file "
                               "permissions only; lacks Landlock, PID and network namespaces and a size limit on the scratch folder)";
}

std::string bubblewrapProblem() {
    static const std::string problem = [] {
        SandboxRun probe;
        probe.argv = {"/usr/bin/true"};
        probe.timeout_seconds = 20;
        const auto [r, log] = runProbe(probe, Confinement::bubblewrap, "sandbox-probe");
        if (r.exit_code == 0) return std::string();
        if (r.exit_code == 127) return std::string("bwrap is not installed (Debian package bubblewrap; ./lab setup installs it)");
        return "bwrap cannot create a sandbox here (exit " + std::to_string(r.exit_code) + "): " + firstLines(log, 1, "");
    }();
    return problem;
}

Protected instructorFiles(const fs::path& tree, const std::vector<fs::path>& reference, const std::vector<fs::path>& unwritable) {
    Protected p;
    for (const char* dir : {"solutions", "tests/instructor"}) {
        std::vector<fs::path> files;
        forEachEntry(tree / dir, true, [&](const fs::path& f, const struct stat& st) {
            if (S_ISREG(st.st_mode) && files.size() < 2000) files.push_back(f);
        });
        std::sort(files.begin(), files.end());
        p.unreadable.insert(p.unreadable.end(), files.begin(), files.end());
    }
    forEachEntry(tree / "tests", false, [&](const fs::path& f, const struct stat&) {
        const std::string s = f.string();
        if (s.size() > 12 && s.compare(s.size() - 12, 12, ".points.json") == 0) p.unreadable.push_back(f), p.unwritable.push_back(f);
    });
    if (fs::is_directory(tree / "solutions")) p.unreadable.insert(p.unreadable.end(), reference.begin(), reference.end());
    p.unwritable.push_back(tree);
    p.unwritable.insert(p.unwritable.end(), unwritable.begin(), unwritable.end());
    return p;
}

std::string chooseConfinement(const std::string& wanted, const Protected& p) {
    g_confinement = Confinement::none;
    std::string bubblewrap;
    if (wanted != "container") {
        bubblewrap = bubblewrapProblem();
        if (bubblewrap.empty()) return g_confinement = Confinement::bubblewrap, "";
        if (wanted == "bubblewrap") return bubblewrap;
    }
    const std::string container = containerProblem(p);
    if (container.empty()) {
        ::umask(022);  // what the grader writes for a run (sources, objects) its user can read
        return g_confinement = Confinement::container, "";
    }
    return bubblewrap.empty() ? container : "bubblewrap: " + bubblewrap + "; " + container;
}

int containerProbeMain(int argc, char** argv) {
    int holes = 0;
    const auto hole = [&](const std::string& what) { std::printf("hole: %s\n", what.c_str()), ++holes; };
    for (int i = 2; i + 1 < argc; i += 2) {
        const std::string kind = argv[i], path = argv[i + 1];
        std::error_code ec;
        if (kind == "r") {
            const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
            if (fd >= 0) hole("the submission could read " + path), ::close(fd);
        } else if (fs::is_directory(path, ec)) {  // (a path it cannot even stat is no hole)
            const std::string file = path + "/.clothlab-probe-" + std::to_string(::getpid());
            const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
            if (fd >= 0) hole("the submission could write into " + path), ::close(fd), ::unlink(file.c_str());
        } else {
            const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);  // no O_TRUNC: nothing changes
            if (fd >= 0) hole("the submission could write " + path), ::close(fd);
        }
    }
    const int s = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (s >= 0) hole("the submission could open an AF_INET socket (the network)"), ::close(s);
    if (::kill(::getppid(), 0) == 0) hole("the submission could signal the grader");
    if (::getuid() == 0) hole("the submission would run as root");
    if (holes == 0) std::printf("probe: every guarantee holds\n");
    return holes == 0 ? 0 : 1;
}

void makeWritableForSandbox(const fs::path& dir) {
    fs::create_directories(dir);
    if (::geteuid() != 0) fs::permissions(dir, fs::perms::owner_all, fs::perm_options::add);
    else if (g_confinement == Confinement::container && ::lchown(dir.c_str(), 0, 0) != 0) die(dir.string() + ": (folder): cannot make it root's");
    else if (g_confinement != Confinement::container && ::chown(dir.c_str(), bubblewrapUser(), bubblewrapUser()) != 0) die(dir.string() + ": (folder): cannot hand it to user nobody");
}

RunOutcome runSandboxed(const SandboxRun& run) {
    RunOutcome out;
    const Confinement mode = g_confinement;
    const bool bubblewrap = mode == Confinement::bubblewrap, container = mode == Confinement::container;
    // Everything the child needs is prepared before fork(): after it, only async-signal-safe calls.
    RunUser user = container ? leaseUser() : RunUser{};
    std::vector<std::string> args = bubblewrap ? bwrapArgs(run) : run.argv, env_text;
    std::string workdir;
    if (!bubblewrap) {
        for (auto& a : args) a = outside(a, run.mounts);
        if (container) env_text = {"PATH=/usr/bin", "HOME=" + user.scratch.string(), "TMPDIR=" + user.scratch.string()};
        else
            for (char** e = ::environ; *e; ++e) env_text.emplace_back(*e);
        workdir = container && run.workdir == "/tmp" ? user.scratch.string() : outside(run.workdir.string(), run.mounts);
        for (const auto& [name, value] : run.env) env_text.push_back(name + "=" + outside(value, run.mounts));
    }
    std::vector<char*> argv, envp;
    for (const auto& s : args) argv.push_back(const_cast<char*>(s.c_str()));
    for (const auto& s : env_text) envp.push_back(const_cast<char*>(s.c_str()));
    argv.push_back(nullptr), envp.push_back(nullptr);
    // The ruleset's descriptor above 9, like the channel's: the child's dup2 onto fd 3 must not replace it.
    int ruleset = container ? landlockRules(run, user.scratch) : -1;
    if (ruleset >= 0 && ruleset < 10) {
        const int moved = ::fcntl(ruleset, F_DUPFD_CLOEXEC, 10);
        ::close(ruleset);
        if (moved < 0) die(std::string("container mode: cannot keep the Landlock ruleset: ") + std::strerror(errno));
        ruleset = moved;
    }
    const struct sock_fprog* filter = container && !weakened("container-seccomp") ? containerFilter() : nullptr;
    if (container)
        for (const auto& m : run.mounts)
            if (m.writable && ::lchown(m.host.c_str(), user.uid, user.uid) != 0) die(m.host.string() + ": (folder): cannot hand it to the run's user");
    const uid_t runner = container ? user.uid : ::geteuid() == 0 && bubblewrap ? bubblewrapUser() : ::geteuid();
    // The limits (test tool only: without the one a red-team attack aims at, tests/instructor/hostile/README.md).
    const rlim_t unlimited = RLIM_INFINITY, cpu = weakened("time") ? unlimited : static_cast<rlim_t>(run.limits.cpu_seconds);
    const std::pair<int, rlim_t> limits[] = {
        {RLIMIT_AS, weakened("memory") ? unlimited : static_cast<rlim_t>(run.limits.address_space)},
        {RLIMIT_FSIZE, weakened("file-size") ? unlimited : static_cast<rlim_t>(run.limits.file_size)},
        {RLIMIT_NOFILE, static_cast<rlim_t>(run.limits.open_files)},
        {RLIMIT_CORE, 0},
        {RLIMIT_NPROC, static_cast<rlim_t>(processesOf(runner) + run.limits.processes + (bubblewrap ? 4 : 0))}};  // + bwrap's own
    const int timeout_seconds = weakened("time") ? 86400 : run.timeout_seconds;
    const int log = ::open(run.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (log < 0) die(run.log.string() + ": (file): cannot write the log");
    int report_pipe[2] = {-1, -1};
    if (run.channel && ::pipe2(report_pipe, O_CLOEXEC) != 0) die("cannot create a pipe");

    const pid_t pid = ::fork();
    if (pid < 0) die("fork failed");
    if (pid == 0) {
        ::setpgid(0, 0);  // its own process group: a timeout kills the group
        ::dup2(log, 1), ::dup2(log, 2);
        if (const int devnull = ::open("/dev/null", O_RDONLY); devnull >= 0) ::dup2(devnull, 0);
        // The channel's write end onto fd 3 (moved above 9 first: it may be 3 already); dup2 gives the
        // copy no close-on-exec flag, so exactly this one reaches the program.
        if (const int report = run.channel ? ::fcntl(report_pipe[1], F_DUPFD_CLOEXEC, 10) : 0; report < 0 || (run.channel && ::dup2(report, 3) != 3))
            ::_exit(125);
        if (run.cpu >= 0) {
            cpu_set_t set;
            CPU_ZERO(&set);
            CPU_SET(run.cpu, &set);
            ::sched_setaffinity(0, sizeof set, &set);
        }
        const struct rlimit cpu_limit {cpu, cpu == unlimited ? unlimited : cpu + 1};  // SIGXCPU, SIGKILL a second later
        ::setrlimit(RLIMIT_CPU, &cpu_limit);
        for (const auto& [resource, value] : limits) {
            const struct rlimit r {value, value};
            ::setrlimit(resource, &r);
        }
        if (container) {
            // The run's own user and group (raw system calls: this process alone, no C library
            // bookkeeping across threads), which drops every capability; then no_new_privs, Landlock, seccomp.
            ::umask(022);
            if (::syscall(SYS_setgroups, 0, nullptr) != 0) childFails("setgroups");
            if (::syscall(SYS_setresgid, user.uid, user.uid, user.uid) != 0) childFails("setresgid");
            if (::syscall(SYS_setresuid, user.uid, user.uid, user.uid) != 0) childFails("setresuid");
            if (::prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0) childFails("no_new_privs");
            if (ruleset >= 0 && ::syscall(SYS_landlock_restrict_self, ruleset, 0) != 0) childFails("Landlock");
            if (filter && ::prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, filter) != 0) childFails("seccomp");
            if (::chdir(workdir.c_str()) != 0) childFails("chdir to its scratch folder");
        }
        if (bubblewrap) ::execvp("bwrap", argv.data());
        else ::execvpe(argv[0], argv.data(), envp.data());
        ::_exit(127);
    }
    ::close(log);
    if (ruleset >= 0) ::close(ruleset);
    if (run.channel) ::close(report_pipe[1]);
    // Read the channel (if any) until the program ends or the deadline passes; then what is still buffered.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeout_seconds);
    const auto drain = [&](int wait_ms) {
        struct pollfd p {report_pipe[0], POLLIN, 0};
        char buf[4096];
        while (report_pipe[0] >= 0 && ::poll(&p, 1, wait_ms) > 0) {
            const ssize_t n = ::read(report_pipe[0], buf, sizeof buf);
            if (n <= 0) ::close(report_pipe[0]), report_pipe[0] = -1;
            else if (out.report.size() < (8u << 20)) out.report.append(buf, static_cast<size_t>(n));
            if (wait_ms > 0) break;
        }
    };
    int status = 0;
    for (bool reaped = false; !reaped;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
        if (left <= 0) {
            out.timed_out = true;
            ::kill(-pid, SIGKILL), ::kill(pid, SIGKILL);
            ::waitpid(pid, &status, 0);
            break;
        }
        if (report_pipe[0] >= 0) drain(static_cast<int>(std::min<long long>(left, 50)));
        else ::usleep(2000);
        reaped = ::waitpid(pid, &status, WNOHANG) == pid;
    }
    drain(0);
    if (report_pipe[0] >= 0) ::close(report_pipe[0]);
    ::kill(-pid, SIGKILL);  // whatever the program left in its group
    if (container) releaseUser(user, run.mounts);
    out.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return out;
}

}  // namespace grade
