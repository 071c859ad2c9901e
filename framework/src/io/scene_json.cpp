// Scene loading: a small validating reader over nlohmann::json.
#include "clothlab/io/scene_json.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "clothlab/core/grid.h"
#include "clothlab/core/input_error.h"
#include "clothlab/core/mesh.h"
#include "clothlab/sim/colliders.h"
#include "clothlab/sim/kernel_registry.h"

namespace clothlab {
namespace {

using json = nlohmann::json;

std::string join(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& e : v) s += (s.empty() ? "" : ", ") + e;
    return s;
}

std::string describe(const json& j) {
    std::string s = j.dump(-1, ' ', false, json::error_handler_t::replace);  // bytes that are not UTF-8 print as U+FFFD
    if (s.size() > 40) s = s.substr(0, 37) + "...";
    return std::string(j.type_name()) + " " + s;
}

/// One JSON object being read: remembers its path and which keys were used.
class Reader {
public:
    Reader(const json& j, std::string path, const std::string& file) : j_(j), path_(std::move(path)), file_(file) {
        if (!j_.is_object()) fail("", "expected an object (got " + describe(j_) + ")");
    }
    [[noreturn]] void fail(const std::string& key, const std::string& reason) const {
        throw InputError(file_, field(key), reason);
    }
    std::string field(const std::string& key) const {
        if (key.empty()) return path_.empty() ? "(top level)" : path_;
        return path_.empty() ? key : path_ + "." + key;
    }
    bool has(const std::string& key) const { return j_.contains(key); }
    const json* get(const std::string& key) {
        if (std::find(allowed_.begin(), allowed_.end(), key) == allowed_.end()) allowed_.push_back(key);
        return j_.contains(key) ? &j_.at(key) : nullptr;
    }
    double number(const std::string& key, double def, double lo = -INFINITY, double hi = INFINITY,
                  bool lo_open = false) {
        const json* v = get(key);
        if (!v) return def;
        return checkNumber(*v, key, lo, hi, lo_open);
    }
    double checkNumber(const json& v, const std::string& key, double lo, double hi, bool lo_open) const {
        if (!v.is_number()) fail(key, "expected a number (got " + describe(v) + ")");
        const double x = v.get<double>();
        if (!std::isfinite(x)) fail(key, "must be a finite number");
        if (lo_open ? !(x > lo) : !(x >= lo)) fail(key, "must be " + std::string(lo_open ? "> " : ">= ") + fmt(lo) + " (got " + fmt(x) + ")");
        if (!(x <= hi)) fail(key, "must be <= " + fmt(hi) + " (got " + fmt(x) + ")");
        return x;
    }
    int integer(const std::string& key, int def, int lo, int hi) {
        const json* v = get(key);
        if (!v) return def;
        if (!v->is_number_integer()) fail(key, "expected a whole number (got " + describe(*v) + ")");
        const long long x = v->get<long long>();
        if (x < lo || x > hi) fail(key, "must be between " + std::to_string(lo) + " and " + std::to_string(hi) + " (got " + v->dump() + ")");
        return static_cast<int>(x);
    }
    bool boolean(const std::string& key, bool def) {
        const json* v = get(key);
        if (!v) return def;
        if (!v->is_boolean()) fail(key, "expected true or false (got " + describe(*v) + ")");
        return v->get<bool>();
    }
    std::string choice(const std::string& key, const std::string& def, const std::vector<std::string>& allowed) {
        const json* v = get(key);
        if (!v) return def;
        if (!v->is_string()) fail(key, "expected a string (got " + describe(*v) + ")");
        const std::string s = v->get<std::string>();
        for (const auto& a : allowed) if (a == s) return s;
        fail(key, "unknown value \"" + s + "\" (allowed: " + join(allowed) + ")");
    }
    std::string text(const std::string& key, const std::string& def) {
        const json* v = get(key);
        if (!v) return def;
        if (!v->is_string()) fail(key, "expected a string (got " + describe(*v) + ")");
        return v->get<std::string>();
    }
    Vec3 vec3(const std::string& key, const Vec3& def) {
        const json* v = get(key);
        if (!v) return def;
        if (!v->is_array() || v->size() != 3) fail(key, "expected an array of 3 numbers (got " + describe(*v) + ")");
        Vec3 r;
        for (int i = 0; i < 3; ++i) r[i] = checkNumber((*v)[i], key + "[" + std::to_string(i) + "]", -INFINITY, INFINITY, false);
        return r;
    }
    /// A nested object; an absent key reads as an empty object (all defaults).
    Reader object(const std::string& key) {
        static const json empty = json::object();
        const json* v = get(key);
        return Reader(v ? *v : empty, field(key), file_);
    }
    /// Fails on any key that no reader call asked for.
    void finish() const {
        for (auto it = j_.begin(); it != j_.end(); ++it) {
            bool known = false;
            for (const auto& a : allowed_) known = known || a == it.key();
            if (!known) fail(it.key(), "unknown key (allowed here: " + join(allowed_) + ")");
        }
    }
    const std::string& file() const { return file_; }

private:
    static std::string fmt(double x) {
        std::ostringstream s;
        s << x;
        return s.str();
    }
    const json& j_;
    std::string path_;
    const std::string& file_;
    std::vector<std::string> allowed_;
};

SingleSpringSpec readSpring(Reader r) {
    SingleSpringSpec s;
    s.anchor = r.vec3("anchor", s.anchor);
    s.start = r.vec3("start", s.start);
    s.velocity = r.vec3("velocity", s.velocity);
    s.mass = r.number("mass", s.mass, 0, INFINITY, true);
    s.k = r.number("k", s.k, 0);
    s.l0 = r.number("l0", s.l0, 0);
    s.kd = r.number("kd", s.kd, 0);
    r.finish();
    return s;
}

ChainSpec readChain(Reader r) {
    ChainSpec c;
    c.particles = r.integer("particles", c.particles, 2, 100000);
    c.anchor = r.vec3("anchor", c.anchor);
    c.direction = r.vec3("direction", c.direction);
    if (c.direction.norm() < 1e-12) r.fail("direction", "must not be the zero vector");
    c.direction.normalize();
    c.mass = r.number("mass", c.mass, 0, INFINITY, true);
    c.k = r.number("k", c.k, 0);
    c.l0 = r.number("l0", c.l0, 0);
    c.kd = r.number("kd", c.kd, 0);
    if (r.has("end")) {
        c.end = r.vec3("end", Vec3::Zero());
        const double span = (*c.end - c.anchor).norm(), length = (c.particles - 1) * c.l0;
        if (!(span < length))
            r.fail("end", "the anchors are " + std::to_string(span) + " m apart, not less than the chain's length (particles - 1) * l0 = " +
                              std::to_string(length) + " m");
    }
    (void)r.get("end");
    r.finish();
    return c;
}

/// A file named in the scene, relative to the scene file's folder (an absolute path stays as it is).
std::string besideScene(const std::string& sceneFile, const std::string& name) {
    const std::filesystem::path p(name);
    return p.is_absolute() ? name : (std::filesystem::path(sceneFile).parent_path() / p).string();
}

/// A turn given as Euler angles in degrees [a_x, a_y, a_z]: R = R_z(a_z) R_y(a_y) R_x(a_x).
Eigen::Matrix3d readRotation(Reader& r, const std::string& key) {
    const Vec3 a = r.vec3(key, Vec3::Zero()) * (3.14159265358979323846 / 180.0);
    return (Eigen::AngleAxisd(a.z(), Vec3::UnitZ()) * Eigen::AngleAxisd(a.y(), Vec3::UnitY()) *
            Eigen::AngleAxisd(a.x(), Vec3::UnitX())).toRotationMatrix();
}

/// One pin given as an object: {"index": i}, {"nearest": [x, y, z]} or {"box": {"min": .., "max": ..}},
/// the first two optionally with "to": [x, y, z] (the particle is held there).
/// @return the pinned particles (a move is appended to c.moves)
std::vector<int> readPinObject(Reader e, const Matrix3X& rest, ClothSpec& c) {
    const int n = static_cast<int>(rest.cols());
    const int given = e.has("index") + e.has("nearest") + e.has("box");
    if (given != 1) e.fail("", "give exactly one of index, nearest, box");
    std::vector<int> chosen;
    if (e.has("index")) {
        chosen.push_back(e.integer("index", 0, 0, n - 1));
    } else if (e.has("nearest")) {
        const Vec3 q = e.vec3("nearest", Vec3::Zero());
        Eigen::Index best = 0;
        (rest.colwise() - q).colwise().squaredNorm().minCoeff(&best);
        chosen.push_back(static_cast<int>(best));
    } else {
        Reader box = e.object("box");
        const Vec3 lo = box.vec3("min", Vec3::Zero()), hi = box.vec3("max", Vec3::Zero());
        if (!box.has("min") || !box.has("max")) box.fail("", "needs min and max, e.g. {\"min\": [0, 0, 0], \"max\": [1, 1, 1]}");
        if (!(lo.array() <= hi.array()).all()) box.fail("max", "must be >= min in every coordinate");
        box.finish();
        for (int i = 0; i < n; ++i)
            if ((rest.col(i).array() >= lo.array()).all() && (rest.col(i).array() <= hi.array()).all()) chosen.push_back(i);
        if (chosen.empty()) e.fail("box", "no particle lies inside the box");
        if (e.has("to")) e.fail("to", "moves one particle: use it with index or nearest, not with box");
    }
    if (e.has("to")) c.moves.push_back({chosen.front(), e.vec3("to", Vec3::Zero())});
    (void)e.get("to");
    e.finish();
    return chosen;
}

/// Pins: indices, names of corners and edges of the grid, or objects (readPinObject()).
std::vector<int> readPins(Reader& r, ClothSpec& c) {
    const json* v = r.get("pins");
    std::vector<int> pins;
    if (!v) return pins;
    if (!v->is_array()) r.fail("pins", "expected an array of indices, names or objects (got " + describe(*v) + ")");
    const int nx = c.nx, ny = c.ny;
    const Matrix3X rest = makeClothGeometry(c).state.x;  // pins and moves refer to the cloth at rest
    const long long count = rest.cols();
    for (size_t k = 0; k < v->size(); ++k) {
        const json& e = (*v)[k];
        const std::string key = "pins[" + std::to_string(k) + "]";
        if (e.is_number_integer()) {
            const long long i = e.get<long long>();
            if (i < 0 || i >= count)
                r.fail(key, "particle index " + e.dump() + " outside the cloth (0.." + std::to_string(count - 1) + ")");
            pins.push_back(static_cast<int>(i));
        } else if (e.is_object()) {
            const std::vector<int> chosen = readPinObject(Reader(e, r.field(key), r.file()), rest, c);
            pins.insert(pins.end(), chosen.begin(), chosen.end());
        } else if (e.is_string() && c.meshData) {
            r.fail(key, "named pins need a grid cloth; on a mesh use an index or {\"nearest\": [x, y, z]} or {\"box\": ...}");
        } else if (e.is_string()) {
            const std::string s = e.get<std::string>();
            if (s == "top-left") pins.push_back(0);
            else if (s == "top-right") pins.push_back(nx - 1);
            else if (s == "bottom-left") pins.push_back((ny - 1) * nx);
            else if (s == "bottom-right") pins.push_back(ny * nx - 1);
            else if (s == "top-edge") for (int i = 0; i < nx; ++i) pins.push_back(i);
            else if (s == "left-edge") for (int j = 0; j < ny; ++j) pins.push_back(j * nx);
            else r.fail(key, "unknown pin \"" + s + "\" (allowed: an index, top-left, top-right, bottom-left, bottom-right, top-edge, left-edge)");
        } else {
            r.fail(key, "expected an index or a name (got " + describe(e) + ")");
        }
    }
    return pins;
}

/// cloth.mesh, cloth.scale: a cloth made of the triangles of an OBJ file (grid fields are then errors).
void readClothMesh(Reader& r, ClothSpec& c) {
    c.mesh = r.text("mesh", "");
    c.scale = r.number("scale", c.scale, 0, INFINITY, true);
    if (c.mesh.empty()) {
        if (r.has("scale")) r.fail("scale", "only for a mesh cloth (cloth.mesh)");
        return;
    }
    for (const char* grid : {"nx", "ny", "width", "height", "orientation", "tilt", "normal"})
        if (r.has(grid)) r.fail(grid, std::string("not used by a mesh cloth (cloth.mesh is given)") +
                                          (std::string(grid) == "normal" ? "; turn it with cloth.rotation" : ""));
    c.meshData = std::make_shared<const TriangleMesh>(loadObjMesh(besideScene(r.file(), c.mesh), r.file(), r.field("mesh"), true));
}

/// cloth.rotation or cloth.normal: a turn of the whole cloth about its origin.
void readClothRotation(Reader& r, ClothSpec& c) {
    if (r.has("rotation") && r.has("normal")) r.fail("normal", "give cloth.rotation or cloth.normal, not both");
    c.rotation = readRotation(r, "rotation");
    const Vec3 n = r.vec3("normal", Vec3::Zero());
    if (!r.has("normal")) return;
    if (n.norm() < 1e-12) r.fail("normal", "must not be the zero vector");
    const State flat = makeGridState(c);  // the normal of the unturned grid: (down) x (across)
    const Vec3 n0 = (flat.x.col(c.nx) - flat.x.col(0)).cross(flat.x.col(1) - flat.x.col(0)).normalized();
    c.rotation = Eigen::Quaterniond::FromTwoVectors(n0, n.normalized()).toRotationMatrix();
}

ClothSpec readCloth(Reader r) {
    ClothSpec c;
    readClothMesh(r, c);
    c.nx = r.integer("nx", c.nx, 2, 4096);
    c.ny = r.integer("ny", c.ny, 2, 4096);
    if (static_cast<long long>(c.nx) * c.ny > 4'000'000) r.fail("ny", "grid too large (nx*ny > 4,000,000)");
    c.width = r.number("width", c.width, 0, INFINITY, true);
    c.height = r.number("height", c.height, 0, INFINITY, true);
    c.mass = r.number("mass", c.mass, 0, INFINITY, true);
    c.origin = r.vec3("origin", c.origin);
    c.horizontal = r.choice("orientation", "vertical", {"vertical", "horizontal"}) == "horizontal";
    c.tilt = r.number("tilt", c.tilt, -90, 90);
    readClothRotation(r, c);
    c.pins = readPins(r, c);
    r.finish();
    return c;
}

SpringGroup readSpringGroup(Reader r) {
    SpringGroup g;
    g.enabled = r.boolean("enabled", true);  // naming a group switches it on unless it says otherwise
    g.k = r.number("k", g.k, 0);
    g.kd = r.number("kd", g.kd, 0);
    r.finish();
    return g;
}

ConstraintGroup readConstraintGroup(Reader r) {
    ConstraintGroup g;
    g.enabled = r.boolean("enabled", true);
    g.stiffness = r.number("stiffness", g.stiffness, 0, 1);
    g.compliance = r.number("compliance", g.compliance, 0);
    r.finish();
    return g;
}

/// The fields of a box, capsule or mesh collider.
void readSolidCollider(Reader& r, const std::string& type, Collider& c) {
    if (type == "box") {
        c.type = Collider::Type::Box;
        c.point = r.vec3("center", c.point);
        c.halfExtents = r.vec3("half_extents", c.halfExtents);
        if (!(c.halfExtents.array() > 0).all()) r.fail("half_extents", "every half extent must be > 0");
        c.rotation = readRotation(r, "rotation");
    } else if (type == "capsule") {
        c.type = Collider::Type::Capsule;
        c.point = r.vec3("start", c.point);
        c.end = r.vec3("end", c.end);
        if ((c.end - c.point).norm() < 1e-12) r.fail("end", "equals start (a capsule needs an axis; use a sphere)");
        c.radius = r.number("radius", c.radius, 0, INFINITY, true);
    } else {
        c.type = Collider::Type::Mesh;
        c.mesh = r.text("mesh", "");
        if (c.mesh.empty()) r.fail("mesh", "missing (an OBJ file, relative to the scene file)");
        TriangleMesh m = loadObjMesh(besideScene(r.file(), c.mesh), r.file(), r.field("mesh"), false);
        const double scale = r.number("scale", 1.0, 0, INFINITY, true);
        m.vertices = (readRotation(r, "rotation") * (scale * m.vertices)).colwise() + r.vec3("origin", Vec3::Zero());
        c.shape = std::make_shared<const MeshShape>(std::move(m));
    }
}

Collider readCollider(Reader r) {
    Collider c;
    const std::string type = r.choice("type", "", {"plane", "sphere", "box", "capsule", "mesh"});
    if (type.empty()) r.fail("type", "missing (plane, sphere, box, capsule or mesh)");
    if (type == "box" || type == "capsule" || type == "mesh") {
        readSolidCollider(r, type, c);
    } else if (type == "plane") {
        c.type = Collider::Type::Plane;
        c.point = r.vec3("point", c.point);
        c.normal = r.vec3("normal", c.normal);
        if (c.normal.norm() < 1e-12) r.fail("normal", "must not be the zero vector");
        c.normal.normalize();
    } else {
        c.type = Collider::Type::Sphere;
        c.point = r.vec3("center", c.point);
        c.radius = r.number("radius", c.radius, 0, INFINITY, true);
    }
    c.friction = r.number("friction", c.friction, 0);
    c.restitution = r.number("restitution", c.restitution, 0, 1);
    r.finish();
    return c;
}

/// Limits of a scene file (docs/scenes.md "Limits"), checked before the file is read or parsed.
constexpr std::uintmax_t kMaxSceneBytes = 16u << 20;  // 16 MiB
constexpr int kMaxDepth = 64;                          // nesting of arrays and objects

/// json::parse with a nesting limit (nlohmann's dump() and comparisons recurse once per level).
json parseLimited(const std::string& text, const std::string& file, const std::string& field, bool allow_exceptions) {
    const auto depthCheck = [&](int depth, json::parse_event_t, json&) {
        if (depth >= kMaxDepth) throw InputError(file, field, "nested deeper than " + std::to_string(kMaxDepth) + " levels");
        return true;
    };
    return json::parse(text, depthCheck, allow_exceptions);
}

/// Sets a dotted key of the document to a value given on the command line.
void applyOverride(json& doc, const std::string& kv, const std::string& file) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0)
        throw InputError(file, "(--set)", "--set expects key=value, e.g. solver.dt=0.01 (got \"" + kv + "\")");
    const std::string key = kv.substr(0, eq), text = kv.substr(eq + 1);
    json value = parseLimited(text, file, key, /*allow_exceptions=*/false);
    if (value.is_discarded()) value = text;  // plain words are strings
    json* node = &doc;
    std::string::size_type start = 0;
    while (true) {
        const auto dot = key.find('.', start);
        const std::string part = key.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
        if (part.empty()) throw InputError(file, key, "empty component in key");
        if (node->is_array()) {
            char* end = nullptr;
            const long idx = std::strtol(part.c_str(), &end, 10);
            if (*end != '\0' || idx < 0 || idx >= static_cast<long>(node->size()))
                throw InputError(file, key, "no element \"" + part + "\" in this array");
            node = &(*node)[static_cast<size_t>(idx)];
        } else {
            if (node->is_null()) *node = json::object();
            if (!node->is_object()) throw InputError(file, key, "\"" + part + "\" is inside a value that is not an object");
            node = &(*node)[part];
        }
        if (dot == std::string::npos) break;
        start = dot + 1;
    }
    *node = value;
}

Scene readScene(const json& doc, const std::string& file) {
    Reader r(doc, "", file);
    Scene s;
    s.file = file;
    s.description = r.text("description", "");
    const std::string model = r.choice("model", "", {"spring", "chain", "cloth"});
    if (model.empty()) r.fail("model", "missing (spring, chain or cloth)");
    s.model = model == "spring" ? Model::Spring : model == "chain" ? Model::Chain : Model::Cloth;
    if (s.model == Model::Spring) s.spring = readSpring(r.object("spring"));
    else if (r.has("spring")) r.fail("spring", "given but model is \"" + model + "\"");
    if (s.model == Model::Chain) s.chain = readChain(r.object("chain"));
    else if (r.has("chain")) r.fail("chain", "given but model is \"" + model + "\"");
    if (s.model == Model::Cloth) s.cloth = readCloth(r.object("cloth"));
    else if (r.has("cloth")) r.fail("cloth", "given but model is \"" + model + "\"");

    Reader springs = r.object("springs");
    if (springs.has("structural")) s.springs.structural = readSpringGroup(springs.object("structural"));
    if (springs.has("shear")) s.springs.shear = readSpringGroup(springs.object("shear"));
    if (springs.has("bending")) s.springs.bending = readSpringGroup(springs.object("bending"));
    for (const char* key : {"structural", "shear", "bending"}) (void)springs.get(key);
    springs.finish();

    Reader provot = r.object("provot");
    s.provot.enabled = provot.boolean("enabled", r.has("provot"));
    s.provot.max_strain = provot.number("max_strain", s.provot.max_strain, 0, INFINITY, true);
    provot.finish();

    Reader cons = r.object("constraints");
    if (cons.has("distance")) s.constraints.distance = readConstraintGroup(cons.object("distance"));
    if (cons.has("bending")) s.constraints.bending = readConstraintGroup(cons.object("bending"));
    for (const char* key : {"distance", "bending"}) (void)cons.get(key);
    cons.finish();

    if (const json* cs = r.get("colliders")) {
        if (!cs->is_array()) r.fail("colliders", "expected an array (got " + describe(*cs) + ")");
        for (size_t i = 0; i < cs->size(); ++i)
            s.colliders.push_back(readCollider(Reader((*cs)[i], "colliders[" + std::to_string(i) + "]", file)));
    }

    Reader self = r.object("self_collision");
    s.self_collision.enabled = self.boolean("enabled", r.has("self_collision"));
    s.self_collision.thickness = self.number("thickness", s.self_collision.thickness, 0, INFINITY, true);
    s.self_collision.friction = self.number("friction", s.self_collision.friction, 0);
    self.finish();

    Reader f = r.object("forces");
    s.forces.gravity = f.vec3("gravity", s.forces.gravity);
    if (f.has("damping"))  // one name had two meanings (N s/m and [0, 1]) before it was split
        f.fail("damping", "renamed: use forces.air_damping (force -c v, N s/m; force-based methods and pbd/xpbd) or "
                          "pbd.damping (k_damping of dampVelocities in [0, 1]; pbd and xpbd)");
    s.forces.air_damping = f.number("air_damping", s.forces.air_damping, 0);
    s.forces.wind = f.vec3("wind", s.forces.wind);
    s.forces.drag = f.number("drag", s.forces.drag, 0);
    f.finish();

    Reader sv = r.object("solver");
    std::vector<std::string> methods;
    for (Method m : allMethods()) methods.push_back(methodName(m));
    s.solver.method = *parseMethod(sv.choice("method", methodName(s.solver.method), methods));
    s.solver.dt = sv.number("dt", s.solver.dt, 0, 10, true);
    s.solver.steps = sv.integer("steps", s.solver.steps, 0, 1'000'000'000);
    s.solver.iterations = sv.integer("iterations", s.solver.iterations, 0, 100000);
    s.solver.substeps = sv.integer("substeps", s.solver.substeps, 1, 100000);
    s.solver.thickness = sv.number("thickness", s.solver.thickness, 0);
    s.solver.kernel = sv.choice("kernel", s.solver.kernel, sweepKernelNames());
    s.solver.threads = sv.integer("threads", s.solver.threads, 0, 1024);
    if (isPositionBased(s.solver.method) && s.model != Model::Cloth)
        sv.fail("method", std::string("\"") + methodName(s.solver.method) + "\" needs model \"cloth\" (got \"" + model + "\")");
    sv.finish();
    if (s.self_collision.enabled && !isPositionBased(s.solver.method))
        r.fail("self_collision", std::string("works with method \"pbd\" or \"xpbd\" (got \"") + methodName(s.solver.method) + "\")");

    Reader pbd = r.object("pbd");
    s.pbd.damping = pbd.number("damping", s.pbd.damping, 0, 1);
    pbd.finish();

    Reader rep = r.object("report");
    s.report.every = rep.integer("every", s.report.every, 0, 1'000'000'000);
    s.report.blowup = rep.number("blowup", s.report.blowup, 0, INFINITY, true);
    rep.finish();

    Reader view = r.object("view");
    s.view.camera = view.has("eye");
    s.view.eye = view.vec3("eye", s.view.eye);
    s.view.target = view.vec3("target", s.view.target);
    s.view.fov = view.number("fov", s.view.fov, 1, 170);
    s.view.look = view.text("look", "");
    s.view.error = view.text("error", "");
    if (s.view.camera && (s.view.eye - s.view.target).norm() <= 0) view.fail("target", "equals view.eye");
    view.finish();
    r.finish();
    return s;
}

}  // namespace

Scene parseScene(const std::string& text, const std::string& file, const std::vector<std::string>& overrides) {
    if (text.size() > kMaxSceneBytes)
        throw InputError(file, "(file)", "larger than the limit of 16 MiB (" + std::to_string(text.size()) + " bytes)");
    json doc;
    try {
        doc = parseLimited(text, file, "(JSON syntax)", /*allow_exceptions=*/true);
    } catch (const json::exception& e) {  // syntax errors and numbers too large for a double
        throw InputError(file, "(JSON syntax)", std::string(e.what()).substr(std::string(e.what()).find(']') + 2));
    }
    for (const auto& kv : overrides) applyOverride(doc, kv, file);
    return readScene(doc, file);
}

Scene loadScene(const std::string& path, const std::vector<std::string>& overrides) {
    std::ifstream in(path);
    if (!in) throw InputError(path, "(file)", "cannot open the file");
    std::error_code ec;
    if (const std::uintmax_t n = std::filesystem::file_size(path, ec); !ec && n > kMaxSceneBytes)
        throw InputError(path, "(file)", "larger than the limit of 16 MiB (" + std::to_string(n) + " bytes)");
    std::stringstream buf;
    buf << in.rdbuf();
    return parseScene(buf.str(), path, overrides);
}

}  // namespace clothlab
