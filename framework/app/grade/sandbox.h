// Running untrusted programs (a submission's compiler run, its linked test binary) in a sandbox.
//
// With the sandbox on, a program runs under bubblewrap (bwrap, Debian package `bubblewrap`) in new
// PID, network, IPC, UTS and cgroup namespaces (and a user namespace when the grader is not root),
// with no capabilities, as user `nobody` when the grader runs as root, with no network, a fresh /tmp
// and only the paths in `mounts` (plus /usr, read-only). Limits (setrlimit): CPU seconds, address
// space, file size, open files, processes. A wall-clock timeout kills the whole sandbox (every
// process in its PID namespace dies with it).
#pragma once
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace grade {

namespace fs = std::filesystem;

struct Mount {
    fs::path host;    ///< file or folder outside
    fs::path inside;  ///< where the program sees it
    bool writable = false;
};

struct Limits {
    int cpu_seconds = 60;
    long long address_space = 4LL << 30;  ///< bytes
    long long file_size = 64LL << 20;     ///< bytes, any one file the program writes (also its log)
    int open_files = 64;
    int processes = 32;  ///< processes the program may start (on top of those its user already has)
};

struct SandboxRun {
    std::vector<std::string> argv;  ///< argv[0]: the program as seen inside
    std::vector<Mount> mounts;
    Limits limits;
    int timeout_seconds = 60;  ///< wall clock
    fs::path log;              ///< stdout and stderr of the program
    fs::path workdir = "/tmp";
    bool channel = false;  ///< open the graded-test channel (fd 3: the test process's report, see graded_main.cpp)
    int cpu = -1;          ///< ≥ 0: run on this CPU only (a test and its submission process share one)
    std::vector<std::pair<std::string, std::string>> env;  ///< variables set for the program (the rest is cleared)
};

struct RunOutcome {
    int exit_code = -1;   ///< exit status, or 128 + signal
    bool timed_out = false;
    std::string report;   ///< what the program wrote to fd 3 (channel)
};

/// Whether programs run sandboxed (bwrap) or directly (still with limits): set once, by the CLI.
void setSandbox(bool on);
bool sandboxOn();
/// Empty when bwrap works here, else why not (one line).
std::string sandboxProblem();

/// Runs the program; never throws for the program's own failure (see RunOutcome).
RunOutcome runSandboxed(const SandboxRun& run);

/// Makes a folder the sandboxed user may write (owned by nobody when the grader is root).
void makeWritableForSandbox(const fs::path& dir);

}  // namespace grade
