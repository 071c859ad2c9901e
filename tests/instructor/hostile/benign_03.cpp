// BENIGN FIXTURE: the stub with harmless student additions. It scores 0 (every task still
// throws NotImplemented) but a careful screen must ACCEPT it: nothing here is an attack.
//@head
#include <array>
#include <cstdio>
#include <numeric>


// Harmless student additions: std::array, a constexpr function, a helper in namespace clothlab.
namespace clothlab {
double meanOf(const std::array<double, 3>& a) { return std::accumulate(a.begin(), a.end(), 0.0) / 3.0; }
}  // namespace clothlab

namespace {
constexpr double square(double x) { return x * x; }
}  // namespace
//@each
    static_assert(square(2.0) == 4.0, "constexpr works");
    std::fprintf(stderr, "debug: mean %g\n", clothlab::meanOf({1.0, 2.0, 3.0}));
