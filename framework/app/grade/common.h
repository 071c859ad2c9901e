// clothlab-grade: what the grader's parts share (results, points files, small file helpers).
#pragma once
#include <filesystem>
#include <string>
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

struct StageResult {
    std::string stage, title;
    std::string status = "graded";  ///< graded | not submitted | rejected | does not compile | does not link
    std::string problem;            ///< what the student must fix when status is not "graded"
    std::vector<TestResult> tests;
    double points() const;      ///< earned, without the bonus tests
    double max_points() const;  ///< possible, without the bonus tests
    double bonus() const;       ///< earned by the bonus tests
    int passed() const;
};

[[noreturn]] void die(const std::string& msg);
std::string readFile(const fs::path& p, size_t max_bytes = 16u << 20);
void writeFile(const fs::path& p, const std::string& text);

/// SHA-256 of `data` (OpenSSL's libcrypto) as 64 hex digits: the key of the grader's caches, which
/// reuse a result whose stored digest equals the digest of what it would be made from.
std::string sha256(const std::string& data);

/// The points file tests/NN_name.points.json of stage NN, checked: {"title": "...", "tests": {"Suite.Test": points > 0}},
/// optionally "bonus": {"Suite.Test": points > 0} (tests of an optional task, counted beside the stage's points).
json loadPoints(const fs::path& points_dir, const std::string& stage);

/// The graded tests of a points file in its order, the bonus tests last, with their points.
std::vector<TestResult> pointsTests(const json& points);

/// Every test of a stage failed with `why` (a stage that could not be graded).
StageResult ungradedStage(const fs::path& points_dir, const std::string& stage, const std::string& status,
                          const std::string& why);

/// The first n non-empty lines of text, joined with "\n" + indent.
std::string firstLines(const std::string& text, int n, const std::string& indent = "        ");

}  // namespace grade
