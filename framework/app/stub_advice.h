// What a program tells a student who runs a scene that reaches an unfinished task.
#pragma once
#include <algorithm>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

// Set by the build (cmake/stages.cmake, framework/CMakeLists.txt) on the programs' mains: the stages
// that have a reference here (solutions/, or the student copy's reference objects) and the stages this
// build links it for (--reference), each as "05,06".
#ifndef CLOTHLAB_REFERENCE_HAVE
#define CLOTHLAB_REFERENCE_HAVE ""
#endif
#ifndef CLOTHLAB_REFERENCE_USED
#define CLOTHLAB_REFERENCE_USED ""
#endif

namespace clothlab::cli {

inline std::vector<std::string> stageList(const std::string& csv) {
    std::vector<std::string> out;
    std::stringstream in(csv);
    for (std::string s; std::getline(in, s, ',');)
        if (!s.empty()) out.push_back(s);
    return out;
}

/// "not implemented: exercise 4.2 ..." -> advice that works in this copy. Where stage NN has a
/// reference (the instructor's tree, or a student copy with reference objects): finish the task, or
/// rebuild with the reference for NN and the stages this build already takes from it (the exact
/// command); else (a copy released with --no-reference-objects): finish the task, grade, hint.
inline std::string stubAdvice(const std::string& what, const std::string& have = CLOTHLAB_REFERENCE_HAVE,
                              const std::string& used = CLOTHLAB_REFERENCE_USED) {
    std::smatch m;
    const bool numbered = std::regex_search(what, m, std::regex("exercise ([1-9])\\.([0-9]+)"));
    const std::string task = numbered ? m[1].str() + "." + m[2].str() : "N.M";
    const std::string stage = numbered ? "0" + m[1].str() : "NN";
    const std::string finish = "finish task " + task + " in exercises/" + stage + "_*/ (./lab hint " + task +
                               " gives a hint, ./lab grade --stage " + stage + " says what is still missing)";
    const auto haveList = stageList(have);
    if (!numbered || std::find(haveList.begin(), haveList.end(), stage) == haveList.end())
        return "  (" + finish + ")";
    auto refs = stageList(used);
    if (std::find(refs.begin(), refs.end(), stage) == refs.end()) refs.push_back(stage);
    std::sort(refs.begin(), refs.end());
    std::string list;
    for (const auto& r : refs) list += (list.empty() ? "" : ",") + r;
    return "  (" + finish + ", or run stage " + stage + " with its reference: ./lab build --reference " + list + ")";
}

}  // namespace clothlab::cli
