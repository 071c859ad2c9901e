// BENIGN FIXTURE: the stub with harmless student additions. It scores 0 (every task still
// throws NotImplemented) but a careful screen must ACCEPT it: nothing here is an attack.
//@head
#include <array>
#include <cstdio>
#include <vector>


// Harmless student additions: a constexpr table, a helper, printf, std::clamp.
namespace {
constexpr std::array<double, 3> kWeights{0.25, 0.5, 0.25};
double clamp01(double x) { return std::clamp(x, 0.0, 1.0); }
}  // namespace

double sumOfWeights() {
    double s = 0.0;
    for (double w : kWeights) s += w;
    return s;
}
//@each
    std::printf("debug: weights %g, clamp %g\n", sumOfWeights(), clamp01(1.5));
