// Every function a stage's submission implements, with the number that names it on the wire.
// The submission process serves all of them (remote/serve_main.cpp); the test process calls those
// of the stages whose code comes from the submission (remote/proxies_NN.cpp).
//
// 901–906 are the framework's sweeps (sim/sweeps.h): loops that call a stage's function once per
// constraint, many times per step. When that stage's code is the submission's, the test process
// sends the whole sweep (one call per iteration, not one per constraint): the proxies define
// __wrap_<sweep>, and the grader links with -Wl,--wrap=<sweep>. The result is the positions the
// submission's function produces either way; the sweep adds nothing the submission could not do.
#pragma once
#include <cstdint>

#include "clothlab/sim/sweeps.h"

#define CLOTHLAB_REMOTE_FUNCTIONS(X)                                                                   \
    X(101, hookeForce)                                                                                 \
    X(102, springDampingForce)                                                                         \
    X(103, explicitEulerStep)                                                                          \
    X(104, symplecticEulerStep)                                                                        \
    X(105, velocityVerletStep)                                                                         \
    X(201, makeClothSprings)                                                                           \
    X(202, addClothSpringForces)                                                                       \
    X(203, addClothExternalForces)                                                                     \
    X(301, dampVelocities)                                                                             \
    X(302, iterationStiffness)                                                                         \
    X(303, pbdStep)                                                                                    \
    X(401, distanceConstraint)                                                                         \
    X(402, distanceGradient)                                                                           \
    X(403, projectDistanceConstraint)                                                                  \
    X(501, bendingGradients)                                                                           \
    X(502, projectBendingConstraint)                                                                   \
    X(503, bendingStencils)                                                                            \
    X(601, generatePlaneConstraint)                                                                    \
    X(602, generateSphereConstraint)                                                                   \
    X(603, projectCollisionConstraint)                                                                 \
    X(604, velocityUpdate)                                                                             \
    X(701, cellOf)                                                                                     \
    X(702, hashCell)                                                                                   \
    X(703, buildSpatialHash)                                                                           \
    X(704, findNeighbourPairs)                                                                         \
    X(705, projectSeparation)                                                                          \
    X(706, layerFriction)                                                                              \
    X(901, projectDistanceSweep)                                                                       \
    X(902, projectDistanceSweepXpbd)                                                                   \
    X(903, projectBendingSweep)                                                                        \
    X(904, projectBendingSweepXpbd)                                                                    \
    X(905, projectCollisionSweep)                                                                      \
    X(906, projectSelfCollisionSweep)

namespace clothlab {
/// The plan a sweep runs with in the submission's process: serial (its sandbox allows no threads;
/// the colour groups give the same positions bit for bit either way).
inline SweepPlan serialPlan(const SweepPlan& plan) { return {plan.groups, 1}; }
}  // namespace clothlab

namespace clothlab::remote {
#define CLOTHLAB_REMOTE_ID(id, name) k_##name = id,
enum Function : uint32_t { CLOTHLAB_REMOTE_FUNCTIONS(CLOTHLAB_REMOTE_ID) };
#undef CLOTHLAB_REMOTE_ID
}  // namespace clothlab::remote
