#include "clothlab/sim/colliders.h"

namespace clothlab {

double colliderDistance(const Collider& c, const Vec3& x) {
    switch (c.type) {
        case Collider::Type::Plane: return (x - c.point).dot(c.normal);
        case Collider::Type::Sphere: return (x - c.point).norm() - c.radius;
    }
    return 0.0;
}

}  // namespace clothlab
