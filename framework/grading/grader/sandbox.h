// Running untrusted programs (a submission's compiler run, its test and submission processes)
// confined, in one of two ways chosen once per grading (docs/grading.md, "Two confinements", has the
// table of what each gives and lacks):
//  - bubblewrap (bwrap): new PID, network, IPC, UTS and cgroup namespaces, no capabilities, user
//    `nobody` when the grader is root, a fresh /tmp and only the paths in `mounts` (plus /usr, read-only);
//  - container mode, where no namespace can be made (Docker's default confinement) and the grader is
//    root: a user and group of its own per run, no_new_privs, Landlock where the kernel has it and a
//    seccomp filter; the programs see the host's paths (a path of `mounts` becomes the mount's host path).
// Both apply the limits (setrlimit) and a wall clock.
#pragma once
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace grade {

namespace fs = std::filesystem;

struct Mount {
    fs::path host;    ///< file or folder outside
    fs::path inside;  ///< where the program sees it (bubblewrap; container mode: the host path)
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
    fs::path workdir = "/tmp";  ///< "/tmp": the run's own scratch folder in container mode
    bool channel = false;  ///< open the graded-test channel (fd 3: the test process's report, see graded_main.cpp)
    int cpu = -1;          ///< ≥ 0: run on this CPU only (a test and its submission process share one)
    std::vector<std::pair<std::string, std::string>> env;  ///< variables set for the program (the rest is cleared)
};

struct RunOutcome {
    int exit_code = -1;   ///< exit status, or 128 + signal
    bool timed_out = false;
    std::string report;   ///< what the program wrote to fd 3 (channel)
};

/// Runs the program; never throws for the program's own failure (see RunOutcome).
RunOutcome runSandboxed(const SandboxRun& run);

/// Makes a folder the confined user may write: owned by nobody when bubblewrap runs as root (container
/// mode hands it to each run's user while that run lasts).
void makeWritableForSandbox(const fs::path& dir);

enum class Confinement { none, bubblewrap, container };

/// How programs run: set once by the CLI (default bubblewrap). `none` still applies the limits.
void setConfinement(Confinement c);
Confinement confinement();
/// "bubblewrap", "container mode (...what it lacks...)" or "none (...)": for the reports.
std::string confinementName();

/// Empty when bwrap can make its sandbox here, else why not (one line).
std::string bubblewrapProblem();

/// What a submission's programs must not touch, checked by container mode's probe.
struct Protected {
    std::vector<fs::path> unreadable;  ///< files a program must fail to open for reading
    std::vector<fs::path> unwritable;  ///< files it must fail to open for writing, folders it must fail to create a file in
    std::vector<fs::path> needed;      ///< paths the programs read (the kit, the work folder): every folder above must let others pass
    bool students_apart = false;       ///< several students' submissions at once (--class): needs Landlock in container mode
};

/// The instructor's files under `tree` (the folder holding the points files' tests/): unreadable, every
/// file of solutions/ and tests/instructor/, the points files, and `reference` (objects built from
/// solutions/: only when the tree has solutions/; the student copy's are the students' own files);
/// unwritable, the tree, the points files and `unwritable`.
Protected instructorFiles(const fs::path& tree, const std::vector<fs::path>& reference, const std::vector<fs::path>& unwritable);

/// Sets the confinement `wanted`: "auto" (bubblewrap where it works, else container mode),
/// "bubblewrap" or "container". Container mode holds when the grader is root, every folder above
/// `p.needed` lets other users pass, and a probe confined as a test fails to read every `p.unreadable`,
/// to write every `p.unwritable`, to open an AF_INET socket and to signal the grader. Returns "" when
/// the confinement holds, else why not (one line; the confinement is then `none`).
std::string chooseConfinement(const std::string& wanted, const Protected& p);

/// The probe's main(): `clothlab-grade --container-probe [r FILE | w PATH]...` prints one line per
/// guarantee that does not hold and exits 1 if there is one (run only by chooseConfinement).
int containerProbeMain(int argc, char** argv);

}  // namespace grade
