#include "clothlab/core/stub_advice.h"

#include <algorithm>
#include <cctype>
#include <utility>
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

/// The first "exercise N.M" in `what` (N a digit 1-9, M digits) as {N, M}; {"", ""} if there is none.
std::pair<std::string, std::string> exerciseNumber(const std::string& what) {
    const std::string key = "exercise ";
    for (size_t at = what.find(key); at != std::string::npos; at = what.find(key, at + 1)) {
        const size_t n = at + key.size();
        if (n + 2 >= what.size() || what[n] < '1' || what[n] > '9' || what[n + 1] != '.') continue;
        size_t end = n + 2;
        while (end < what.size() && std::isdigit(static_cast<unsigned char>(what[end]))) ++end;
        if (end > n + 2) return {what.substr(n, 1), what.substr(n + 2, end - n - 2)};
    }
    return {"", ""};
}

}  // namespace

std::string stubAdvice(const std::string& what, const std::string& have, const std::string& used) {
    const auto [n, m] = exerciseNumber(what);
    const bool numbered = !n.empty();
    const std::string task = numbered ? n + "." + m : "N.M";
    const std::string stage = numbered ? "0" + n : "NN";
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
