// A submission written to test the submission process (submission_process_test.cpp): every function of the seven
// stages, each doing what a scenario of the test asks for (a computation, a crash, an exception, a
// forbidden system call, a forged reply, a wrong-sized result, calls of its callbacks).
#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/01_hooke.h"
#include "clothlab/exercise/02_mfn.h"
#include "clothlab/exercise/03_pbd_loop.h"
#include "clothlab/exercise/04_distance.h"
#include "clothlab/exercise/05_bending.h"
#include "clothlab/exercise/06_collision.h"
#include "clothlab/exercise/07_self_collision.h"
#include "clothlab/sim/sweeps.h"
#include "clothlab/sim/team.h"

namespace clothlab {

namespace {
/// The result of a system call the seccomp filter should refuse: (return value, errno, 0).
Vec3 attempt(long result) { return {static_cast<double>(result), static_cast<double>(errno), 0.0}; }
}  // namespace

/// k selects the scenario; l0 is a parameter of it.
Vec3 hookeForce(const Vec3& p0, const Vec3& p1, double k, double l0) {
    static int calls = 0;  // state survives between calls of one process
    ++calls;
    switch (static_cast<int>(k)) {
        case 1: return p0 + 2.0 * p1 + Vec3(l0, 0, 0);
        case 2: ::raise(SIGSEGV); return {};
        case 3: throw NotImplemented("1.1 hookeForce");
        case 4: throw std::invalid_argument("l0 must be positive");
        case 5: return attempt(::open("/etc/hostname", O_RDONLY));
        case 6: return attempt(::kill(::getppid(), SIGKILL));
        case 7: return attempt(::fork());
        case 8: {  // a forged reply on the reply pipe, then a real one
            const char junk[] = "end Suite.Test passed 0123456789abcdef\nexit 0123456789abcdef\n";
            if (::write(4, junk, sizeof junk) < 0) return {};
            return {};
        }
        case 9: return {static_cast<double>(calls), 0, 0};
        case 10: ::_exit(3);
        default: return {};
    }
}

Vec3 springDampingForce(const Vec3&, const Vec3&, const Vec3&, const Vec3&, double) { throw NotImplemented("1.2"); }

/// dt selects the scenario: 1: call the force twice and step x by the force; 2: resize x;
/// 3: call the force with a matrix of another size.
void explicitEulerStep(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt) {
    Matrix3X f = Matrix3X::Zero(3, x.cols());
    if (dt == 1) {
        force(x, v, f);
        force(x, v, f);
        x += f;
        v.array() += w.sum();
    } else if (dt == 2) {
        x.resize(3, x.cols() + 1);
    } else if (dt == 3) {
        Matrix3X bigger = Matrix3X::Zero(3, x.cols() + 5);
        force(bigger, bigger, bigger);
    } else if (dt == 4) {
        try {
            force(x, v, f);
        } catch (const std::exception& e) {
            x.setConstant(static_cast<double>(std::strlen(e.what())));
            throw;
        }
    }
}
void symplecticEulerStep(Matrix3X&, Matrix3X&, const VectorX&, const ForceField&, double) { throw NotImplemented("1.4"); }
void velocityVerletStep(Matrix3X&, Matrix3X&, const VectorX&, const ForceField&, double) { throw NotImplemented("1.5"); }

/// nx selects the scenario: 1: two good springs; 2: a spring to a particle that does not exist.
std::vector<Spring> makeClothSprings(const Matrix3X& x, int nx, int, const ClothSprings& types) {
    Spring s;
    s.i = 0;
    s.j = static_cast<int>(x.cols()) - 1;
    s.k = types.structural.k;
    s.type = SpringType::Shear;
    if (nx == 2) s.j = 1000000;
    return {s, s};
}
void addClothSpringForces(const std::vector<Spring>&, const Matrix3X&, const Matrix3X&, Matrix3X&) { throw NotImplemented("2.2"); }
void addClothExternalForces(const VectorX&, const Matrix3X&, const Vec3&, double, Matrix3X&) { throw NotImplemented("2.3"); }

void dampVelocities(const Matrix3X&, Matrix3X&, const VectorX&, double) { throw NotImplemented("3.1"); }
double iterationStiffness(double, int) { throw NotImplemented("3.2"); }
/// Says which of the other callbacks are set (P.t = 1, 10, 100 for each) and lets projectConstraints move x.
void pbdStep(PbdParticles& P, const PbdCallbacks& cb, double, int, double) {
    P.t = (cb.externalForces ? 1 : 0) + (cb.generateCollisionConstraints ? 10 : 0) + (cb.velocityUpdate ? 100 : 0);
    Matrix3X moved = P.x;
    if (cb.projectConstraints) cb.projectConstraints(moved);
    P.x = moved;
}

double distanceConstraint(const Vec3& p1, const Vec3& p2, double d) { return (p1 - p2).norm() - d; }
Vec3 distanceGradient(const Vec3&, const Vec3&) { throw NotImplemented("4.2"); }
DistanceCorrection projectDistanceConstraint(const Vec3&, const Vec3&, double, double, double, double) { throw NotImplemented("4.3"); }
std::vector<int> tetherAnchors(const Matrix3X&, const VectorX&) { throw NotImplemented("4.4"); }
Vec3 projectTether(const Vec3&, const Vec3&, double) { throw NotImplemented("4.4"); }

BendingGradients bendingGradients(const Vec3&, const Vec3&, const Vec3&, const Vec3&) { throw NotImplemented("5.1"); }
BendingCorrection projectBendingConstraint(const Vec3&, const Vec3&, const Vec3&, const Vec3&, double, double, double,
                                           double, double, double) {
    throw NotImplemented("5.2");
}
/// One stencil; with two triangles it names a particle that does not exist.
std::vector<BendingStencil> bendingStencils(const std::vector<Eigen::Vector3i>& triangles, const Matrix3X& x) {
    BendingStencil s;
    s.i4 = triangles.size() == 2 ? static_cast<int>(x.cols()) : 0;
    return {s};
}

/// i selects the scenario: i = 5: a good contact; i = 6: a contact about particle 0 instead.
bool generatePlaneConstraint(int i, const Vec3&, const Vec3& p, const PlaneCollider& collider, double h, double,
                             CollisionConstraint* out) {
    if (!out) return false;
    out->i = i;
    out->q = p - h * collider.normal;
    out->n = collider.normal;
    out->friction = collider.friction;
    return true;
}
bool generateSphereConstraint(int, const Vec3&, const Vec3&, const SphereCollider&, double, double, CollisionConstraint*) {
    throw NotImplemented("6.2");
}
Vec3 projectCollisionConstraint(const Vec3&, double, double, const CollisionConstraint&) { throw NotImplemented("6.3"); }
void velocityUpdate(Matrix3X& v, const std::vector<CollisionConstraint>& contacts) {
    for (const auto& c : contacts) v.col(c.i) = c.n;
}

Eigen::Vector3i cellOf(const Vec3&, double) { throw NotImplemented("7.1"); }
int hashCell(const Eigen::Vector3i&, int) { throw NotImplemented("7.2"); }
SpatialHash buildSpatialHash(const Matrix3X&, double, int) { throw NotImplemented("7.3"); }
std::vector<ParticlePair> findNeighbourPairs(const Matrix3X& p, const SpatialHash&, double) {
    return {{0, static_cast<int>(p.cols()) - 1}, {0, static_cast<int>(p.cols())}};  // the second names no particle
}
PairCorrection projectSeparation(const Vec3&, const Vec3&, double, double, double) { throw NotImplemented("7.5"); }
PairCorrection layerFriction(const Vec3&, const Vec3&, const Vec3&, const Vec3&, double, double, double, double) {
    throw NotImplemented("7.6");
}

/// The framework's distance sweep, replaced here too (sim/sweeps.cpp defines it weak): every position
/// becomes 42 when the sweep arrives whole and runs serially here (submission_process_test.cpp ASweepCrossesWhole).
void projectDistanceSweep(const std::vector<DistanceLink>&, const VectorX&, double, Matrix3X& p, const SweepPlan& plan) {
    p.setConstant(teamThreads(plan.threads) == 1 ? 42.0 : -1.0);
}

}  // namespace clothlab
