// Every function a stage's submission implements, with the number that names it on the wire.
// The submission process serves all of them (remote/serve_main.cpp); the test process calls those
// of the stages whose code comes from the submission (remote/proxies_NN.cpp).
#pragma once
#include <cstdint>

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
    X(604, velocityUpdate)

namespace clothlab::remote {
#define CLOTHLAB_REMOTE_ID(id, name) k_##name = id,
enum Function : uint32_t { CLOTHLAB_REMOTE_FUNCTIONS(CLOTHLAB_REMOTE_ID) };
#undef CLOTHLAB_REMOTE_ID
}  // namespace clothlab::remote
