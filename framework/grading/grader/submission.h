// Grading one submission: find its stage folders, lint, compile (sandboxed), link each stage's
// two programs, run every test in its own sandboxed process and read the verdict from the channel.
#pragma once
#include <map>
#include <set>

#include "common.h"

namespace grade {

/// One stage as the build made it ready for grading (objects are absolute paths in the build tree).
struct KitStage {
    std::string stage;  ///< "01"
    std::string dir;    ///< "01_hooke"
    std::vector<fs::path> tests, reference, stub;  ///< object files: graded tests, solutions/ (may be empty), stub
    std::vector<fs::path> proxy;  ///< the stage's functions as calls into the submission process (wire/make_proxies.cpp)
};

/// The grading kit: what CMake built (build/grade-kit/kit.json, written by cmake/grade_kit.cmake).
struct Kit {
    fs::path file;
    std::string compiler;
    std::vector<std::string> compile_flags;
    fs::path include_dir;  ///< a copy of the public headers (clothlab/core, clothlab/exercise) only
    std::string precompiled_header;  ///< in include_dir, compiled into its .gch: a submission file starts with it ("" none)
    std::vector<fs::path> system_includes;
    std::vector<fs::path> main_objects, libs;
    std::vector<std::string> link_flags;
    std::vector<fs::path> client_objects;  ///< the test process's side of the submission process (test_process/, wire/)
    std::vector<fs::path> server_objects;  ///< main() of the submission process and its side of the wire
    std::vector<std::string> server_link_flags;
    fs::path points_dir;
    std::vector<KitStage> stages;
    std::string fingerprint;  ///< changes when anything in the kit changes (cache key)
};

Kit loadKit(const fs::path& file);

/// Finds the stage folders (e.g. "01_hooke") anywhere below root (nested folders of an LMS export or
/// an archive with an extra top folder are fine). Missing stages are absent from the map.
/// Throws std::runtime_error with one line when the layout cannot be read.
std::map<std::string, fs::path> locateStages(const fs::path& root, const Kit& kit);

struct GradeOptions {
    fs::path work;              ///< this submission's build folder (cache): nothing else is written
    bool use_reference = true;  ///< the stages not graded link solutions/ (else the submission's own, or the stub)
    std::set<std::string> only;  ///< stages to grade (empty: all)
    int jobs = 1;
    int first_cpu = 0;  ///< test worker w runs on the usable CPU number first_cpu + w (a class: one per student graded at once)
    int timeout_seconds = 30;  ///< CPU seconds per test process (wall clock: 3 times that); after two timeouts a stage's remaining tests are not run
    bool progress = true;      ///< "grading stage 01 ..." on stderr
    fs::path shared_cache;     ///< objects and binaries shared by submissions with identical files (a class)
};

/// Grades the submission in `root`. Throws std::runtime_error when its layout cannot be read.
std::vector<StageResult> gradeSubmission(const Kit& kit, const fs::path& root, const GradeOptions& options);

/// One graded stage, ready to run: its test program, the submission process's program ("" none:
/// the self-checks) and the folder with the answers its experiments read.
struct StageRun {
    std::string stage;
    fs::path exe, server, answers;
};

/// Runs the tests of every stage in one queue (run.cpp): the stages in order, each stage's tests in its
/// points file's order, `jobs` processes at a time, worker w pinned to usable CPU first_cpu + w, so a
/// worker done with one stage goes on with the next. After two timeouts in a stage, its remaining
/// tests are not run.
std::vector<StageResult> runStages(const fs::path& points_dir, const std::vector<StageRun>& stages, int timeout_s, int jobs,
                                   int first_cpu, const fs::path& logs);

/// Usable CPU number `index` of this grader (counted modulo their number), or -1 (any) when the
/// grader cannot read its affinity.
int usableCpu(int index);

/// A folder holding a copy of the answers file (the graded experiments' numbers), or an empty folder
/// when there is none: only a regular file of at most 64 KiB is copied, never a link.
fs::path answersFolder(const fs::path& file, const fs::path& folder);

/// Runs the tests of a graded binary built elsewhere (the suite's self-checks, clothlab-grade --binary):
/// every test of the points file, each in its own (sandboxed) process; `answers`: the answers.json its
/// experiments read (empty: none). The binary's tests and the points file must name the same tests.
StageResult gradeBinary(const fs::path& points_dir, const std::string& stage, const fs::path& exe, const fs::path& answers,
                        int timeout_seconds, int jobs, const fs::path& tmp);

}  // namespace grade
