// BENIGN FIXTURE: the stub with harmless student additions. It scores 0 (every task still
// throws NotImplemented) but a careful screen must ACCEPT it: nothing here is an attack.
//@head
#include <cassert>
#include <iostream>
#include <limits>


// Harmless student additions: a static const, std::numeric_limits, an assert, std::cerr.
namespace {
static const double kEpsilon = std::numeric_limits<double>::epsilon();
double safeInverse(double x) { return std::abs(x) > kEpsilon ? 1.0 / x : 0.0; }
}  // namespace
//@each
    assert(safeInverse(2.0) == 0.5);
    std::cerr << "debug: epsilon " << kEpsilon << "\n";
