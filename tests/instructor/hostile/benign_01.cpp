// BENIGN FIXTURE: the stub with harmless student additions. It scores 0 (every task still
// throws NotImplemented) but a careful screen must ACCEPT it: nothing here is an attack.
//@head
#include <cassert>
#include <cmath>
#include <iostream>


// Harmless student additions: a helper with external linkage, one in an anonymous namespace,
// a constant, a debug print and an assert. The tasks are still not done (every test: not implemented).
namespace clothlab {
double squaredDistance(const Vec3& a, const Vec3& b) { return (a - b).squaredNorm(); }
}  // namespace clothlab

namespace {
static const double kTiny = 1e-12;
bool nearlyZero(double x) { return std::abs(x) < kTiny; }
}  // namespace
//@each
    assert(kTiny > 0.0);
    if (nearlyZero(clothlab::squaredDistance(Vec3::Zero(), Vec3::Zero()))) std::cout << "debug: not started yet\n";
