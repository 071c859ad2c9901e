// clothlab-grade: runs graded GoogleTest binaries one test at a time (a crash or a hang costs
// one test, not the stage), applies the points in tests/NN_name.points.json, and prints a
// table per stage, JSON and JUnit XML. `expect` mode checks the test suite itself: the graded
// tests must pass on solutions/, fail on the stubs with "not implemented", and catch mistakes.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

struct TestResult {
    std::string name;     // Suite.Test
    bool passed = false;
    double points = 0, max_points = 0;
    std::string message;  // why it failed
};

struct StageResult {
    std::string stage, title, exe;
    std::string broken;  // compiler errors when the stage did not compile
    std::vector<TestResult> tests;
    double points() const { double s = 0; for (auto& t : tests) s += t.points; return s; }
    double max_points() const { double s = 0; for (auto& t : tests) s += t.max_points; return s; }
    int passed() const { int n = 0; for (auto& t : tests) n += t.passed; return n; }
};

[[noreturn]] void die(const std::string& msg) {
    std::cerr << "error: " << msg << "\n";
    std::exit(1);
}

std::string quote(const std::string& s) {
    std::string r = "'";
    for (char c : s) r += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return r + "'";
}

std::string readFile(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

/// Runs a shell command, returns its wait status; output goes to `log`.
int runCommand(const std::string& cmd, const fs::path& log) {
    return std::system((cmd + " >" + quote(log.string()) + " 2>&1").c_str());
}

std::vector<std::string> listTests(const std::string& exe, const fs::path& tmp) {
    const fs::path log = tmp / "list.txt";
    const int status = runCommand(quote(exe) + " --gtest_list_tests", log);
    if (status != 0) die(exe + ": (binary): cannot list its tests (missing or not a GoogleTest binary)");
    std::vector<std::string> names;
    std::istringstream in(readFile(log));
    std::string line, suite;
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        const auto hash = line.find("  #");
        if (hash != std::string::npos) line = line.substr(0, hash);
        if (line[0] != ' ') suite = line;  // "Suite."
        else names.push_back(suite + line.substr(line.find_first_not_of(' ')));
    }
    return names;
}

/// GoogleTest starts a failure with "path/to/file.cpp:123" or "unknown file": keep only "file.cpp:123: ".
std::string tidyFailure(const std::string& text) {
    const auto nl = text.find('\n');
    if (nl == std::string::npos) return text;
    const std::string first = text.substr(0, nl), rest = text.substr(nl + 1);
    if (first == "unknown file") return rest;
    if (first.find(".cpp:") != std::string::npos) return fs::path(first).filename().string() + ": " + rest;
    return text;
}

/// Runs one test in its own process with a time limit.
TestResult runOne(const std::string& exe, const std::string& name, int timeout_s, const fs::path& tmp) {
    TestResult r;
    r.name = name;
    const fs::path out = tmp / "one.json", log = tmp / "one.log";
    fs::remove(out);
    const int status = runCommand("timeout -k 5 " + std::to_string(timeout_s) + " " + quote(exe) +
                                      " --gtest_filter=" + quote(name) + " --gtest_output=json:" + quote(out.string()),
                                  log);
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    if (code == 124 || code == 137) {
        r.message = "timed out after " + std::to_string(timeout_s) + " s (endless loop?)";
        return r;
    }
    json j = json::parse(readFile(out), nullptr, false);
    if (j.is_discarded() || !j.contains("testsuites")) {
        std::string tail = readFile(log);
        if (tail.size() > 400) tail = tail.substr(tail.size() - 400);
        r.message = "crashed (exit status " + std::to_string(code) + ")" + (tail.empty() ? "" : ":\n" + tail);
        return r;
    }
    for (const auto& suite : j["testsuites"])
        for (const auto& t : suite["testsuite"]) {
            if (t.contains("failures")) {
                for (const auto& f : t["failures"]) r.message += tidyFailure(f.value("failure", "")) + "\n";
                return r;
            }
            r.passed = code == 0;
        }
    if (!r.passed && r.message.empty()) r.message = "test did not run";
    return r;
}

json loadPoints(const fs::path& file) {
    if (!fs::exists(file)) die(file.string() + ": (file): the points file is missing");
    json j = json::parse(readFile(file), nullptr, false);
    if (j.is_discarded() || !j.is_object()) die(file.string() + ": (JSON syntax): not a JSON object");
    if (!j.contains("title") || !j["title"].is_string()) die(file.string() + ": title: missing or not a string");
    if (!j.contains("tests") || !j["tests"].is_object()) die(file.string() + ": tests: missing or not an object");
    for (auto it = j["tests"].begin(); it != j["tests"].end(); ++it)
        if (!it->is_number() || it->get<double>() <= 0) die(file.string() + ": tests." + it.key() + ": points must be a number > 0");
    return j;
}

/// The points file of stage NN in points_dir (NN_name.points.json).
fs::path pointsFile(const std::string& stage, const fs::path& points_dir) {
    for (const auto& e : fs::directory_iterator(points_dir)) {
        const std::string name = e.path().filename().string();
        if (name.rfind(stage + "_", 0) == 0 && name.size() > 12 && name.substr(name.size() - 12) == ".points.json")
            return e.path();
    }
    die(points_dir.string() + ": (folder): no " + stage + "_*.points.json");
}

/// spec "NN=file": stage NN did not compile; every test fails with the compiler's message from file.
StageResult brokenStage(const std::string& spec, const fs::path& points_dir) {
    const auto eq = spec.find('=');
    if (eq == std::string::npos) die("--broken expects NN=LOGFILE (got " + spec + ")");
    StageResult s;
    s.stage = spec.substr(0, eq);
    const json points = loadPoints(pointsFile(s.stage, points_dir));
    s.title = points["title"];
    s.broken = readFile(spec.substr(eq + 1));
    const std::string why = "the submission does not compile:\n" + s.broken;
    for (auto it = points["tests"].begin(); it != points["tests"].end(); ++it)
        s.tests.push_back({it.key(), false, 0.0, it->get<double>(), why});
    return s;
}

/// stage spec "NN=path/to/exe": runs all tests, applies points.
StageResult gradeStage(const std::string& spec, const fs::path& points_dir, int timeout_s, const fs::path& tmp) {
    const auto eq = spec.find('=');
    if (eq == std::string::npos) die("--stage expects NN=EXECUTABLE (got " + spec + ")");
    StageResult s;
    s.stage = spec.substr(0, eq);
    s.exe = spec.substr(eq + 1);
    const fs::path points_file = pointsFile(s.stage, points_dir);
    const json points = loadPoints(points_file);
    s.title = points["title"];
    const auto names = listTests(s.exe, tmp);
    for (const auto& n : names)
        if (!points["tests"].contains(n)) die(points_file.string() + ": tests." + n + ": the graded test has no points");
    for (auto it = points["tests"].begin(); it != points["tests"].end(); ++it)
        if (std::find(names.begin(), names.end(), it.key()) == names.end())
            die(points_file.string() + ": tests." + it.key() + ": no such test in " + s.exe);
    for (const auto& n : names) {
        TestResult r = runOne(s.exe, n, timeout_s, tmp);
        r.max_points = points["tests"][n].get<double>();
        r.points = r.passed ? r.max_points : 0.0;
        s.tests.push_back(std::move(r));
    }
    return s;
}

std::string firstLines(const std::string& text, int n) {
    std::istringstream in(text);
    std::string line, out;
    for (int i = 0; i < n && std::getline(in, line);) {
        if (line.empty()) continue;
        out += (i ? "\n        " : "") + line;
        ++i;
    }
    return out;
}

void printTable(const std::vector<StageResult>& stages, bool verbose) {
    double pts = 0, max = 0;
    std::printf("\n%-6s %-44s %9s %15s\n", "stage", "title", "tests", "points");
    for (const auto& s : stages) {
        std::printf("%-6s %-44s %4d / %-3zu %7.1f / %-5.1f\n", s.stage.c_str(), s.title.c_str(), s.passed(), s.tests.size(),
                    s.points(), s.max_points());
        pts += s.points();
        max += s.max_points();
        if (verbose && !s.broken.empty())
            std::printf("    DOES NOT COMPILE (every test 0 points)\n        %s\n", firstLines(s.broken, 4).c_str());
        else if (verbose)
            for (const auto& t : s.tests)
                if (!t.passed) std::printf("    FAIL %s\n        %s\n", t.name.c_str(), firstLines(t.message, 4).c_str());
    }
    std::printf("%-6s %-44s %9s %7.1f / %-5.1f\n\n", "total", "", "", pts, max);
}

std::string xmlEscape(const std::string& s) {
    std::string r;
    for (char c : s) {
        switch (c) {
            case '&': r += "&amp;"; break;
            case '<': r += "&lt;"; break;
            case '>': r += "&gt;"; break;
            case '"': r += "&quot;"; break;
            default: r += (static_cast<unsigned char>(c) < 32 && c != '\n' && c != '\t') ? ' ' : c;
        }
    }
    return r;
}

void writeJson(const std::string& path, const std::vector<StageResult>& stages) {
    json j;
    double pts = 0, max = 0;
    j["stages"] = json::array();
    for (const auto& s : stages) {
        json st = {{"stage", s.stage}, {"title", s.title}, {"points", s.points()}, {"max_points", s.max_points()},
                   {"passed", s.passed()}, {"tests", json::array()}};
        for (const auto& t : s.tests)
            st["tests"].push_back({{"name", t.name}, {"passed", t.passed}, {"points", t.points},
                                   {"max_points", t.max_points}, {"message", t.message}});
        j["stages"].push_back(st);
        pts += s.points();
        max += s.max_points();
    }
    j["points"] = pts;
    j["max_points"] = max;
    std::ofstream(path) << j.dump(2) << "\n";
}

void writeJunit(const std::string& path, const std::vector<StageResult>& stages) {
    std::ofstream out(path);
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"clothlab\">\n";
    for (const auto& s : stages) {
        out << "  <testsuite name=\"stage " << s.stage << " " << xmlEscape(s.title) << "\" tests=\"" << s.tests.size()
            << "\" failures=\"" << s.tests.size() - static_cast<size_t>(s.passed()) << "\">\n";
        for (const auto& t : s.tests) {
            out << "    <testcase classname=\"stage" << s.stage << "\" name=\"" << xmlEscape(t.name) << "\">\n"
                << "      <properties><property name=\"points\" value=\"" << t.points << "\"/>"
                << "<property name=\"max_points\" value=\"" << t.max_points << "\"/></properties>\n";
            if (!t.passed)
                out << "      <failure message=\"" << xmlEscape(firstLines(t.message, 1)) << "\">"
                    << xmlEscape(t.message) << "</failure>\n";
            out << "    </testcase>\n";
        }
        out << "  </testsuite>\n";
    }
    out << "</testsuites>\n";
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"clothlab-grade — per-stage points from the graded tests"};
    std::vector<std::string> stages, broken;
    std::string points_dir = "tests", json_out, junit_out, expect, message, mistake, why;
    int timeout_s = 60;
    bool quiet = false;
    app.add_option("--stage", stages, "NN=EXECUTABLE, one per stage to grade");
    app.add_option("--broken", broken, "NN=LOGFILE: stage NN did not compile (0 points, the log as message)");
    app.add_option("--points-dir", points_dir, "Folder with NN_name.points.json")->check(CLI::ExistingDirectory);
    app.add_option("--json", json_out, "Write the results as JSON");
    app.add_option("--junit", junit_out, "Write the results as JUnit XML");
    app.add_option("--timeout", timeout_s, "Seconds per test")->check(CLI::PositiveNumber);
    app.add_option("--expect", expect, "Self-check of the test suite: all-pass, all-fail or some-fail")
        ->check(CLI::IsMember({"all-pass", "all-fail", "some-fail"}));
    app.add_option("--message", message, "With --expect all-fail: every failure must contain this text");
    app.add_option("--mistake", mistake, "With --expect some-fail: the name of the mistake the stage was built with");
    app.add_option("--why", why, "With --expect some-fail: what the mistake does wrong (printed with the verdict)");
    app.add_flag("--quiet", quiet, "No per-test failure lines");
    CLI11_PARSE(app, argc, argv);

    const fs::path tmp = fs::temp_directory_path() / ("clothlab-grade-" + std::to_string(::getpid()));
    fs::create_directories(tmp);
    std::vector<StageResult> results;
    for (const auto& spec : stages) {
        std::fprintf(stderr, "grading stage %s ...\n", spec.substr(0, spec.find('=')).c_str());
        results.push_back(gradeStage(spec, points_dir, timeout_s, tmp));
    }
    for (const auto& spec : broken) results.push_back(brokenStage(spec, points_dir));
    std::sort(results.begin(), results.end(), [](const StageResult& a, const StageResult& b) { return a.stage < b.stage; });
    if (results.empty()) die("nothing to grade: give --stage NN=EXECUTABLE (or --broken)");
    fs::remove_all(tmp);
    printTable(results, !quiet);
    if (!json_out.empty()) writeJson(json_out, results), std::printf("wrote %s\n", json_out.c_str());
    if (!junit_out.empty()) writeJunit(junit_out, results), std::printf("wrote %s\n", junit_out.c_str());
    if (expect.empty()) return 0;

    // Self-check mode: say what does not hold and exit non-zero.
    int bad = 0;
    for (const auto& s : results)
        for (const auto& t : s.tests) {
            if (expect == "all-pass" && !t.passed) ++bad, std::printf("expected to pass: %s\n", t.name.c_str());
            if (expect == "all-fail" && t.passed) ++bad, std::printf("passes against the stub (a test that cannot fail?): %s\n", t.name.c_str());
            if (expect == "all-fail" && !t.passed && t.message.find(message) == std::string::npos)
                ++bad, std::printf("fails without \"%s\" (crash or wrong message?): %s\n", message.c_str(), t.name.c_str());
        }
    if (expect == "some-fail") {
        // A mistake is caught when at least one graded test fails; say which one, and what the mistake is.
        const std::string what = (mistake.empty() ? "the mistake" : mistake) + (why.empty() ? "" : " — " + why);
        const TestResult* first = nullptr;
        for (const auto& s : results)
            for (const auto& t : s.tests)
                if (!first && !t.passed) first = &t;
        if (first) std::printf("caught: %s (by %s)\n", what.c_str(), first->name.c_str());
        else ++bad, std::printf("NOT caught: %s (no graded test fails)\n", what.c_str());
    }
    std::printf("self-check (%s): %s\n", expect.c_str(), bad == 0 ? "holds" : "DOES NOT HOLD");
    return bad == 0 ? 0 : 1;
}
