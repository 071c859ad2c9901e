/// @file run.h
/// @brief Running a simulation for a number of steps, with instability detection and report rows.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "clothlab/sim/simulation.h"

namespace clothlab {

/// One row of the report time series.
struct ReportRow {
    long long step;               ///< steps done
    double t;                     ///< simulated time, s
    double wall;                  ///< wall time since the start, s
    std::vector<Metric> metrics;  ///< the scene's metrics at this time
};

/// What runSimulation() did.
struct RunResult {
    long long steps = 0;          ///< steps done
    double wall = 0.0;            ///< wall time of the steps, s
    bool unstable = false;        ///< stopped because the state blew up
    std::string message;          ///< "unstable at step N (t = ...): reason" when unstable
    std::vector<ReportRow> rows;  ///< one row every `every` steps and one at the end
};

/// Why a state can no longer be trusted, or "" when it can: a position or velocity is NaN or
/// infinite, or a particle left the ball |x| < bound (report.blowup). The one instability check of
/// every program (run, render, app, studies).
/// @param s      the state
/// @param bound  radius of the region the particles must stay in, m
std::string instabilityReason(const State& s, double bound);

/// Takes one step and checks it: "" when the step went well, else the one message every program
/// prints, "unstable at step N (t = T s): <reason>", for a blow-up (instabilityReason()) or a step
/// the method could not take (SolverFailure).
/// @param sim    the simulation
/// @param step   the number of this step (1 for the first), for the message
/// @param bound  radius of the region the particles must stay in, m
std::string stepAndCheck(Simulation& sim, long long step, double bound);

/// stepAndCheck() with the scene's own bound, report.blowup.
/// @param sim   the simulation
/// @param step  the number of this step (1 for the first), for the message
inline std::string stepAndCheck(Simulation& sim, long long step) {
    return stepAndCheck(sim, step, sim.scene().report.blowup);
}

/// Steps `steps` times (or until the state turns NaN/Inf or leaves the ball of radius
/// scene.report.blowup), recording a report row every `every` steps.
/// @param sim     the simulation
/// @param steps   number of steps
/// @param every   report interval in steps (≥ 1)
/// @param on_row  called with each row as it is recorded (progress output); may be empty
RunResult runSimulation(Simulation& sim, long long steps, long long every,
                        const std::function<void(const ReportRow&)>& on_row = {});

}  // namespace clothlab
