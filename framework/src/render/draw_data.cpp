// What the renderer draws, filled from a simulation or a scene (no GL).
#include "clothlab/render/draw_data.h"

#include <cstdlib>

#include "clothlab/core/grid.h"
#include "clothlab/core/topology.h"
#include "clothlab/sim/colliders.h"
#include "clothlab/sim/mass_spring.h"
#include "clothlab/sim/simulation.h"

namespace clothlab {

const char* edgeKindName(EdgeKind kind) {
    switch (kind) {
        case EdgeKind::Single: return "spring";
        case EdgeKind::Structural: return "structural";
        case EdgeKind::Shear: return "shear";
        case EdgeKind::Bending: return "bending";
    }
    return "?";
}

double DrawData::strain(int e) const {
    const auto& ed = edges[static_cast<size_t>(e)];
    const double l0 = rest_length[static_cast<size_t>(e)];
    if (l0 <= 0.0) return 0.0;
    return (x.col(ed[0]) - x.col(ed[1])).norm() / l0 - 1.0;
}

namespace {

// Kind of a grid edge from the column/row offset of its particles.
EdgeKind gridKind(int i, int j, int nx) {
    const int dc = std::abs(i % nx - j % nx), dr = std::abs(i / nx - j / nx);
    if (dc + dr == 1) return EdgeKind::Structural;
    if (dc == 1 && dr == 1) return EdgeKind::Shear;
    return EdgeKind::Bending;
}

std::string titleOf(const Scene& s) {
    std::string name = s.file;
    const auto slash = name.find_last_of('/');
    if (slash != std::string::npos) name = name.substr(slash + 1);
    return name + "  |  " + methodName(s.solver.method) + "  |  dt = " + std::to_string(s.solver.dt).substr(0, 7) + " s";
}

void setEdges(DrawData& d, const std::vector<Eigen::Vector2i>& edges, const Scene& s, const State& rest) {
    d.edges = edges;
    d.edge_kind.clear();
    d.rest_length.clear();
    for (const auto& e : edges) {
        if (s.model == Model::Cloth) {
            d.edge_kind.push_back(s.cloth.meshData ? EdgeKind::Structural : gridKind(e[0], e[1], s.cloth.nx));
            d.rest_length.push_back((rest.x.col(e[0]) - rest.x.col(e[1])).norm());
        } else {
            d.edge_kind.push_back(EdgeKind::Single);
            d.rest_length.push_back(s.model == Model::Chain ? s.chain.l0 : s.spring.l0);
        }
    }
}

// The scene's colliders, and the solid ones (box, capsule, mesh) as triangles.
void setColliders(DrawData& d, const Scene& s) {
    d.colliders = s.colliders;
    d.collider_triangles.clear();
    for (const Collider& c : s.colliders)
        if (c.type != Collider::Type::Plane && c.type != Collider::Type::Sphere) d.collider_triangles.push_back(colliderTriangles(c));
}

void setUv(DrawData& d, const ClothSpec& c) {
    d.uv.resize(2, c.nx * c.ny);
    for (int r = 0; r < c.ny; ++r)
        for (int col = 0; col < c.nx; ++col)
            d.uv.col(gridIndex(col, r, c.nx)) << double(col) / (c.nx - 1), double(r) / (c.ny - 1);
}

std::vector<Eigen::Vector2i> gridEdges(int nx, int ny) {
    std::vector<Eigen::Vector2i> e;
    for (int r = 0; r < ny; ++r)
        for (int c = 0; c < nx; ++c) {
            const int i = gridIndex(c, r, nx);
            if (c + 1 < nx) e.emplace_back(i, gridIndex(c + 1, r, nx));
            if (r + 1 < ny) e.emplace_back(i, gridIndex(c, r + 1, nx));
            if (c + 1 < nx && r + 1 < ny) e.emplace_back(i, gridIndex(c + 1, r + 1, nx));
            if (c > 0 && r + 1 < ny) e.emplace_back(i, gridIndex(c - 1, r + 1, nx));
            if (c + 2 < nx) e.emplace_back(i, gridIndex(c + 2, r, nx));
            if (r + 2 < ny) e.emplace_back(i, gridIndex(c, r + 2, nx));
        }
    return e;
}

}  // namespace

DrawData makeDrawData(const Simulation& sim) {
    const Scene& s = sim.scene();
    DrawData d;
    d.x = sim.state().x;
    d.w = sim.state().w;
    d.t = sim.state().t;
    d.triangles = sim.triangles();
    setColliders(d, s);
    d.title = titleOf(s);
    State rest;
    if (s.model == Model::Cloth) {
        rest = makeClothGeometry(s.cloth).state;
        if (rest.size() != sim.state().size()) rest = sim.state();
        else if (!s.cloth.meshData) setUv(d, s.cloth);
    }
    setEdges(d, sim.edges(), s, rest);
    if (const auto exact = singleSpringAnalytic(s))
        d.ghosts.push_back(s.spring.anchor + exact->position(d.t) * (s.spring.start - s.spring.anchor).normalized());
    return d;
}

DrawData makeClothDrawData(const ClothSpec& spec, const State& state, const State& rest) {
    DrawData d;
    d.x = state.x;
    d.w = state.w;
    d.t = state.t;
    d.triangles = gridTriangles(spec.nx, spec.ny);
    Scene s;
    s.model = Model::Cloth;
    s.cloth = spec;
    setEdges(d, gridEdges(spec.nx, spec.ny), s, rest);
    setUv(d, spec);
    return d;
}

DrawData makeDrawData(const Scene& s) {
    DrawData d;
    if (s.model == Model::Cloth && s.cloth.meshData) {
        ClothGeometry g = makeClothGeometry(s.cloth);
        movePins(g.state, s.cloth);
        d.x = g.state.x;
        d.w = g.state.w;
        d.triangles = g.triangles;
        setEdges(d, uniqueEdges(g.triangles), s, g.state);
    } else if (s.model == Model::Cloth) {
        State st = makeGridState(s.cloth);
        movePins(st, s.cloth);
        d = makeClothDrawData(s.cloth, st, makeGridState(s.cloth));
    } else {
        const MassSpringModel m = s.model == Model::Chain ? makeChain(s.chain) : makeSingleSpring(s.spring);
        d.x = m.state.x;
        d.w = m.state.w;
        std::vector<Eigen::Vector2i> e;
        for (const Spring& sp : m.springs) e.emplace_back(sp.i, sp.j);
        setEdges(d, e, s, m.state);
    }
    setColliders(d, s);
    d.title = titleOf(s);
    return d;
}

}  // namespace clothlab
