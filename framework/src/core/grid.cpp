#include "clothlab/core/grid.h"

namespace clothlab {

State makeGridState(const ClothSpec& spec) {
    State s;
    s.resize(spec.nx * spec.ny);
    const double dx = spec.width / (spec.nx - 1), dy = spec.height / (spec.ny - 1);
    const double w = spec.nx * spec.ny / spec.mass;  // 1 / m_i
    for (int r = 0; r < spec.ny; ++r)
        for (int c = 0; c < spec.nx; ++c) {
            const int i = gridIndex(c, r, spec.nx);
            s.x.col(i) = spec.origin + (spec.horizontal ? Vec3(c * dx, 0, r * dy) : Vec3(c * dx, -r * dy, 0));
            s.w[i] = w;
        }
    for (int p : spec.pins) s.w[p] = 0.0;
    return s;
}

std::vector<Eigen::Vector3i> gridTriangles(int nx, int ny) {
    std::vector<Eigen::Vector3i> t;
    t.reserve(2 * static_cast<size_t>(nx - 1) * (ny - 1));
    for (int r = 0; r + 1 < ny; ++r)
        for (int c = 0; c + 1 < nx; ++c) {
            const int a = gridIndex(c, r, nx), b = gridIndex(c + 1, r, nx);
            const int d = gridIndex(c, r + 1, nx), e = gridIndex(c + 1, r + 1, nx);
            t.emplace_back(a, d, e);
            t.emplace_back(a, e, b);
        }
    return t;
}

}  // namespace clothlab
