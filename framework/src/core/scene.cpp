#include "clothlab/core/scene.h"

namespace clothlab {

const char* modelName(Model m) {
    switch (m) {
        case Model::Spring: return "spring";
        case Model::Chain: return "chain";
        case Model::Cloth: return "cloth";
    }
    return "?";
}

const char* methodName(Method m) {
    switch (m) {
        case Method::ExplicitEuler: return "explicit_euler";
        case Method::SymplecticEuler: return "symplectic_euler";
        case Method::VelocityVerlet: return "velocity_verlet";
        case Method::Rk4: return "rk4";
        case Method::ImplicitEuler: return "implicit_euler";
        case Method::Pbd: return "pbd";
        case Method::Xpbd: return "xpbd";
    }
    return "?";
}

const char* colliderTypeName(Collider::Type t) {
    switch (t) {
        case Collider::Type::Plane: return "plane";
        case Collider::Type::Sphere: return "sphere";
        case Collider::Type::Box: return "box";
        case Collider::Type::Capsule: return "capsule";
        case Collider::Type::Mesh: return "mesh";
    }
    return "?";
}

const std::vector<Method>& allMethods() {
    static const std::vector<Method> all = {Method::ExplicitEuler, Method::SymplecticEuler, Method::VelocityVerlet,
                                            Method::Rk4,           Method::ImplicitEuler,   Method::Pbd,
                                            Method::Xpbd};
    return all;
}

std::optional<Method> parseMethod(const std::string& name) {
    for (Method m : allMethods())
        if (name == methodName(m)) return m;
    return std::nullopt;
}

bool isPositionBased(Method m) { return m == Method::Pbd || m == Method::Xpbd; }

}  // namespace clothlab
