// Small helpers shared by the graded tests (messages for students).
#pragma once

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <Eigen/Geometry>

#include "clothlab/core/types.h"
#include "clothlab/io/scene_json.h"
#include "clothlab/sim/run.h"

namespace clothlab::testing_util {

// ---- Numbers in messages --------------------------------------------------------------------------

/// A number with 6 significant digits ("0.3", not "0.29999999999999999").
inline std::string num(double v) {
    std::ostringstream s;
    s.precision(6);
    s << v;
    return s.str();
}

/// "(x, y, z)" for failure messages, each coordinate with 6 significant digits: "(0.1, 0, -2.5)".
inline std::string str(const Vec3& v) {
    return "(" + num(v.x()) + ", " + num(v.y()) + ", " + num(v.z()) + ")";
}

/// A matrix or vector for failure messages, 6 significant digits: a row or column vector as
/// "(a, b, c)", a matrix column by column, e.g. the positions of a 3 x N matrix as "[(x0), (x1), ...]".
template <class Derived>
std::string str(const Eigen::MatrixBase<Derived>& m) {
    auto vec = [](const auto& v) {
        std::string s = "(";
        for (Eigen::Index i = 0; i < v.size(); ++i) s += (i ? ", " : "") + num(static_cast<double>(v(i)));
        return s + ")";
    };
    if (m.rows() == 1 || m.cols() == 1) return vec(m.reshaped());
    std::string s = "[";
    for (Eigen::Index j = 0; j < m.cols(); ++j) s += (j ? ", " : "") + vec(m.col(j));
    return s + "]";
}

/// Two numbers that are compared: 6 significant digits, or more until they print differently
/// (so "expected 1, got 1" never appears for 1 and 1.0000001).
inline std::pair<std::string, std::string> numPair(double a, double b) {
    for (int p = 6; p <= 17; ++p) {
        std::ostringstream x, y;
        x.precision(p), y.precision(p);
        x << a, y << b;
        if (x.str() != y.str() || a == b || p == 17) return {x.str(), y.str()};
    }
    return {num(a), num(b)};
}

/// EXPECT_NEAR's check (|actual - expected| <= tolerance) with a message in 6 significant digits that
/// names both expressions: "speed = 9.81, expected a * T = 9.7 within 0.01 (off by 0.11)". Use through
/// EXPECT_CLOSE / ASSERT_CLOSE; stream the physical explanation after it as with EXPECT_NEAR.
inline testing::AssertionResult closeFormat(const char* actual_expr, const char* expected_expr, const char* tol_expr, double actual,
                                            double expected, double tolerance) {
    const double diff = std::abs(actual - expected);
    if (diff <= tolerance) return testing::AssertionSuccess();
    (void)tol_expr;
    const auto [a, e] = numPair(actual, expected);
    return testing::AssertionFailure() << actual_expr << " = " << a << ", expected " << expected_expr << " = " << e << " within "
                                       << num(tolerance) << " (off by " << num(diff) << ").";
}

/// EXPECT_DOUBLE_EQ's check (equal up to 4 units in the last place) with both numbers printed only as
/// precisely as needed to tell them apart (0.3, not 0.29999999999999999). Use through EXPECT_SAME_DOUBLE.
inline testing::AssertionResult sameDoubleFormat(const char* actual_expr, const char* expected_expr, double actual, double expected) {
    using FP = testing::internal::FloatingPoint<double>;
    if (FP(actual).AlmostEquals(FP(expected))) return testing::AssertionSuccess();
    const auto [a, e] = numPair(actual, expected);
    return testing::AssertionFailure() << actual_expr << " = " << a << ", expected " << expected_expr << " = " << e
                                       << " (equal up to rounding).";
}

/// EXPECT_LT/GT/LE/GE/EQ's checks on numbers with a message in 6 significant digits that names the
/// expressions: "worst = 0.2, must be < 0.15." (GoogleTest's own would print 0.20000000000000001).
/// Use through EXPECT_LESS, EXPECT_LESS_EQ, EXPECT_GREATER, EXPECT_GREATER_EQ, EXPECT_EXACT (and ASSERT_*).
template <class Cmp>
testing::AssertionResult compareFormat(const char* actual_expr, const char* bound_expr, double actual, double bound, Cmp cmp,
                                       const char* op) {
    if (cmp(actual, bound)) return testing::AssertionSuccess();
    const auto [a, b] = numPair(actual, bound);
    testing::AssertionResult r = testing::AssertionFailure();
    r << actual_expr << " = " << a << ", must be " << op << " ";
    if (b == bound_expr) r << b << ".";
    else r << bound_expr << " = " << b << ".";
    return r;
}
inline testing::AssertionResult lessFormat(const char* ae, const char* be, double a, double b) {
    return compareFormat(ae, be, a, b, [](double x, double y) { return x < y; }, "<");
}
inline testing::AssertionResult lessEqFormat(const char* ae, const char* be, double a, double b) {
    return compareFormat(ae, be, a, b, [](double x, double y) { return x <= y; }, "<=");
}
inline testing::AssertionResult greaterFormat(const char* ae, const char* be, double a, double b) {
    return compareFormat(ae, be, a, b, [](double x, double y) { return x > y; }, ">");
}
inline testing::AssertionResult greaterEqFormat(const char* ae, const char* be, double a, double b) {
    return compareFormat(ae, be, a, b, [](double x, double y) { return x >= y; }, ">=");
}
/// Exactly equal (==), as EXPECT_EQ on doubles, printed as precisely as needed to tell them apart.
inline testing::AssertionResult exactFormat(const char* ae, const char* be, double a, double b) {
    return compareFormat(ae, be, a, b, [](double x, double y) { return x == y; }, "exactly");
}

/// A rod of rest length d (m) between particles a and b, for the tests of stages other than 04 that need
/// constraints (the projection of a distance constraint is task 4.3, which these tests must not give
/// away nor depend on): two free ends each take half of the error along the rod, a free end beside a
/// pinned one (w = 0) all of it, two pinned ends none. Masses are otherwise ignored: it conserves
/// momentum only for equal masses, so tests that check momentum use equal masses or
/// pullTowardsCentreOfMass().
inline void projectRod(Matrix3X& p, const VectorX& w, int a, int b, double d) {
    const Vec3 e = p.col(a) - p.col(b);
    const double len = e.norm();
    if (len < 1e-12) return;
    const double share_a = w[a] > 0 ? (w[b] > 0 ? 0.5 : 1.0) : 0.0, share_b = w[b] > 0 ? (w[a] > 0 ? 0.5 : 1.0) : 0.0;
    const Vec3 error = (len - d) / len * e;
    p.col(a) -= share_a * error;
    p.col(b) += share_b * error;
}

/// A constraint that conserves momentum for any masses, and is no exercise: the free particles (w > 0)
/// move the fraction `share` of the way towards their centre of mass c = Σ m_i p_i / Σ m_i, so
/// Σ m_i Δp_i = share (Σ m_i c − Σ m_i p_i) = 0; pinned particles stay.
inline void pullTowardsCentreOfMass(Matrix3X& p, const VectorX& w, double share) {
    Vec3 c = Vec3::Zero();
    double mass = 0;
    for (Eigen::Index i = 0; i < p.cols(); ++i)
        if (w[i] > 0) c += p.col(i) / w[i], mass += 1 / w[i];
    if (mass <= 0) return;
    c /= mass;
    for (Eigen::Index i = 0; i < p.cols(); ++i)
        if (w[i] > 0) p.col(i) += share * (c - p.col(i));
}

}  // namespace clothlab::testing_util

/// EXPECT_DOUBLE_EQ with numbers as short as they can be (testing_util::sameDoubleFormat).
#define EXPECT_SAME_DOUBLE(actual, expected) \
    EXPECT_PRED_FORMAT2(::clothlab::testing_util::sameDoubleFormat, actual, expected)
/// EXPECT_NEAR with numbers in 6 significant digits (testing_util::closeFormat).
#define EXPECT_CLOSE(actual, expected, tolerance) \
    EXPECT_PRED_FORMAT3(::clothlab::testing_util::closeFormat, actual, expected, tolerance)
/// ASSERT_NEAR with numbers in 6 significant digits (testing_util::closeFormat).
#define ASSERT_CLOSE(actual, expected, tolerance) \
    ASSERT_PRED_FORMAT3(::clothlab::testing_util::closeFormat, actual, expected, tolerance)
/// EXPECT_LT / EXPECT_LE / EXPECT_GT / EXPECT_GE / EXPECT_EQ on doubles with numbers in 6 significant
/// digits (testing_util::compareFormat); the ASSERT_ forms stop the test.
#define EXPECT_LESS(actual, bound) EXPECT_PRED_FORMAT2(::clothlab::testing_util::lessFormat, actual, bound)
#define EXPECT_LESS_EQ(actual, bound) EXPECT_PRED_FORMAT2(::clothlab::testing_util::lessEqFormat, actual, bound)
#define EXPECT_GREATER(actual, bound) EXPECT_PRED_FORMAT2(::clothlab::testing_util::greaterFormat, actual, bound)
#define EXPECT_GREATER_EQ(actual, bound) EXPECT_PRED_FORMAT2(::clothlab::testing_util::greaterEqFormat, actual, bound)
#define EXPECT_EXACT(actual, expected) EXPECT_PRED_FORMAT2(::clothlab::testing_util::exactFormat, actual, expected)
#define ASSERT_LESS(actual, bound) ASSERT_PRED_FORMAT2(::clothlab::testing_util::lessFormat, actual, bound)
#define ASSERT_GREATER(actual, bound) ASSERT_PRED_FORMAT2(::clothlab::testing_util::greaterFormat, actual, bound)
#define ASSERT_GREATER_EQ(actual, bound) ASSERT_PRED_FORMAT2(::clothlab::testing_util::greaterEqFormat, actual, bound)
#define ASSERT_EXACT(actual, expected) ASSERT_PRED_FORMAT2(::clothlab::testing_util::exactFormat, actual, expected)

// Every double streamed into a failure message (`EXPECT_...(...) << x`, `AssertionFailure() << x`) prints
// with 6 significant digits, not GoogleTest's 17 (0.3, not 0.29999999999999999). Non-template overloads
// beat the member templates of Message and AssertionResult, and ADL finds them in namespace testing.
namespace testing {
inline Message& operator<<(Message& m, const double& v) { return m << ::clothlab::testing_util::num(v).c_str(); }
inline Message& operator<<(Message&& m, const double& v) { return m << ::clothlab::testing_util::num(v).c_str(); }
inline AssertionResult& operator<<(AssertionResult& r, const double& v) { return r << ::clothlab::testing_util::num(v).c_str(); }
inline AssertionResult& operator<<(AssertionResult&& r, const double& v) { return r << ::clothlab::testing_util::num(v).c_str(); }
}  // namespace testing

namespace clothlab::testing_util {

// ---- Graded experiments: the student's answers.json ------------------------------------------------
// Each stage ends with an experiment the student writes up in exercises/NN_name/answers.json:
//   {"predict": {"<field>": {"value": <number or null>, "what": "<the quantity, from theory>"}, ...},
//    "measure": {"<field>": {"value": <number or null>, "how": "<the command>"}, ...},
//    "explain": "<one or two sentences: why the measurement differs from the prediction, or agrees>"}
// The student's tests (AnswerFileIsComplete) check only that the file is complete and well formed; the
// numbers are graded by the instructor's tests (tests/instructor/experiments/, not in the student copy),
// which compute the physics from first principles and rerun the student's own code.

#ifndef CLOTHLAB_ANSWERS_DEFAULT_DIR
#define CLOTHLAB_ANSWERS_DEFAULT_DIR "exercises"
#endif

/// The answers file of a stage: $CLOTHLAB_ANSWERS_DIR/answers.json when that variable is set (the
/// grader copies the submission's file into its sandbox and sets it), else the compile-time default
/// CLOTHLAB_ANSWERS_DEFAULT_DIR/<stageDir>/answers.json (tests/CMakeLists.txt: solutions/ when the
/// stage is built from the reference, else exercises/).
/// @param stageDir  the stage's folder name, e.g. "01_hooke"
inline std::string answersPath(const char* stageDir) {
    if (const char* dir = std::getenv("CLOTHLAB_ANSWERS_DIR"); dir && *dir) return std::string(dir) + "/answers.json";
    return std::string(CLOTHLAB_ANSWERS_DEFAULT_DIR) + "/" + stageDir + "/answers.json";
}

/// The answers file as the student knows it, for messages: $CLOTHLAB_ANSWERS_SHOWN_AS when set (the
/// grader sets exercises/<stageDir>/answers.json beside its sandbox's copy), else answersPath().
/// @param stageDir  the stage's folder name, e.g. "01_hooke"
inline std::string answersShownAs(const char* stageDir) {
    if (const char* shown = std::getenv("CLOTHLAB_ANSWERS_SHOWN_AS"); shown && *shown) return shown;
    return answersPath(stageDir);
}

/// Reads answersPath(stageDir) into *doc. A missing or unreadable file or malformed JSON is a failure
/// whose message names the file; nothing throws.
inline testing::AssertionResult readAnswersFile(const char* stageDir, nlohmann::json* doc) {
    const std::string path = answersShownAs(stageDir);
    std::ifstream in(answersPath(stageDir));
    if (!in)
        return testing::AssertionFailure() << path << ": cannot read the answers file (the task sheet's \"Experiment\" says what to enter)";
    *doc = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    if (doc->is_discarded()) return testing::AssertionFailure() << path << ": not valid JSON (check commas, quotes and brackets)";
    if (!doc->is_object()) return testing::AssertionFailure() << path << ": expected an object with \"predict\", \"measure\" and \"explain\"";
    return testing::AssertionSuccess();
}

/// The number in `section`.`field`.value of an answers file already read (doc; `path` as the student
/// knows it), into *value. A missing field, a null (not entered yet) or a non-number is a failure whose
/// message names the file and the field.
inline testing::AssertionResult answerIn(const nlohmann::json& doc, const std::string& path, const std::string& section,
                                         const std::string& field, double* value) {
    const std::string name = section + "." + field;
    if (!doc.contains(section) || !doc[section].is_object() || !doc[section].contains(field))
        return testing::AssertionFailure() << path << ": " << name << ": missing (keep the file's fields as shipped)";
    const nlohmann::json& entry = doc[section][field];
    const nlohmann::json v = entry.is_object() && entry.contains("value") ? entry["value"] : nlohmann::json();
    if (v.is_null())
        return testing::AssertionFailure() << path << ": " << name << ".value: null, not entered yet"
                                           << (section == "predict" ? " (a number from theory, before you run anything)"
                                                                    : " (run the command in its \"how\" on your own code)");
    if (!v.is_number() || !std::isfinite(v.get<double>()))
        return testing::AssertionFailure() << path << ": " << name << ".value: expected a number (got " << v.dump() << ")";
    *value = v.get<double>();
    return testing::AssertionSuccess();
}

/// Reads answersPath(stageDir) and the number the student entered as `section`.`field`.value (section
/// "predict" or "measure") into *value; every failure names the file (and the field); nothing throws.
inline testing::AssertionResult readAnswer(const char* stageDir, const std::string& section, const std::string& field, double* value) {
    nlohmann::json doc;
    if (auto read = readAnswersFile(stageDir, &doc); !read) return read;
    return answerIn(doc, answersShownAs(stageDir), section, field, value);
}

/// The student's check of the answers file: every field of `predicts` and `measures` holds a finite
/// number and "explain" has at least five words. It grades no number: those are graded by the
/// instructor (the message says so).
inline testing::AssertionResult answerFileIsComplete(const char* stageDir, const std::vector<std::string>& predicts,
                                                     const std::vector<std::string>& measures) {
    nlohmann::json doc;
    if (auto read = readAnswersFile(stageDir, &doc); !read) return read;
    const std::string path = answersShownAs(stageDir);
    double v = 0;
    for (const auto& f : predicts)
        if (auto r = answerIn(doc, path, "predict", f, &v); !r) return r;
    for (const auto& f : measures)
        if (auto r = answerIn(doc, path, "measure", f, &v); !r) return r;
    if (!doc.contains("explain") || !doc["explain"].is_string())
        return testing::AssertionFailure() << path << ": explain: missing (one or two sentences: why your measurement differs from your prediction)";
    std::istringstream words(doc["explain"].get<std::string>());
    int n = 0;
    for (std::string w; words >> w;) ++n;
    if (n < 5)
        return testing::AssertionFailure() << path << ": explain: " << n << " words; write one or two sentences on why your "
                                              "measurement differs from your prediction (or agrees with it)";
    return testing::AssertionSuccess();
}

/// A run of a scene as `./lab run SCENE --set ... --quiet` makes it, remade by the instructor's grade of a
/// measurement: solver.steps steps of the scene (its JSON text, e.g. kScene_pbd_link from
/// experiment_scenes.h) with the overrides, through whichever code this binary links for each stage,
/// with the run's checks (RunChecks: the warnings its summary prints).
struct SceneRun {
    std::string command;          ///< how the student types it, "./lab run scenes/x.json --set a=b", for messages
    std::vector<Metric> metrics;  ///< the summary's final metrics
    std::string warning;          ///< the first warning of the run (warningHeadline()), "" when it gave none
    std::unique_ptr<Simulation> sim;  ///< the simulation after its last step (its state)
    /// The final value of metric `name`, as the summary prints it.
    /// @throws std::runtime_error when the run reports no such metric
    double metric(const std::string& name) const {
        for (const Metric& m : metrics)
            if (m.name == name) return m.value;
        throw std::runtime_error(command + ": the run reports no metric " + name);
    }
};

/// One quantity of an instructor's experiment that the student predicts and measures: its field in
/// answers.json, the value of the setting the runs vary (a time step in s, a stiffness), and the
/// quantity in words with its unit, for messages.
struct ExperimentField {
    const char* field;  ///< e.g. "link_strain_dt_0_01"
    double setting;     ///< e.g. 0.01 (s)
    const char* what;   ///< e.g. "the strain at rest of the link of pbd_link at dt = 0.01 s, 1"
};

/// Runs a scene as `./lab run` does (SceneRun). `file` is the scene's path as the student types it
/// (mesh files are looked up beside it).
/// @throws std::runtime_error when that run stops (the code under test blew up): the test fails with
///         this one message, "your code's run of ... was unstable at step N ...", and grades nothing
inline SceneRun runScene(const char* sceneText, const std::string& file, const std::vector<std::string>& sets) {
    const Scene scene = parseScene(sceneText, file, sets);
    SceneRun run;
    run.command = "./lab run " + file;
    for (const auto& s : sets) run.command += " --set " + s;
    run.sim = makeSimulation(scene);
    const RunResult r = runSimulation(*run.sim, scene.solver.steps, scene.solver.steps);
    if (r.unstable)
        throw std::runtime_error("your code's run of " + run.command + " (the experiment's expected value comes from it) was " + r.message +
                                 ": the stage's other tests show where");
    run.metrics = run.sim->metrics();
    if (!r.warnings.empty()) run.warning = warningHeadline(r.warnings.front(), scene);
    return run;
}

/// A measurement from a run that warned is no result (its summary says not to trust the numbers):
/// a failure naming the run and its warning, so its measurement earns no points; success otherwise.
/// @param run  the run the measurement came from
inline testing::AssertionResult runGaveAResult(const SceneRun& run) {
    if (run.warning.empty()) return testing::AssertionSuccess();
    return testing::AssertionFailure() << "your code's run of " << run.command << " warned (" << run.warning
                                       << "), so its numbers are no result; the warning names the pass and the exercise to fix";
}

/// Asserts a grade (gradePrediction(), gradeMeasurement()) without quoting its arguments: EXPECT_TRUE
/// prints the asserted expression ("Value of: ..."), which would show the expected value and tolerance.
#define EXPECT_GRADED(result)                                          \
    do {                                                               \
        const ::testing::AssertionResult graded_ = (result);           \
        EXPECT_TRUE(graded_);                                          \
    } while (0)

/// The instructor's grade of a prediction: predict.`field` must lie within `tolerance` of `expected`
/// (computed by the test from first principles). The message names the field and the student's number,
/// never the expected value or the tolerance.
inline testing::AssertionResult gradePrediction(const char* stageDir, const std::string& field, double expected, double tolerance,
                                                const std::string& what) {
    double answer = 0;
    if (auto read = readAnswer(stageDir, "predict", field, &answer); !read) return read;
    if (std::abs(answer - expected) <= tolerance) return testing::AssertionSuccess();
    return testing::AssertionFailure() << answersShownAs(stageDir) << ": predict." << field << " (" << what << "): " << num(answer)
                                       << " is not what the theory gives; redo the derivation the task sheet's \"Experiment\" outlines";
}

/// The instructor's grade of a measurement: measure.`field` must lie within `tolerance` of `rerun`,
/// the same measurement made by the test with the student's code, and that code must reproduce the
/// physics (`physics`, the test's first-principles check of the same code, with `physicsWhy` naming
/// what failed), so a wrong implementation earns no measurement points. No target in the message.
inline testing::AssertionResult gradeMeasurement(const char* stageDir, const std::string& field, double rerun, double tolerance,
                                                 const testing::AssertionResult& physics, const std::string& what) {
    double answer = 0;
    if (auto read = readAnswer(stageDir, "measure", field, &answer); !read) return read;
    if (!physics)
        return testing::AssertionFailure() << answersShownAs(stageDir) << ": measure." << field << " (" << what
                                           << "): your code does not reproduce the physics here, so its measurement earns no points: "
                                           << physics.message();
    if (std::abs(answer - rerun) <= tolerance) return testing::AssertionSuccess();
    return testing::AssertionFailure() << answersShownAs(stageDir) << ": measure." << field << " (" << what << "): " << num(answer)
                                       << " does not agree with the same measurement made here with your code; run the command in its "
                                          "\"how\" again on your final code and copy the number from its output";
}

// ---- Randomised property tests ----------------------------------------------------------------
// Each property test draws its inputs from std::mt19937 with the fixed seeds 1..kPropertySeeds, so a
// run is reproducible and a failure names the seed. The expected behaviour comes from physics
// (equivariance, conservation laws, analytic limits), never from the reference's output.

/// Seeds per property test: 1..kPropertySeeds.
constexpr unsigned kPropertySeeds = 30;

/// Random geometry for one seed: rotations, scales, masses, directions.
class RandomGeometry {
public:
    explicit RandomGeometry(unsigned seed) : rng_(seed) {}
    /// Uniform in [a, b].
    double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng_); }
    /// Log-uniform in [a, b] (a > 0): every decade equally likely.
    double logUniform(double a, double b) { return std::exp(uniform(std::log(a), std::log(b))); }
    /// A length scale in metres, log-uniform in [1e-3, 1e2] (a millimetre to a hundred metres).
    double scale() { return logUniform(1e-3, 1e2); }
    /// +1 or -1 with equal probability.
    double sign() { return uniform(0.0, 1.0) < 0.5 ? -1.0 : 1.0; }
    /// A random unit vector, uniform on the sphere.
    Vec3 unitVector() {
        std::normal_distribution<double> n(0.0, 1.0);
        Vec3 v;
        do v = Vec3(n(rng_), n(rng_), n(rng_));
        while (v.norm() < 1e-6);
        return v.normalized();
    }
    /// A point with coordinates uniform in [-a, a].
    Vec3 point(double a) { return Vec3(uniform(-a, a), uniform(-a, a), uniform(-a, a)); }
    /// A uniformly distributed random rotation (a unit quaternion from four normal samples;
    /// Eigen's Quaterniond::UnitRandom would use std::rand, which the seed does not control).
    Eigen::Matrix3d rotation() {
        std::normal_distribution<double> n(0.0, 1.0);
        Eigen::Quaterniond q;
        do q = Eigen::Quaterniond(n(rng_), n(rng_), n(rng_), n(rng_));
        while (q.norm() < 1e-6);
        return q.normalized().toRotationMatrix();
    }
    /// A unit vector perpendicular to n (n a unit vector).
    Vec3 perpendicularTo(const Vec3& n) {
        Vec3 t;
        do {
            const Vec3 u = unitVector();
            t = u - n * n.dot(u);
        } while (t.norm() < 1e-3);
        return t.normalized();
    }
    std::mt19937& engine() { return rng_; }

private:
    std::mt19937 rng_;
};

/// Runs check(seed) for the seeds 1..kPropertySeeds and reports the first seed that fails (its
/// message first, so the grader's first lines explain the physics), then stops.
template <class Check>
void forEachSeed(Check check) {
    for (unsigned seed = 1; seed <= kPropertySeeds; ++seed) {
        const testing::AssertionResult r = check(seed);
        if (!r) {
            ADD_FAILURE() << r.message() << " [random input of seed " << seed << "; the seeds are 1.." << kPropertySeeds
                          << ", fixed, so the run is reproducible]";
            return;
        }
    }
}

}  // namespace clothlab::testing_util
