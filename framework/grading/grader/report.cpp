#include "report.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>

namespace grade {

namespace {

/// printf into a string.
template <class... A> std::string format(const char* f, A... a) {
    char b[256];
    std::snprintf(b, sizeof b, f, a...);
    return b;
}
/// " + B bonus" when there are bonus tests, else "".
std::string bonusNote(const Totals& t) { return t.bonus_tests ? format(" + %g bonus", t.bonus) : ""; }
std::string escaped(const std::string& s, const std::string& chars, const std::vector<std::string>& as) {
    std::string r;
    for (char c : s) r += chars.find(c) == std::string::npos ? std::string(1, c) : as[chars.find(c)];
    return r;
}
std::string xml(const std::string& s) {
    std::string r = escaped(s, "&<>\"", {"&amp;", "&lt;", "&gt;", "&quot;"});
    for (char& c : r) c = static_cast<unsigned char>(c) < 32 && c != '\n' && c != '\t' ? ' ' : c;
    return r;
}
std::string csv(const std::string& s) {  // quoted (with "" for ") when it holds a comma, quote or line break
    return s.find_first_of(",\"\n\r") == std::string::npos ? s : "\"" + escaped(s, "\"\n\r", {"\"\"", " ", " "}) + "\"";
}

}  // namespace

void printTable(const std::vector<StageResult>& stages, bool verbose) {
    std::printf("\n%-6s %-44s %9s %15s\n", "stage", "title", "tests", "points");
    for (const auto& s : stages) {
        const Totals t = totals({s});
        std::printf("%-6s %-44s %4d / %-3d %7.1f / %-5.1f%s\n", s.stage.c_str(), s.title.c_str(), t.passed, t.tests, t.points, t.max_points,
                    t.bonus_tests ? format("   + bonus %d / %d tests, %g / %g points", t.bonus_passed, t.bonus_tests, t.bonus, t.max_bonus).c_str() : "");
        if (verbose && s.status != Status::graded) {
            std::string what = statusName(s.status);
            std::transform(what.begin(), what.end(), what.begin(), ::toupper);
            std::printf("    %s (every test 0 points)\n        %s\n", what.c_str(), firstLines(s.problem, 12).c_str());
        }
        for (const auto& r : s.tests)
            if (verbose && s.status == Status::graded && !r.passed)
                std::printf("    %s %s\n        %s\n", r.bonus ? "BONUS NOT EARNED" : "FAIL", r.name.c_str(), firstLines(r.message, 8).c_str());
    }
    const Totals t = totals(stages);
    std::printf("%-6s %-44s %9s %7.1f / %-5.1f%s\n\n", "total", "", "", t.points, t.max_points,
                t.max_bonus > 0 ? format("   + bonus %g / %g points", t.bonus, t.max_bonus).c_str() : "");
}

json resultsJson(const std::vector<StageResult>& stages) {
    json j = {{"stages", json::array()}};
    for (const auto& s : stages) {
        const Totals t = totals({s});
        json st = {{"stage", s.stage}, {"title", s.title}, {"status", statusName(s.status)}, {"problem", s.problem}, {"points", t.points},
                   {"max_points", t.max_points}, {"bonus", t.bonus}, {"passed", t.passed + t.bonus_passed}, {"tests", json::array()}};
        for (const auto& r : s.tests)
            st["tests"].push_back({{"name", r.name}, {"passed", r.passed}, {"points", r.points}, {"max_points", r.max_points}, {"bonus", r.bonus},
                                   {"message", r.message}});
        j["stages"].push_back(st);
    }
    const Totals t = totals(stages);
    j.update({{"points", t.points}, {"max_points", t.max_points}, {"bonus", t.bonus}, {"status", statusLine(stages)}});
    return j;
}

std::vector<StageResult> resultsFromJson(const json& j) {
    std::vector<StageResult> out;
    for (const auto& s : j.at("stages")) {
        out.push_back({s.at("stage"), s.at("title"), statusNamed(s.at("status")), s.at("problem"), {}});
        for (const auto& t : s.at("tests"))
            out.back().tests.push_back({t.at("name"), t.at("passed"), t.at("points"), t.at("max_points"), t.at("message"), t.value("bonus", false)});
    }
    return out;
}

void writeJunit(const fs::path& path, const std::vector<StageResult>& stages, const std::string& prefix) {
    std::ofstream out(path);
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"" << xml(prefix.empty() ? "clothlab" : prefix) << "\">\n";
    for (const auto& s : stages) {
        const Totals t = totals({s});  // a bonus test not earned is skipped, not failed
        out << "  <testsuite name=\"stage " << s.stage << " " << xml(s.title) << "\" tests=\"" << s.tests.size() << "\" failures=\""
            << t.tests - t.passed << "\" skipped=\"" << t.bonus_tests - t.bonus_passed << "\">\n";
        for (const auto& r : s.tests) {
            out << "    <testcase classname=\"stage" << s.stage << "\" name=\"" << xml(r.name) << "\">\n"
                << "      <properties><property name=\"points\" value=\"" << r.points << "\"/><property name=\"max_points\" value=\""
                << r.max_points << "\"/>" << (r.bonus ? "<property name=\"bonus\" value=\"true\"/>" : "") << "</properties>\n";
            if (!r.passed && r.bonus) out << "      <skipped message=\"bonus not earned: " << xml(firstLines(r.message, 1)) << "\"/>\n";
            else if (!r.passed) out << "      <failure message=\"" << xml(firstLines(r.message, 1)) << "\">" << xml(r.message) << "</failure>\n";
            out << "    </testcase>\n";
        }
        out << "  </testsuite>\n";
    }
    out << "</testsuites>\n";
}

json gradescopeJson(const std::vector<StageResult>& stages, double execution_seconds) {
    // A bonus test has max_score 0: Gradescope adds its score as extra credit.
    json tests = json::array();
    for (const auto& s : stages)
        for (const auto& r : s.tests)
            tests.push_back({{"name", "stage " + s.stage + ": " + r.name + (r.bonus ? " (bonus)" : "")}, {"name_format", "text"},
                             {"score", r.points}, {"max_score", r.bonus ? 0.0 : r.max_points}, {"status", r.passed ? "passed" : "failed"},
                             {"output", r.passed ? "" : r.message}, {"visibility", "visible"}});
    const Totals t = totals(stages);
    const std::string status = statusLine(stages);
    return {{"score", t.points + t.bonus},
            {"execution_time", std::max(0L, std::lround(execution_seconds))},
            {"output", format("clothlab: %g / %g points", t.points, t.max_points) + bonusNote(t) +
                           (status == "ok" ? "" : " (" + status + ": every test of such a stage fails with the reason)")},
            {"stdout_visibility", "hidden"},  // the grader's log is for the instructor; students get output and tests
            {"tests", tests}};
}

std::string markdownTable(const std::vector<StageResult>& stages) {
    const auto cell = [](const std::string& s) { return escaped(s, "|\n", {"\\|", " "}); };
    std::string md = "| stage | title | status | tests passed | points |\n|---|---|---|---:|---:|\n", details;
    for (const auto& s : stages) {
        const Totals t = totals({s});
        md += "| " + s.stage + " | " + cell(s.title) + " | " + cell(statusName(s.status)) + format(" | %d / %d", t.passed, t.tests) +
              (t.bonus_tests ? format(" + %d / %d bonus", t.bonus_passed, t.bonus_tests) : "") + format(" | %g / %g", t.points, t.max_points) +
              bonusNote(t) + " |\n";
        std::string failed = s.status != Status::graded ? "```\n" + firstLines(s.problem, 12, "") + "\n```\n" : "";
        for (const auto& r : s.tests)
            if (!r.passed && s.status == Status::graded)
                failed += "- " + std::string(r.bonus ? "bonus not earned: " : "") + "`" + r.name + "`\n  ```\n  " + firstLines(r.message, 4, "  ") + "\n  ```\n";
        const int n = s.status != Status::graded ? static_cast<int>(s.tests.size()) : t.tests - t.passed,
                  unearned = s.status != Status::graded ? 0 : t.bonus_tests - t.bonus_passed;
        if (n + unearned > 0)
            details += "\n<details><summary>stage " + s.stage + ": " + std::to_string(n) + " failed" +
                       (unearned ? ", " + std::to_string(unearned) + " bonus not earned" : "") +
                       (s.status != Status::graded ? " (" + statusName(s.status) + ")" : "") + "</summary>\n\n" + failed + "\n</details>\n";
    }
    const Totals t = totals(stages);
    return md + format("| **total** | | | | **%g / %g", t.points, t.max_points) + bonusNote(t) + "** |\n" + details;
}

std::string statusLine(const std::vector<StageResult>& stages) {
    std::string s;
    for (const auto& st : stages)
        if (st.status != Status::graded) s += (s.empty() ? "" : "; ") + st.stage + " " + statusName(st.status);
    return s.empty() ? "ok" : s;
}

void writeGradebooks(const fs::path& out, const std::vector<std::string>& stages, const std::set<std::string>& only,
                     const fs::path& points_dir, const std::vector<GradebookRow>& rows) {
    const auto points = [](const GradebookRow& r, const std::string& stage) {
        const auto s = std::find_if(r.stages.begin(), r.stages.end(), [&](const StageResult& x) { return x.stage == stage; });
        return s == r.stages.end() ? 0.0 : totals({*s}).points;
    };
    std::string book = "student", moodle = "Identifier", canvas = "Student,ID,SIS User ID,Section", possible = "\nPoints Possible,,,";
    std::vector<std::string> items;  // the import formats' columns (--stage: just those, so an import overwrites no other stage with 0)
    for (const auto& st : stages) {
        book += "," + st;
        if (!only.empty() && !only.count(st)) continue;
        const std::string name = csv("clothlab " + st + " " + loadPoints(points_dir, st)["title"].get<std::string>());
        items.push_back(st), moodle += "," + name, canvas += "," + name, possible += format(",%g", totals({pointsStage(points_dir, st)}).max_points);
    }
    book += ",total,max,status,bonus\n", moodle += "\n", canvas += possible + "\n";
    for (const auto& r : rows) {
        const Totals t = totals(r.stages);
        book += csv(r.student), moodle += csv(r.student), canvas += csv(r.student) + ",," + csv(r.student) + ",";
        for (const auto& st : stages) book += format(",%g", points(r, st));
        for (const auto& st : items) moodle += format(",%g", points(r, st)), canvas += format(",%g", points(r, st));
        book += format(",%g,%g,", t.points, t.max_points) + csv(r.status) + format(",%g\n", t.bonus), moodle += "\n", canvas += "\n";
    }
    writeFile(out / "gradebook.csv", book);
    writeFile(out / "moodle.csv", moodle);
    writeFile(out / "canvas.csv", canvas);
}

}  // namespace grade
