#include "clothlab/study/plot.h"

#include <cstdlib>
#include <fstream>
#include <iostream>

namespace clothlab {

bool gnuplotAvailable() { return std::system("command -v gnuplot >/dev/null 2>&1") == 0; }

bool runGnuplot(const std::string& script_path, const std::string& script) {
    {
        std::ofstream out(script_path);
        if (!out) {
            std::cerr << "note: cannot write " << script_path << ": no plot\n";
            return false;
        }
        out << script;
    }
    if (!gnuplotAvailable()) {
        static bool told = false;  // one note per run, not one per plot
        if (!told)
            std::cerr << "note: gnuplot not found, so no PNG was drawn (install it: apt-get install gnuplot-nox, "
                         "or ./lab setup); the CSV and the gnuplot scripts (*.gp, e.g. " << script_path << ") are written\n";
        told = true;
        return false;
    }
    const std::string log = script_path + ".log";
    if (std::system(("gnuplot '" + script_path + "' >'" + log + "' 2>&1").c_str()) != 0) {
        std::cerr << "note: gnuplot failed on " << script_path << " (see " << log << "); the CSV is written\n";
        return false;
    }
    return true;
}

}  // namespace clothlab
