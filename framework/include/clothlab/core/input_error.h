/// @file input_error.h
/// @brief The one error type for bad input (scene files, command-line values).
#pragma once
#include <stdexcept>
#include <string>

namespace clothlab {

/// Bad input. what() reads `<file>: <field>: <reason>`; the CLI prints it after `error: `
/// and exits with a non-zero status.
class InputError : public std::runtime_error {
public:
    /// @param file   the input file (or "command line")
    /// @param field  dotted path of the offending field, e.g. "solver.dt"
    /// @param reason what is wrong, e.g. "must be > 0 (got -1)"
    InputError(const std::string& file, const std::string& field, const std::string& reason)
        : std::runtime_error(file + ": " + field + ": " + reason) {}
};

}  // namespace clothlab
