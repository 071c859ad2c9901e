// What a program tells a student who runs a scene that reaches an unfinished task.
#pragma once
#include <regex>
#include <string>

namespace clothlab::cli {

/// "not implemented: exercise 4.2 ..." -> advice that works in this copy: where the reference is
/// (the instructor's tree) building the stage with it; in the student copy finishing the task.
/// CLOTHLAB_REFERENCE_AVAILABLE is set by the build (framework/CMakeLists.txt).
inline std::string stubAdvice(const std::string& what) {
    std::smatch m;
    const bool numbered = std::regex_search(what, m, std::regex("exercise ([1-9])\\.([0-9]+)"));
    const std::string task = numbered ? m[1].str() + "." + m[2].str() : "N.M";
    const std::string stage = numbered ? "0" + m[1].str() : "NN";
#if CLOTHLAB_REFERENCE_AVAILABLE
    return "  (finish task " + task + ", or run with its reference: ./lab build --reference " + stage + ")";
#else
    return "  (finish task " + task + " in exercises/" + stage + "_*/; ./lab grade --stage " + stage +
           " says what is still missing, ./lab hint " + task + " gives a hint)";
#endif
}

}  // namespace clothlab::cli
