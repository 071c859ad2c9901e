// Grading one submission: find its stage folders, lint, compile (sandboxed), link each stage's
// graded tests, run every test in its own sandboxed process and read the verdict from the channel.
#pragma once
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "common.h"
#include "screen.h"

namespace grade {

/// One stage as the build made it ready for grading (objects are absolute paths in the build tree).
struct KitStage {
    std::string stage;  ///< "01"
    std::string dir;    ///< "01_hooke"
    std::vector<fs::path> tests, reference, stub;  ///< object files: graded tests, solutions/ (may be empty), stub
    std::vector<fs::path> proxy;  ///< the stage's functions as calls into the submission process (remote/)
};

/// The grading kit: what CMake built (kit.json in the build tree, written by cmake/grade_kit.cmake).
struct Kit {
    fs::path file;
    std::string compiler;
    std::vector<std::string> compile_flags;
    fs::path include_dir;  ///< a copy of the public headers (clothlab/core, clothlab/exercise) only
    std::string precompiled_header;  ///< in include_dir, compiled into its .gch: a submission file starts with it ("" none)
    std::vector<fs::path> system_includes;
    std::vector<fs::path> main_objects, libs;
    std::vector<std::string> link_flags;
    std::vector<fs::path> client_objects;     ///< the test process's side of the submission process (remote/)
    std::vector<fs::path> server_objects;     ///< main() of the submission process and its side of the wire
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

/// Runs the tests of a graded binary built elsewhere (the suite's self-checks): every test of the
/// points file, each in its own (sandboxed) process; `answers`: the answers.json its experiments read
/// (empty: none).
StageResult gradeBinary(const fs::path& points_dir, const std::string& stage, const fs::path& exe, const fs::path& answers,
                        int timeout_seconds, int jobs, const fs::path& tmp);

/// Runs fn(0..count-1) on `jobs` threads (fn(i, worker) when fn takes the worker's number too).
template <class Fn>
void parallelFor(int count, int jobs, Fn fn);

}  // namespace grade

#include <atomic>
#include <thread>
#include <type_traits>
template <class Fn>
void grade::parallelFor(int count, int jobs, Fn fn) {
    std::atomic<int> next{0};
    std::vector<std::thread> pool;
    for (int t = 0; t < std::max(1, std::min(jobs, count)); ++t)
        pool.emplace_back([&, t] {
            for (int i; (i = next++) < count;) {
                if constexpr (std::is_invocable_v<Fn, int, int>) fn(i, t);
                else fn(i);
            }
        });
    for (auto& th : pool) th.join();
}
