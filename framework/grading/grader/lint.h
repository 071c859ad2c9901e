// The source lint: friendly messages for what a stage file has no use for (its own main(),
// ending the program instead of throwing, GoogleTest), each with the file, the line and what to do
// instead. It is not a security layer: the submission's code runs only in the confined submission
// process (docs/grading.md, "The trust boundary"); a file the lint misreads costs nothing there.
#pragma once
#include <string>
#include <vector>

namespace grade {

struct Finding {
    std::string where;  ///< "01_hooke/hooke.cpp:12"
    std::string what;   ///< one sentence: what a stage file does not do and what to do instead
};

/// Lints one source file of a stage. `display` is its name in messages ("01_hooke/hooke.cpp").
std::vector<Finding> lintSource(const std::string& text, const std::string& display);

}  // namespace grade
