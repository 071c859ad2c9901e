// clothlab-grade: what the grader's parts share: results and their totals, points files, files, the
// cache, a pool of workers, and the red team's test-only switches.
#pragma once
#include <sys/stat.h>

#include <atomic>
#include <filesystem>
#include <functional>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

#include <nlohmann/json.hpp>

namespace grade {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;  // keeps the order of the points files (task order)

struct TestResult {
    std::string name;  ///< Suite.Test
    bool passed = false;
    double points = 0, max_points = 0;
    std::string message;  ///< why it failed
    bool bonus = false;   ///< a bonus test: its points count beside the stage's points, never in max_points
};

/// Whether a stage was graded, or why not (then every test fails with the stage's problem).
enum class Status { graded, not_submitted, rejected, does_not_compile, does_not_link, not_graded };
std::string statusName(Status s);  ///< "graded", "not submitted", ... (the reports and the JSON)
Status statusNamed(const std::string& name);

struct StageResult {
    std::string stage, title;
    Status status = Status::graded;
    std::string problem;  ///< what the student must fix when the stage was not graded
    std::vector<TestResult> tests;
};

/// Points and tests summed over stages, the bonus tests apart (they count beside the stages' points).
struct Totals {
    double points = 0, max_points = 0, bonus = 0, max_bonus = 0;
    int passed = 0, tests = 0, bonus_passed = 0, bonus_tests = 0;
};
Totals totals(const std::vector<StageResult>& stages);

[[noreturn]] void die(const std::string& msg);
std::string readFile(const fs::path& p, size_t max_bytes = 16u << 20);
void writeFile(const fs::path& p, const std::string& text);

/// SHA-256 of `data` (OpenSSL's libcrypto) as 64 hex digits.
std::string sha256(const std::string& data);

/// The grader's caches (compiled stages, linked programs, a class's results): the result stored in
/// `file` if it was made from what has the SHA-256 `hash`, else make()'s, stored there. One caller at
/// a time per file: two submissions with the same files make it once.
json cached(const fs::path& file, const std::string& hash, const std::function<json()>& make);

/// The points file tests/NN_name.points.json of stage NN, checked: {"title": "...", "tests": {"Suite.Test": points > 0}},
/// optionally "bonus": {"Suite.Test": points > 0} (tests of an optional task, counted beside the stage's points).
json loadPoints(const fs::path& points_dir, const std::string& stage);

/// The stage as its points file lists it: its tests in order (the bonus tests last), none run yet.
StageResult pointsStage(const fs::path& points_dir, const std::string& stage);

/// Every test of a stage failed with `why` (a stage that could not be graded).
StageResult ungradedStage(const fs::path& points_dir, const std::string& stage, Status status, const std::string& why);

/// The first n non-empty lines of text, joined with "\n" + indent.
std::string firstLines(const std::string& text, int n, const std::string& indent = "        ");

/// Calls fn(path, lstat of it) for each entry of `dir` (or of its whole tree), never following a link;
/// a folder it may not read is skipped.
template <class Fn> void forEachEntry(const fs::path& dir, bool recursive, Fn fn) {
    std::error_code ec;
    for (fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec), end; !ec && it != end; it.increment(ec)) {
        if (!recursive) it.disable_recursion_pending();
        struct stat st {};
        if (::lstat(it->path().c_str(), &st) == 0) fn(it->path(), st);
    }
}

/// Runs fn(i) for i = 0..count-1 on `jobs` threads (fn(i, worker) when fn takes the worker's number too).
template <class Fn> void parallelFor(int count, int jobs, Fn fn) {
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

// A defence switched off, to show that the attacks aimed at it get through without it: only in the
// test tool clothlab-grade-weakened (tests/sandbox/CMakeLists.txt, built with CLOTHLAB_GRADER_TEST_SWITCHES), where
// CLOTHLAB_WEAKEN names them; clothlab-grade has no switch (tests/instructor/hostile/README.md).
#ifdef CLOTHLAB_GRADER_TEST_SWITCHES
bool weakened(const char* defence);
#else
constexpr bool weakened(const char*) { return false; }
#endif

}  // namespace grade
