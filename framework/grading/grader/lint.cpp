#include "lint.h"

#include <set>

namespace grade {

namespace {

/// Calls a stage file has no use for, and what to say of them.
const std::set<std::string> kProcessCalls = {"exit", "_Exit", "quick_exit", "abort", "terminate", "system", "popen",
                                             "fork", "execl", "execlp", "execle", "execv", "execvp", "execve"};
const std::string kProcess = "report errors by throwing an exception (throw std::invalid_argument(\"...\")); "
                             "a stage file does not end the program or start others";
const std::string kGoogleTest = "a stage file does not use GoogleTest: the graded tests do";

bool identStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool identChar(char c) { return identStart(c) || std::isdigit(static_cast<unsigned char>(c)); }

}  // namespace

std::vector<Finding> lintSource(const std::string& text, const std::string& display) {
    std::vector<Finding> found;
    const auto report = [&](int line, const std::string& what) {
        const std::string where = display + ":" + std::to_string(line);
        for (const auto& f : found)
            if (f.where == where && f.what == what) return;
        found.push_back({where, what});
    };
    const size_t n = text.size();
    const auto at = [&](size_t i) { return i < n ? text[i] : '\0'; };
    int line = 1;
    for (size_t i = 0; i < n;) {
        const char c = text[i];
        if (c == '\n') { ++line; ++i; continue; }
        if (c == '/' && at(i + 1) == '/') { while (i < n && text[i] != '\n') ++i; continue; }
        if (c == '/' && at(i + 1) == '*') {  // a comment, its newlines counted
            for (i += 2; i < n && !(text[i] == '*' && at(i + 1) == '/'); ++i) line += text[i] == '\n';
            i += 2;
            continue;
        }
        if (c == '"' || c == '\'') {  // a literal (no raw strings: this is a lint, not a parser)
            for (++i; i < n && text[i] != c && text[i] != '\n'; ++i) i += text[i] == '\\';
            ++i;
            continue;
        }
        if (!identStart(c)) { ++i; continue; }
        size_t k = i;
        while (k < n && identChar(text[k])) ++k;
        const std::string id = text.substr(i, k - i);
        const bool after_name = i > 0 && (identChar(text[i - 1]) || text[i - 1] == '.');  // 3.0e-5, x.exit
        i = k;
        if (after_name) continue;
        while (k < n && (text[k] == ' ' || text[k] == '\t')) ++k;
        const bool called = at(k) == '(';
        if (id == "main" && called) report(line, "a stage file has no main(): the graded tests bring their own; try your code with ./lab test");
        else if (id.rfind("EXPECT_", 0) == 0 || id.rfind("ASSERT_", 0) == 0) report(line, kGoogleTest);
        else if (kProcessCalls.count(id) && called) report(line, "`" + id + "`: " + kProcess);
        else if (((id == "TEST" || id == "TEST_F") && called) || id == "gtest" || id == "testing") report(line, "`" + id + "`: " + kGoogleTest);
    }
    return found;
}

}  // namespace grade
