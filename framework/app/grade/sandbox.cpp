#include "sandbox.h"

#include <fcntl.h>
#include <sched.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <fstream>
#include <set>

#include "common.h"

namespace grade {

namespace {

bool g_sandbox = true;
constexpr uid_t kNobody = 65534;

/// Processes the user `uid` has now (RLIMIT_NPROC counts them all, so the limit is this + allowance).
int processesOf(uid_t uid) {
    int n = 0;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator("/proc", ec)) {
        struct stat st {};
        const std::string name = e.path().filename().string();
        if (name.find_first_not_of("0123456789") == std::string::npos && ::stat(e.path().c_str(), &st) == 0 && st.st_uid == uid) ++n;
    }
    return n;
}

/// The bwrap command line. Run by an ordinary user, bwrap makes a user namespace and drops every
/// capability. Run by root, bwrap keeps root (so it can reach paths only root may traverse) but
/// the program itself starts through setpriv as user nobody, with no capabilities and no way to
/// gain any: then the process limit counts nobody's processes (root is exempt from it).
std::vector<std::string> bwrapArgs(const SandboxRun& run) {
    const bool root = ::geteuid() == 0;
    std::vector<std::string> a = {"bwrap", "--die-with-parent", "--new-session", "--hostname", "grader", "--clearenv",
                                  "--setenv", "PATH", "/usr/bin", "--setenv", "HOME", "/tmp", "--ro-bind", "/usr", "/usr"};
    for (const auto& [name, value] : run.env) a.insert(a.end(), {"--setenv", name, value});
    if (root) a.insert(a.begin() + 1, {"--unshare-ipc", "--unshare-pid", "--unshare-net", "--unshare-uts", "--unshare-cgroup-try"});
    else a.insert(a.begin() + 1, {"--unshare-all", "--cap-drop", "ALL"});
    for (const char* l : {"lib", "lib64", "bin", "sbin"})
        if (fs::is_symlink(std::string("/") + l)) a.insert(a.end(), {"--symlink", fs::read_symlink(std::string("/") + l).string(), std::string("/") + l});
        else if (fs::exists(std::string("/") + l)) a.insert(a.end(), {"--ro-bind", std::string("/") + l, std::string("/") + l});
    if (fs::exists("/etc/ld.so.cache")) a.insert(a.end(), {"--ro-bind", "/etc/ld.so.cache", "/etc/ld.so.cache"});
    a.insert(a.end(), {"--dev", "/dev", "--perms", "1777", "--size", std::to_string(run.limits.file_size * 2), "--tmpfs", "/tmp"});
    // The folders the mounts sit in, world-readable (bwrap would make them for root alone).
    std::set<std::string> parents;
    for (const auto& m : run.mounts)
        for (fs::path p = m.inside.parent_path(); p != p.root_path() && !p.empty(); p = p.parent_path()) parents.insert(p.string());
    for (const auto& p : parents)  // sorted: a parent before its children
        if (p != "/usr" && p.rfind("/usr/", 0) != 0 && p != "/tmp") a.insert(a.end(), {"--perms", "0755", "--dir", p});
    for (const auto& m : run.mounts)
        a.insert(a.end(), {m.writable ? "--bind" : "--ro-bind", m.host.string(), m.inside.string()});
    a.insert(a.end(), {"--chdir", run.workdir.string(), "--"});
    if (root)
        a.insert(a.end(), {"/usr/bin/setpriv", "--reuid=65534", "--regid=65534", "--clear-groups", "--no-new-privs",
                           "--inh-caps=-all", "--bounding-set=-all", "--"});
    a.insert(a.end(), run.argv.begin(), run.argv.end());
    return a;
}

void setLimit(int resource, rlim_t value) {
    const struct rlimit r {value, value};
    ::setrlimit(resource, &r);
}

}  // namespace

void setSandbox(bool on) { g_sandbox = on; }
bool sandboxOn() { return g_sandbox; }

std::string sandboxProblem() {
    static const std::string problem = [] {
        SandboxRun probe;
        probe.argv = {"/usr/bin/true"};
        probe.timeout_seconds = 20;
        probe.log = fs::temp_directory_path() / ("clothlab-sandbox-probe-" + std::to_string(::getpid()) + ".log");
        const bool was = g_sandbox;
        g_sandbox = true;
        const RunOutcome r = runSandboxed(probe);
        g_sandbox = was;
        std::string log = readFile(probe.log, 2000);
        fs::remove(probe.log);
        if (r.exit_code == 0) return std::string();
        if (r.exit_code == 127) return std::string("bwrap is not installed (Debian package bubblewrap; ./lab setup installs it)");
        return "bwrap cannot create a sandbox here (exit " + std::to_string(r.exit_code) + "): " + firstLines(log, 1, "");
    }();
    return problem;
}

void makeWritableForSandbox(const fs::path& dir) {
    fs::create_directories(dir);
    if (::geteuid() == 0) {
        if (::chown(dir.c_str(), kNobody, kNobody) != 0) die(dir.string() + ": (folder): cannot hand it to user nobody");
    } else {
        fs::permissions(dir, fs::perms::owner_all, fs::perm_options::add);
    }
}

/// Without the sandbox the program sees the host's paths: a path inside a mount (at the start of an
/// argument or after its '=') becomes the mount's host path.
std::string outside(const std::string& arg, const std::vector<Mount>& mounts) {
    const size_t at = arg.rfind("--", 0) == 0 && arg.find('=') != std::string::npos ? arg.find('=') + 1 : 0;
    for (const auto& m : mounts) {
        const std::string in = m.inside.string();
        if (arg.compare(at, in.size(), in) == 0 && (arg.size() == at + in.size() || arg[at + in.size()] == '/'))
            return arg.substr(0, at) + m.host.string() + arg.substr(at + in.size());
    }
    return arg;
}

RunOutcome runSandboxed(const SandboxRun& run) {
    RunOutcome out;
    // Everything the child needs is prepared before fork(): after it, only async-signal-safe calls.
    std::vector<std::string> args = g_sandbox ? bwrapArgs(run) : run.argv;
    std::vector<std::string> env_text;
    if (!g_sandbox) {
        for (auto& a : args) a = outside(a, run.mounts);
        for (char** e = ::environ; *e; ++e) env_text.emplace_back(*e);
        for (const auto& [name, value] : run.env) env_text.push_back(name + "=" + outside(value, run.mounts));
    }
    std::vector<char*> argv, envp;
    for (const auto& s : args) argv.push_back(const_cast<char*>(s.c_str()));
    argv.push_back(nullptr);
    for (const auto& s : env_text) envp.push_back(const_cast<char*>(s.c_str()));
    envp.push_back(nullptr);
    const uid_t runner = ::geteuid() == 0 && g_sandbox ? kNobody : ::geteuid();
    const rlim_t nproc = static_cast<rlim_t>(processesOf(runner) + run.limits.processes + 4);  // + bwrap's own
    const int log = ::open(run.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (log < 0) die(run.log.string() + ": (file): cannot write the log");
    int report_pipe[2] = {-1, -1};
    if (run.channel && ::pipe2(report_pipe, O_CLOEXEC) != 0) die("cannot create a pipe");
    const char* program = g_sandbox ? "bwrap" : argv[0];

    const pid_t pid = ::fork();
    if (pid < 0) die("fork failed");
    if (pid == 0) {
        ::setpgid(0, 0);  // its own process group: a timeout kills the group
        ::dup2(log, 1);
        ::dup2(log, 2);
        const int devnull = ::open("/dev/null", O_RDONLY);
        if (devnull >= 0) ::dup2(devnull, 0);
        if (run.channel) {
            // The write end onto fd 3 (moved above 9 first: it may be 3 already); dup2 gives the copy no
            // close-on-exec flag, so exactly this one reaches the program.
            const int report = ::fcntl(report_pipe[1], F_DUPFD_CLOEXEC, 10);
            if (report < 0 || ::dup2(report, 3) != 3) ::_exit(125);
        }
        if (run.cpu >= 0) {
            cpu_set_t set;
            CPU_ZERO(&set);
            CPU_SET(run.cpu, &set);
            ::sched_setaffinity(0, sizeof set, &set);
        }
        {  // SIGXCPU at the limit, SIGKILL a second later for a program that ignores SIGXCPU
            const struct rlimit cpu {static_cast<rlim_t>(run.limits.cpu_seconds), static_cast<rlim_t>(run.limits.cpu_seconds) + 1};
            ::setrlimit(RLIMIT_CPU, &cpu);
        }
        setLimit(RLIMIT_AS, static_cast<rlim_t>(run.limits.address_space));
        setLimit(RLIMIT_FSIZE, static_cast<rlim_t>(run.limits.file_size));
        setLimit(RLIMIT_NOFILE, static_cast<rlim_t>(run.limits.open_files));
        setLimit(RLIMIT_CORE, 0);
        setLimit(RLIMIT_NPROC, nproc);
        if (g_sandbox) ::execvp(program, argv.data());
        else ::execvpe(program, argv.data(), envp.data());
        ::_exit(127);
    }
    ::close(log);
    if (run.channel) ::close(report_pipe[1]);
    // Read the report channel (if any) until the deadline; then reap.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(run.timeout_seconds);
    int status = 0;
    bool reaped = false;
    while (!reaped) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
        if (left <= 0) {
            out.timed_out = true;
            ::kill(-pid, SIGKILL);
            ::kill(pid, SIGKILL);
            ::waitpid(pid, &status, 0);
            break;
        }
        if (run.channel && report_pipe[0] >= 0) {
            struct pollfd p {report_pipe[0], POLLIN, 0};
            if (::poll(&p, 1, static_cast<int>(std::min<long long>(left, 50))) > 0) {
                char buf[4096];
                const ssize_t n = ::read(report_pipe[0], buf, sizeof buf);
                if (n > 0 && out.report.size() < (8u << 20)) out.report.append(buf, static_cast<size_t>(n));
                if (n <= 0) { ::close(report_pipe[0]); report_pipe[0] = -1; }
            }
        } else {
            ::usleep(2000);
        }
        if (::waitpid(pid, &status, WNOHANG) == pid) reaped = true;
    }
    if (run.channel && report_pipe[0] >= 0) {  // what is still buffered
        ::fcntl(report_pipe[0], F_SETFL, O_NONBLOCK);
        char buf[4096];
        ssize_t n;
        while ((n = ::read(report_pipe[0], buf, sizeof buf)) > 0 && out.report.size() < (8u << 20)) out.report.append(buf, static_cast<size_t>(n));
        ::close(report_pipe[0]);
    }
    ::kill(-pid, SIGKILL);  // whatever the program left in its group
    out.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);

    return out;
}

}  // namespace grade
