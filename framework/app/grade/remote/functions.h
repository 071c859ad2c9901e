// Every function a stage's submission implements, with the number that names it on the wire.
// The submission process serves all of them (remote/serve_main.cpp); the test process calls those
// of the stages whose code comes from the submission (proxies_NN.cpp, which the build generates
// from the stage headers with remote/make_proxies.cpp, like the list stage_functions.h).
//
// 901–906 are the framework's sweeps (sim/sweeps.h): loops that call a stage's function once per
// constraint, many times per step. When that stage's code is the submission's, the test process
// sends the whole sweep (one call per iteration, not one per constraint): remote/sweeps_NN.cpp define
// the sweeps again, and the framework's own are weak (sim/sweeps.cpp). The result is the positions the
// submission's function produces either way; the sweep adds nothing the submission could not do.
#pragma once
#include <cstdint>

#include "clothlab/sim/sweeps.h"
#include "stage_functions.h"  // generated

#define CLOTHLAB_REMOTE_FUNCTIONS(X)                                                                   \
    CLOTHLAB_STAGE_FUNCTIONS(X)                                                                        \
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
