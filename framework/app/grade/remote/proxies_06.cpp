// Stage 06 in the test process: each function forwards to the submission process (remote/peer.h).
#include "remote/functions.h"
#include "remote/peer.h"

namespace clothlab {

using remote::Invoke;
using remote::submissionProcess;

namespace {
/// The framework indexes particles with c.i: a constraint must be about the particle it was asked for.
bool checked(bool made, int i, const CollisionConstraint* out, const char* name) {
    if (made && out && out->i != i)
        throw std::out_of_range(std::string(name) + " set out->i = " + std::to_string(out->i) + ", not the particle i = " +
                                std::to_string(i) + " it was asked about");
    return made;
}
}  // namespace

bool generatePlaneConstraint(int i, const Vec3& x, const Vec3& p, const PlaneCollider& collider, double h, double dt,
                             CollisionConstraint* out) {
    return checked(Invoke<decltype(generatePlaneConstraint)>::call(submissionProcess(), remote::k_generatePlaneConstraint,
                                                                   "generatePlaneConstraint", i, x, p, collider, h, dt, out),
                   i, out, "generatePlaneConstraint");
}

bool generateSphereConstraint(int i, const Vec3& x, const Vec3& p, const SphereCollider& collider, double h, double dt,
                              CollisionConstraint* out) {
    return checked(Invoke<decltype(generateSphereConstraint)>::call(submissionProcess(), remote::k_generateSphereConstraint,
                                                                    "generateSphereConstraint", i, x, p, collider, h, dt, out),
                   i, out, "generateSphereConstraint");
}

Vec3 projectCollisionConstraint(const Vec3& p, double w, double h, const CollisionConstraint& c) {
    return Invoke<decltype(projectCollisionConstraint)>::call(submissionProcess(), remote::k_projectCollisionConstraint,
                                                              "projectCollisionConstraint", p, w, h, c);
}

void velocityUpdate(Matrix3X& v, const std::vector<CollisionConstraint>& contacts) {
    Invoke<decltype(velocityUpdate)>::call(submissionProcess(), remote::k_velocityUpdate, "velocityUpdate", v, contacts);
}

// The framework's sweeps over this stage's constraints, sent whole (remote/functions.h: 901–905).

void wrappedCollisionSweep(const std::vector<CollisionConstraint>& contacts, const VectorX& w, double h, Matrix3X& p, int) __asm__("__wrap__ZN8clothlab21projectCollisionSweepERKSt6vectorINS_19CollisionConstraintESaIS1_EERKN5Eigen6MatrixIdLin1ELi1ELi0ELin1ELi1EEEdRNS7_IdLi3ELin1ELi0ELi3ELin1EEEi");
void wrappedCollisionSweep(const std::vector<CollisionConstraint>& contacts, const VectorX& w, double h, Matrix3X& p, int) {
    Invoke<decltype(projectCollisionSweep)>::call(submissionProcess(), remote::k_projectCollisionSweep, "projectCollisionSweep", contacts, w, h, p, 1);  // serial: the sandbox makes no threads
}

}  // namespace clothlab
