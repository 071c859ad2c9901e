/// @file not_implemented.h
/// @brief The exception a student stub throws until the exercise is solved.
#pragma once
#include <stdexcept>
#include <string>

namespace clothlab {

/// Thrown by every exercise stub. The framework catches it and prints
/// `not implemented: exercise N.M <name>` instead of crashing.
class NotImplemented : public std::logic_error {
public:
    /// @param task  the task as named in the handout, e.g. "exercise 1.1 hookeForce"
    explicit NotImplemented(const std::string& task) : std::logic_error("not implemented: " + task) {}
};

}  // namespace clothlab
