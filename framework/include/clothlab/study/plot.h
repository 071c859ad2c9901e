/// @file plot.h
/// @brief Plots through gnuplot (Debian package gnuplot-nox), run with a generated script.
#pragma once
#include <string>

namespace clothlab {

/// True if a `gnuplot` program is on the PATH.
bool gnuplotAvailable();

/// Runs gnuplot on `script`, saved as `script_path` beside the data it reads.
/// @param script_path  where to save the script (e.g. out/study/stability.gp)
/// @param script       the gnuplot commands
/// @return             true if gnuplot ran and exited with status 0; otherwise false, with a one-line
///                     note on stderr (gnuplot missing: "install gnuplot-nox", once per run; the script
///                     is written all the same, so `gnuplot FILE.gp` draws the plot later)
bool runGnuplot(const std::string& script_path, const std::string& script);

}  // namespace clothlab
