/// @file input_error.h
/// @brief The one error type for bad input (scene files, command-line values).
#pragma once
#include <stdexcept>
#include <string>

namespace clothlab {

/// Bad input. what() reads `<file>: <field>: <reason>` on one line (a control character that came
/// from the input, e.g. a newline in a key or value, is written as a backslash, `x` and two hex
/// digits); the CLI prints it after `error: ` and exits with a non-zero status.
class InputError : public std::runtime_error {
public:
    /// @param file   the input file (or "command line")
    /// @param field  dotted path of the offending field, e.g. "solver.dt"
    /// @param reason what is wrong, e.g. "must be > 0 (got -1)"
    InputError(const std::string& file, const std::string& field, const std::string& reason)
        : std::runtime_error(oneLine(file + ": " + field + ": " + reason)) {}

private:
    /// `text` with every byte below 0x20 and 0x7f written as a backslash, `x` and two hex digits.
    static std::string oneLine(const std::string& text) {
        static const char* hex = "0123456789abcdef";
        std::string r;
        for (const char c : text) {
            const auto u = static_cast<unsigned char>(c);
            if (u < 0x20 || u == 0x7f) r += std::string("\\x") + hex[u >> 4] + hex[u & 15];
            else r += c;
        }
        return r;
    }
};

}  // namespace clothlab
