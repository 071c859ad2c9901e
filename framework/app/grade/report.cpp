#include "report.h"

#include <cstdio>
#include <fstream>

namespace grade {

void printTable(const std::vector<StageResult>& stages, bool verbose, int lines) {
    double pts = 0, max = 0;
    std::printf("\n%-6s %-44s %9s %15s\n", "stage", "title", "tests", "points");
    for (const auto& s : stages) {
        std::printf("%-6s %-44s %4d / %-3zu %7.1f / %-5.1f\n", s.stage.c_str(), s.title.c_str(), s.passed(), s.tests.size(),
                    s.points(), s.max_points());
        pts += s.points();
        max += s.max_points();
        if (!verbose) continue;
        if (s.status != "graded") {
            std::string what = s.status;
            for (auto& ch : what) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
            std::printf("    %s (every test 0 points)\n        %s\n", what.c_str(), firstLines(s.problem, 12).c_str());
            continue;
        }
        for (const auto& t : s.tests)
            if (!t.passed) std::printf("    FAIL %s\n        %s\n", t.name.c_str(), firstLines(t.message, lines).c_str());
    }
    std::printf("%-6s %-44s %9s %7.1f / %-5.1f\n\n", "total", "", "", pts, max);
    if (const std::string h = hintsText(stages); !h.empty())
        std::printf("hints taken (task:levels, from ./lab hint; your instructor sees them): %s\n\n", h.c_str());
}

json resultsJson(const std::vector<StageResult>& stages) {
    json j;
    double pts = 0, max = 0;
    j["stages"] = json::array();
    for (const auto& s : stages) {
        json st = {{"stage", s.stage}, {"title", s.title}, {"status", s.status}, {"problem", s.problem},
                   {"points", s.points()}, {"max_points", s.max_points()}, {"passed", s.passed()},
                   {"hints_taken", s.hints}, {"tests", json::array()}};
        for (const auto& t : s.tests)
            st["tests"].push_back({{"name", t.name}, {"passed", t.passed}, {"points", t.points},
                                   {"max_points", t.max_points}, {"message", t.message}});
        j["stages"].push_back(st);
        pts += s.points();
        max += s.max_points();
    }
    j["points"] = pts;
    j["max_points"] = max;
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
        out << "  <testsuite name=\"stage " << s.stage << " " << xmlEscape(s.title) << "\" tests=\"" << s.tests.size()
            << "\" failures=\"" << s.tests.size() - static_cast<size_t>(s.passed()) << "\">\n"
            << "    <properties><property name=\"hints_taken\" value=\"" << xmlEscape(hintsText({s})) << "\"/></properties>\n";
        for (const auto& t : s.tests) {
            out << "    <testcase classname=\"stage" << s.stage << "\" name=\"" << xmlEscape(t.name) << "\">\n"
                << "      <properties><property name=\"points\" value=\"" << t.points << "\"/>"
                << "<property name=\"max_points\" value=\"" << t.max_points << "\"/></properties>\n";
            if (!t.passed)
                out << "      <failure message=\"" << xmlEscape(firstLines(t.message, 1)) << "\">" << xmlEscape(t.message)
                    << "</failure>\n";
            out << "    </testcase>\n";
        }
        out << "  </testsuite>\n";
    }
    out << "</testsuites>\n";
}

json classroomJson(const std::vector<StageResult>& stages) {
    json j = {{"version", 1}, {"status", "pass"}, {"max_score", 0.0}, {"tests", json::array()}};
    double max = 0;
    bool all = true;
    for (const auto& s : stages)
        for (const auto& t : s.tests) {
            max += t.max_points;
            all = all && t.passed;
            j["tests"].push_back({{"name", "stage " + s.stage + ": " + t.name}, {"status", t.passed ? "pass" : "fail"},
                                  {"score", t.points}, {"message", t.passed ? "" : firstLines(t.message, 8, "\n")},
                                  {"test_code", "./lab grade --stage " + s.stage}, {"filename", ""}, {"line_no", 0},
                                  {"execution_time", ""}});
        }
    j["max_score"] = max;
    j["status"] = all ? "pass" : "fail";
    return j;
}

std::string hintsText(const std::vector<StageResult>& stages) {
    std::string t;
    for (const auto& s : stages)
        for (auto it = s.hints.begin(); it != s.hints.end(); ++it)
            t += (t.empty() ? "" : " ") + it.key() + ":" + std::to_string(it->get<int>());
    return t;
}

std::string statusLine(const std::vector<StageResult>& stages) {
    std::string s;
    for (const auto& st : stages)
        if (st.status != "graded") s += (s.empty() ? "" : "; ") + st.stage + " " + st.status;
    return s.empty() ? "ok" : s;
}

}  // namespace grade
