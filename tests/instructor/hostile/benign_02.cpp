// BENIGN FIXTURE: the stub with harmless student additions. It scores 0 (every task still
// throws NotImplemented) but a careful screen must ACCEPT it: nothing here is an attack.
//@head
#include <algorithm>
#include <cstdio>
#include <vector>


// Harmless student additions: a global-namespace helper, a constexpr table, a lambda, printf.
int clampIndex(int i, int n) { return std::max(0, std::min(i, n - 1)); }

namespace {
constexpr int kNeighbours[4][2] = {{1, 0}, {0, 1}, {1, 1}, {2, 0}};
}  // namespace
//@each
    const auto count = [](const std::vector<int>& v) { return static_cast<int>(v.size()); };
    std::printf("debug: %d neighbour offsets, clamp %d, %d\n", 4, clampIndex(kNeighbours[3][0], 2), count({1, 2}));
