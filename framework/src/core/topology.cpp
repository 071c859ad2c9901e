#include "clothlab/core/topology.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <utility>

namespace clothlab {

std::vector<Eigen::Vector2i> uniqueEdges(const std::vector<Eigen::Vector3i>& triangles) {
    std::vector<std::pair<int, int>> e;
    e.reserve(3 * triangles.size());
    for (const auto& t : triangles)
        for (int k = 0; k < 3; ++k) e.push_back(std::minmax(t[k], t[(k + 1) % 3]));
    std::sort(e.begin(), e.end());
    e.erase(std::unique(e.begin(), e.end()), e.end());
    std::vector<Eigen::Vector2i> out;
    out.reserve(e.size());
    for (const auto& [a, b] : e) out.emplace_back(a, b);
    return out;
}

std::vector<Eigen::Vector2i> oppositeVertices(const std::vector<Eigen::Vector3i>& triangles) {
    std::map<std::pair<int, int>, std::vector<int>> opposite;  // edge -> the vertex opposite it in each triangle
    for (const auto& t : triangles)
        for (int k = 0; k < 3; ++k) opposite[std::minmax(t[k], t[(k + 1) % 3])].push_back(t[(k + 2) % 3]);
    std::vector<std::pair<int, int>> pairs;
    for (const auto& [edge, o] : opposite)
        if (o.size() == 2 && o[0] != o[1]) pairs.push_back(std::minmax(o[0], o[1]));
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    std::vector<Eigen::Vector2i> out;
    for (const auto& [a, b] : pairs) out.emplace_back(a, b);
    return out;
}

}  // namespace clothlab

namespace clothlab {

std::vector<int> colourOrder(const std::vector<Eigen::Vector4i>& particles, int nParticles) {
    // used[i]: colours already taken by constraints touching particle i (one bit per colour, in 64-colour words).
    std::vector<std::vector<std::uint64_t>> used(static_cast<size_t>(nParticles));
    std::vector<int> colour(particles.size(), 0);
    int colours = 0;
    for (size_t k = 0; k < particles.size(); ++k) {
        int c = 0;
        for (;; ++c) {
            bool free = true;
            for (int a = 0; a < 4 && free; ++a) {
                const int i = particles[k][a];
                if (i < 0) continue;
                const auto& u = used[static_cast<size_t>(i)];
                const size_t word = static_cast<size_t>(c) / 64;
                if (word < u.size() && (u[word] >> (c % 64) & 1u)) free = false;
            }
            if (free) break;
        }
        colour[k] = c;
        colours = std::max(colours, c + 1);
        for (int a = 0; a < 4; ++a) {
            const int i = particles[k][a];
            if (i < 0) continue;
            auto& u = used[static_cast<size_t>(i)];
            const size_t word = static_cast<size_t>(c) / 64;
            if (u.size() <= word) u.resize(word + 1, 0);
            u[word] |= std::uint64_t{1} << (c % 64);
        }
    }
    std::vector<int> order;
    order.reserve(particles.size());
    std::vector<std::vector<int>> byColour(static_cast<size_t>(colours));
    for (size_t k = 0; k < particles.size(); ++k) byColour[static_cast<size_t>(colour[k])].push_back(static_cast<int>(k));
    for (const auto& b : byColour) order.insert(order.end(), b.begin(), b.end());
    return order;
}

}  // namespace clothlab
