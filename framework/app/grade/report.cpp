#include "report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

namespace grade {

namespace {
/// " + B bonus" when the stages have bonus tests, else "".
std::string bonusNote(double earned, bool any) {
    char b[64];
    std::snprintf(b, sizeof b, " + %g bonus", earned);
    return any ? b : "";
}
bool hasBonus(const StageResult& s) {
    return std::any_of(s.tests.begin(), s.tests.end(), [](const TestResult& t) { return t.bonus; });
}
/// Tests passed of the required (bonus = false) or the bonus tests (true), and how many there are.
std::pair<int, int> counted(const StageResult& s, bool bonus) {
    int passed = 0, all = 0;
    for (const auto& t : s.tests)
        if (t.bonus == bonus) ++all, passed += t.passed ? 1 : 0;
    return {passed, all};
}
double maxBonus(const StageResult& s) {
    double m = 0;
    for (const auto& t : s.tests) m += t.bonus ? t.max_points : 0.0;
    return m;
}
/// "   + bonus 0 / 5 tests, 0 / 8 points" for a stage with bonus tests (counted apart), else "".
std::string bonusColumns(const StageResult& s) {
    if (!hasBonus(s)) return "";
    const auto [passed, all] = counted(s, true);
    char b[96];
    std::snprintf(b, sizeof b, "   + bonus %d / %d tests, %g / %g points", passed, all, s.bonus(), maxBonus(s));
    return b;
}
}  // namespace

void printTable(const std::vector<StageResult>& stages, bool verbose, int lines) {
    double pts = 0, max = 0, bonus = 0, max_bonus = 0;
    std::printf("\n%-6s %-44s %9s %15s\n", "stage", "title", "tests", "points");
    for (const auto& s : stages) {
        const auto [passed, all] = counted(s, false);
        std::printf("%-6s %-44s %4d / %-3d %7.1f / %-5.1f%s\n", s.stage.c_str(), s.title.c_str(), passed, all, s.points(),
                    s.max_points(), bonusColumns(s).c_str());
        pts += s.points();
        max += s.max_points();
        bonus += s.bonus();
        max_bonus += maxBonus(s);
        if (!verbose) continue;
        if (s.status != "graded") {
            std::string what = s.status;
            for (auto& ch : what) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
            std::printf("    %s (every test 0 points)\n        %s\n", what.c_str(), firstLines(s.problem, 12).c_str());
            continue;
        }
        for (const auto& t : s.tests)
            if (!t.passed)
                std::printf("    %s %s\n        %s\n", t.bonus ? "BONUS NOT EARNED" : "FAIL", t.name.c_str(),
                            firstLines(t.message, lines).c_str());
    }
    char b[96] = "";
    if (max_bonus > 0) std::snprintf(b, sizeof b, "   + bonus %g / %g points", bonus, max_bonus);
    std::printf("%-6s %-44s %9s %7.1f / %-5.1f%s\n\n", "total", "", "", pts, max, b);
}

json resultsJson(const std::vector<StageResult>& stages) {
    json j;
    double pts = 0, max = 0, bonus = 0;
    j["stages"] = json::array();
    for (const auto& s : stages) {
        json st = {{"stage", s.stage}, {"title", s.title}, {"status", s.status}, {"problem", s.problem},
                   {"points", s.points()}, {"max_points", s.max_points()}, {"bonus", s.bonus()}, {"passed", s.passed()},
                   {"tests", json::array()}};
        for (const auto& t : s.tests)
            st["tests"].push_back({{"name", t.name}, {"passed", t.passed}, {"points", t.points},
                                   {"max_points", t.max_points}, {"bonus", t.bonus}, {"message", t.message}});
        j["stages"].push_back(st);
        pts += s.points();
        max += s.max_points();
        bonus += s.bonus();
    }
    j["points"] = pts;
    j["max_points"] = max;
    j["bonus"] = bonus;
    j["status"] = statusLine(stages);
    return j;
}

namespace {
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
}  // namespace

void writeJunit(const fs::path& path, const std::vector<StageResult>& stages, const std::string& prefix) {
    std::ofstream out(path);
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"" << xmlEscape(prefix.empty() ? "clothlab" : prefix) << "\">\n";
    for (const auto& s : stages) {
        // a bonus test not earned is skipped, not failed
        const auto count = [&](bool bonus) {
            return std::count_if(s.tests.begin(), s.tests.end(), [&](const TestResult& t) { return !t.passed && t.bonus == bonus; });
        };
        out << "  <testsuite name=\"stage " << s.stage << " " << xmlEscape(s.title) << "\" tests=\"" << s.tests.size()
            << "\" failures=\"" << count(false) << "\" skipped=\"" << count(true) << "\">\n";
        for (const auto& t : s.tests) {
            out << "    <testcase classname=\"stage" << s.stage << "\" name=\"" << xmlEscape(t.name) << "\">\n"
                << "      <properties><property name=\"points\" value=\"" << t.points << "\"/>"
                << "<property name=\"max_points\" value=\"" << t.max_points << "\"/>"
                << (t.bonus ? "<property name=\"bonus\" value=\"true\"/>" : "") << "</properties>\n";
            if (!t.passed && t.bonus)
                out << "      <skipped message=\"bonus not earned: " << xmlEscape(firstLines(t.message, 1)) << "\"/>\n";
            else if (!t.passed)
                out << "      <failure message=\"" << xmlEscape(firstLines(t.message, 1)) << "\">" << xmlEscape(t.message)
                    << "</failure>\n";
            out << "    </testcase>\n";
        }
        out << "  </testsuite>\n";
    }
    out << "</testsuites>\n";
}

json gradescopeJson(const std::vector<StageResult>& stages, double execution_seconds) {
    // Field names and values as Gradescope's autograder specification names them (see report.h).
    // A bonus test has max_score 0: Gradescope adds its score as extra credit.
    json j;
    double score = 0, max = 0, bonus = 0;
    bool any_bonus = false;
    json tests = json::array();
    for (const auto& s : stages)
        for (const auto& t : s.tests) {
            score += t.points;
            if (t.bonus) bonus += t.points, any_bonus = true;
            max += t.bonus ? 0.0 : t.max_points;
            tests.push_back({{"name", "stage " + s.stage + ": " + t.name + (t.bonus ? " (bonus)" : "")},
                             {"name_format", "text"}, {"score", t.points}, {"max_score", t.bonus ? 0.0 : t.max_points},
                             {"status", t.passed ? "passed" : "failed"},
                             {"output", t.passed ? "" : t.message}, {"visibility", "visible"}});
        }
    char total[128];
    std::snprintf(total, sizeof total, "clothlab: %g / %g points", score - bonus, max);
    std::string output = total + bonusNote(bonus, any_bonus);
    const std::string status = statusLine(stages);
    if (status != "ok") output += " (" + status + ": every test of such a stage fails with the reason)";
    j["score"] = score;
    j["execution_time"] = std::max(0L, std::lround(execution_seconds));
    j["output"] = output;
    j["stdout_visibility"] = "hidden";  // the grader's log is for the instructor; students get output and tests
    j["tests"] = tests;
    return j;
}

namespace {
/// Text for a Markdown table cell: no line breaks, | escaped.
std::string mdCell(const std::string& s) {
    std::string r;
    for (char c : s) r += c == '|' ? std::string("\\|") : c == '\n' ? std::string(" ") : std::string(1, c);
    return r;
}
}  // namespace

std::string markdownTable(const std::vector<StageResult>& stages) {
    std::string md = "| stage | title | status | tests passed | points |\n|---|---|---|---:|---:|\n";
    double pts = 0, max = 0, bonus = 0;
    bool any_bonus = false;
    char b[128];
    for (const auto& s : stages) {
        const auto [passed, all] = counted(s, false);
        const auto [bonus_passed, bonus_all] = counted(s, true);
        const std::string bonus_tests = bonus_all ? " + " + std::to_string(bonus_passed) + " / " + std::to_string(bonus_all) + " bonus" : "";
        std::snprintf(b, sizeof b, " | %d / %d%s | %g / %g%s |\n", passed, all, bonus_tests.c_str(), s.points(), s.max_points(),
                      bonusNote(s.bonus(), hasBonus(s)).c_str());
        md += "| " + s.stage + " | " + mdCell(s.title) + " | " + mdCell(s.status) + b;
        pts += s.points();
        max += s.max_points();
        bonus += s.bonus();
        any_bonus = any_bonus || hasBonus(s);
    }
    std::snprintf(b, sizeof b, "| **total** | | | | **%g / %g%s** |\n", pts, max, bonusNote(bonus, any_bonus).c_str());
    md += b;
    for (const auto& s : stages) {
        std::string failed;
        int n = 0, unearned = 0;
        if (s.status != "graded") failed = "```\n" + firstLines(s.problem, 12, "") + "\n```\n", n = static_cast<int>(s.tests.size());
        else
            for (const auto& t : s.tests)
                if (!t.passed) {
                    failed += "- " + std::string(t.bonus ? "bonus not earned: " : "") + "`" + t.name + "`\n  ```\n  " +
                              firstLines(t.message, 4, "  ") + "\n  ```\n";
                    t.bonus ? ++unearned : ++n;
                }
        if (n + unearned == 0) continue;
        md += "\n<details><summary>stage " + s.stage + ": " + std::to_string(n) + " failed" +
              (unearned ? ", " + std::to_string(unearned) + " bonus not earned" : "") +
              (s.status != "graded" ? " (" + s.status + ")" : "") + "</summary>\n\n" + failed + "\n</details>\n";
    }
    return md;
}

std::string csvField(const std::string& s) {
    if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
    std::string r = "\"";
    for (char c : s) r += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' || c == '\r' ? ' ' : c);
    return r + "\"";
}

std::string csvNumber(double x) {
    char b[32];
    std::snprintf(b, sizeof b, "%g", x);
    return b;
}

double stagePoints(const std::vector<StageResult>& stages, const std::string& stage) {
    for (const auto& s : stages)
        if (s.stage == stage) return s.points();
    return 0;
}

std::string moodleCsv(const std::vector<GradeItem>& items, const std::vector<GradebookRow>& rows) {
    std::string csv = "Identifier";
    for (const auto& it : items) csv += "," + csvField(it.name);
    csv += "\n";
    for (const auto& r : rows) {
        csv += csvField(r.student);
        for (const auto& it : items) csv += "," + csvNumber(stagePoints(r.stages, it.stage));
        csv += "\n";
    }
    return csv;
}

std::string canvasCsv(const std::vector<GradeItem>& items, const std::vector<GradebookRow>& rows) {
    std::string csv = "Student,ID,SIS User ID,Section";
    for (const auto& it : items) csv += "," + csvField(it.name);
    csv += "\nPoints Possible,,,";
    for (const auto& it : items) csv += "," + csvNumber(it.max_points);
    csv += "\n";
    for (const auto& r : rows) {
        csv += csvField(r.student) + ",," + csvField(r.student) + ",";
        for (const auto& it : items) csv += "," + csvNumber(stagePoints(r.stages, it.stage));
        csv += "\n";
    }
    return csv;
}

std::string statusLine(const std::vector<StageResult>& stages) {
    std::string s;
    for (const auto& st : stages)
        if (st.status != "graded") s += (s.empty() ? "" : "; ") + st.stage + " " + st.status;
    return s.empty() ? "ok" : s;
}

}  // namespace grade
