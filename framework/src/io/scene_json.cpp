// Scene loading: a small validating reader over nlohmann::json.
#include "clothlab/io/scene_json.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "clothlab/core/input_error.h"
#include "clothlab/sim/extensions.h"

namespace clothlab {
namespace {

using json = nlohmann::json;

std::string join(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& e : v) s += (s.empty() ? "" : ", ") + e;
    return s;
}

std::string describe(const json& j) {
    std::string s = j.dump();
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
        if (x < lo || x > hi) fail(key, "must be between " + std::to_string(lo) + " and " + std::to_string(hi) + " (got " + std::to_string(x) + ")");
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
    r.finish();
    return c;
}

/// Pins: indices, or names of corners and edges of the grid.
std::vector<int> readPins(Reader& r, const ClothSpec& c) {
    const json* v = r.get("pins");
    std::vector<int> pins;
    if (!v) return pins;
    if (!v->is_array()) r.fail("pins", "expected an array of indices or names (got " + describe(*v) + ")");
    const int nx = c.nx, ny = c.ny;
    for (size_t k = 0; k < v->size(); ++k) {
        const json& e = (*v)[k];
        const std::string key = "pins[" + std::to_string(k) + "]";
        if (e.is_number_integer()) {
            const long long i = e.get<long long>();
            if (i < 0 || i >= static_cast<long long>(nx) * ny)
                r.fail(key, "particle index " + std::to_string(i) + " outside the grid (0.." + std::to_string(nx * ny - 1) + ")");
            pins.push_back(static_cast<int>(i));
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

ClothSpec readCloth(Reader r) {
    ClothSpec c;
    c.nx = r.integer("nx", c.nx, 2, 4096);
    c.ny = r.integer("ny", c.ny, 2, 4096);
    if (static_cast<long long>(c.nx) * c.ny > 4'000'000) r.fail("ny", "grid too large (nx*ny > 4,000,000)");
    c.width = r.number("width", c.width, 0, INFINITY, true);
    c.height = r.number("height", c.height, 0, INFINITY, true);
    c.mass = r.number("mass", c.mass, 0, INFINITY, true);
    c.origin = r.vec3("origin", c.origin);
    c.horizontal = r.choice("orientation", "vertical", {"vertical", "horizontal"}) == "horizontal";
    c.tilt = r.number("tilt", c.tilt, -90, 90);
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

Collider readCollider(Reader r) {
    Collider c;
    const std::string type = r.choice("type", "", {"plane", "sphere"});
    if (type.empty()) r.fail("type", "missing (plane or sphere)");
    if (type == "plane") {
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

/// Sets a dotted key of the document to a value given on the command line.
void applyOverride(json& doc, const std::string& kv, const std::string& file) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0)
        throw InputError(file, kv, "--set expects key=value, e.g. solver.dt=0.01");
    const std::string key = kv.substr(0, eq), text = kv.substr(eq + 1);
    json value = json::parse(text, nullptr, /*allow_exceptions=*/false);
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
    s.solver.bendingKernel = sv.choice("bending_kernel", s.solver.bendingKernel, bendingSweepNames());
    s.solver.threads = sv.integer("threads", s.solver.threads, 0, 1024);
    if (isPositionBased(s.solver.method) && s.model != Model::Cloth)
        sv.fail("method", std::string("\"") + methodName(s.solver.method) + "\" needs model \"cloth\" (got \"" + model + "\")");
    sv.finish();

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
    if (s.view.camera && (s.view.eye - s.view.target).norm() <= 0) view.fail("target", "equals view.eye");
    view.finish();
    r.finish();
    return s;
}

}  // namespace

Scene parseScene(const std::string& text, const std::string& file, const std::vector<std::string>& overrides) {
    json doc;
    try {
        doc = json::parse(text);
    } catch (const json::exception& e) {  // syntax errors and numbers too large for a double
        throw InputError(file, "(JSON syntax)", std::string(e.what()).substr(std::string(e.what()).find(']') + 2));
    }
    for (const auto& kv : overrides) applyOverride(doc, kv, file);
    return readScene(doc, file);
}

Scene loadScene(const std::string& path, const std::vector<std::string>& overrides) {
    std::ifstream in(path);
    if (!in) throw InputError(path, "(file)", "cannot open the file");
    std::stringstream buf;
    buf << in.rdbuf();
    return parseScene(buf.str(), path, overrides);
}

}  // namespace clothlab
