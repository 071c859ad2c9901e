#include "clothlab/core/mesh.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <utility>

#include <tiny_obj_loader.h>

#include "clothlab/core/input_error.h"

namespace clothlab {

namespace {

std::string triangleName(const TriangleMesh& m, size_t t) {
    const auto& f = m.triangles[t];
    return "face " + std::to_string(t) + " (vertices " + std::to_string(f[0]) + ", " + std::to_string(f[1]) + ", " +
           std::to_string(f[2]) + ")";
}

}  // namespace

std::string meshProblem(const TriangleMesh& m, bool everyVertexUsed) {
    if (m.triangles.empty()) return "no faces (a mesh needs at least one triangle)";
    const long long nv = m.vertices.cols();
    for (size_t t = 0; t < m.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            if (m.triangles[t][k] < 0 || m.triangles[t][k] >= nv)
                return triangleName(m, t) + ": vertex index out of range (the file has " + std::to_string(nv) + " vertices)";
    std::map<std::pair<int, int>, int> edgeUse;
    std::vector<char> used(static_cast<size_t>(nv), 0);
    for (size_t t = 0; t < m.triangles.size(); ++t) {
        const auto& f = m.triangles[t];
        const Vec3 a = m.vertices.col(f[0]), b = m.vertices.col(f[1]), c = m.vertices.col(f[2]);
        const double longest2 = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
        if (!((b - a).cross(c - a).norm() > 1e-12 * longest2) || longest2 == 0.0) return triangleName(m, t) + " has zero area";
        for (int k = 0; k < 3; ++k) {
            used[static_cast<size_t>(f[k])] = 1;
            const auto e = std::minmax(f[k], f[(k + 1) % 3]);
            if (++edgeUse[e] > 2)
                return "non-manifold edge (" + std::to_string(e.first) + ", " + std::to_string(e.second) +
                       ") shared by more than two faces (" + triangleName(m, t) + " is the third)";
        }
    }
    if (everyVertexUsed)
        for (long long i = 0; i < nv; ++i)
            if (!used[static_cast<size_t>(i)]) return "vertex " + std::to_string(i) + " belongs to no face (it would have no mass)";
    return "";
}

TriangleMesh loadObjMesh(const std::string& path, const std::string& sceneFile, const std::string& field, bool everyVertexUsed) {
    const auto fail = [&](const std::string& reason) { throw InputError(sceneFile, field, path + ": " + reason); };
    if (!std::filesystem::is_regular_file(path)) fail("no such file");
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(path, config)) {
        std::string e = reader.Error();
        std::replace(e.begin(), e.end(), '\n', ' ');
        fail("cannot read it as OBJ: " + e);
    }
    TriangleMesh m;
    const auto& v = reader.GetAttrib().vertices;
    m.vertices.resize(3, static_cast<Eigen::Index>(v.size() / 3));
    for (size_t i = 0; i < v.size(); ++i) m.vertices(static_cast<Eigen::Index>(i % 3), static_cast<Eigen::Index>(i / 3)) = v[i];
    for (const auto& shape : reader.GetShapes()) {
        const auto& idx = shape.mesh.indices;
        size_t start = 0;
        for (const unsigned n : shape.mesh.num_face_vertices) {
            if (n != 3) fail("a face with " + std::to_string(n) + " vertices (faces need at least 3)");
            m.triangles.emplace_back(idx[start].vertex_index, idx[start + 1].vertex_index, idx[start + 2].vertex_index);
            start += n;
        }
    }
    if (!m.vertices.allFinite()) fail("a vertex coordinate is not a finite number");
    const std::string problem = meshProblem(m, everyVertexUsed);
    if (!problem.empty()) fail(problem);
    return m;
}

VectorX lumpedMasses(const TriangleMesh& m, double total) {
    VectorX mass = VectorX::Zero(m.vertices.cols());
    double area = 0.0;
    for (const auto& f : m.triangles) {
        const double a = 0.5 * (m.vertices.col(f[1]) - m.vertices.col(f[0])).cross(m.vertices.col(f[2]) - m.vertices.col(f[0])).norm();
        for (int k = 0; k < 3; ++k) mass[f[k]] += a / 3.0;
        area += a;
    }
    return mass * (total / area);
}

Matrix3X triangleNormals(const TriangleMesh& m) {
    Matrix3X n(3, static_cast<Eigen::Index>(m.triangles.size()));
    for (size_t t = 0; t < m.triangles.size(); ++t) {
        const auto& f = m.triangles[t];
        n.col(static_cast<Eigen::Index>(t)) =
            (m.vertices.col(f[1]) - m.vertices.col(f[0])).cross(m.vertices.col(f[2]) - m.vertices.col(f[0])).normalized();
    }
    return n;
}

}  // namespace clothlab
