// What the batched-kernel tests (bending_batched_test.cpp, distance_batched_test.cpp) share: the
// scene they start from, how they crumple it so that every constraint has work to do, and how they
// compare two runs' XPBD multipliers.
#pragma once
#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "clothlab/io/scene_json.h"

namespace clothlab::test {

/// scenes/pbd_hanging.json (a cloth pinned at its two top corners) with `sets` applied.
inline Scene hangingScene(const std::vector<std::string>& sets) {
    return loadScene(std::string(CLOTHLAB_SOURCE_DIR) + "/scenes/pbd_hanging.json", sets);
}

/// Spreads the free particles' inverse masses over three orders of magnitude (pinned ones stay
/// pinned) and moves every position by up to 30 % of the edge length h in each coordinate.
inline void crumple(VectorX& w, Matrix3X& p, double h, std::mt19937& rng) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < w.size(); ++i)
        if (w[i] > 0.0) w[i] *= std::pow(10.0, 1.5 * u(rng));
    for (int i = 0; i < p.cols(); ++i)
        for (int c = 0; c < 3; ++c) p(c, i) += 0.3 * h * u(rng);
}

/// The largest |a_n| and the largest |a_n − b_n| of two runs' multipliers (same length).
inline std::pair<double, double> largestAndDifference(const std::vector<double>& a, const std::vector<double>& b) {
    double largest = 0.0, difference = 0.0;
    for (size_t n = 0; n < a.size(); ++n) {
        largest = std::max(largest, std::fabs(a[n]));
        difference = std::max(difference, std::fabs(b[n] - a[n]));
    }
    return {largest, difference};
}

}  // namespace clothlab::test
