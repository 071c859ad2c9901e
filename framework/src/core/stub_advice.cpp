#include "clothlab/core/stub_advice.h"

#include <algorithm>
#include <regex>
#include <sstream>
#include <vector>

namespace clothlab {
namespace {

std::vector<std::string> stageList(const std::string& csv) {
    std::vector<std::string> out;
    std::stringstream in(csv);
    for (std::string s; std::getline(in, s, ',');)
        if (!s.empty()) out.push_back(s);
    return out;
}

}  // namespace

std::string stubAdvice(const std::string& what, const std::string& have, const std::string& used) {
    std::smatch m;
    const bool numbered = std::regex_search(what, m, std::regex("exercise ([1-9])\\.([0-9]+)"));
    const std::string task = numbered ? m[1].str() + "." + m[2].str() : "N.M";
    const std::string stage = numbered ? "0" + m[1].str() : "NN";
    const std::string finish = "finish task " + task + " in exercises/" + stage + "_*/ (./lab hint " + task +
                               " gives a hint, ./lab grade --stage " + stage + " says what is still missing)";
    const auto haveList = stageList(have);
    if (!numbered || std::find(haveList.begin(), haveList.end(), stage) == haveList.end()) return "  (" + finish + ")";
    auto refs = stageList(used);
    if (std::find(refs.begin(), refs.end(), stage) == refs.end()) refs.push_back(stage);
    std::sort(refs.begin(), refs.end());
    std::string list;
    for (const auto& r : refs) list += (list.empty() ? "" : ",") + r;
    return "  (" + finish + ", or run stage " + stage + " with its reference: ./lab build --reference " + list + ")";
}

}  // namespace clothlab
