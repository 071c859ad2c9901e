#include "clothlab/core/grid.h"

#include <cmath>

#include "clothlab/core/mesh.h"

namespace clothlab {

State makeGridState(const ClothSpec& spec) {
    State s;
    s.resize(spec.nx * spec.ny);
    const double dx = spec.width / (spec.nx - 1), dy = spec.height / (spec.ny - 1);
    const double w = spec.nx * spec.ny / spec.mass;  // 1 / m_i
    // Direction of growing rows: -y (vertical) or +z (horizontal), turned by `tilt` about the x axis.
    const double phi = (spec.horizontal ? 90.0 - spec.tilt : spec.tilt) * 3.14159265358979323846 / 180.0;
    const Vec3 down = spec.tilt == 0.0 ? (spec.horizontal ? Vec3(0, 0, 1) : Vec3(0, -1, 0)) : Vec3(0, -std::cos(phi), std::sin(phi));
    for (int r = 0; r < spec.ny; ++r)
        for (int c = 0; c < spec.nx; ++c) {
            const int i = gridIndex(c, r, spec.nx);
            s.x.col(i) = spec.origin + spec.rotation * (Vec3(c * dx, 0, 0) + r * dy * down);
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

ClothGeometry makeClothGeometry(const ClothSpec& spec) {
    ClothGeometry g;
    if (!spec.meshData) {
        g.state = makeGridState(spec);
        g.triangles = gridTriangles(spec.nx, spec.ny);
        return g;
    }
    const TriangleMesh& m = *spec.meshData;
    g.state.resize(static_cast<int>(m.vertices.cols()));
    g.state.x = (spec.rotation * (spec.scale * m.vertices)).colwise() + spec.origin;
    TriangleMesh placed{g.state.x, m.triangles};
    g.state.w = lumpedMasses(placed, spec.mass).cwiseInverse();
    for (int p : spec.pins) g.state.w[p] = 0.0;
    g.triangles = m.triangles;
    return g;
}

void movePins(State& s, const ClothSpec& spec) {
    for (const PinMove& m : spec.moves) {
        s.x.col(m.index) = m.to;
        s.v.col(m.index).setZero();
    }
}

}  // namespace clothlab
