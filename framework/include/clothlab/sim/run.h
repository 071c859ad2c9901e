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

/// Steps `steps` times (or until the state turns NaN/Inf or leaves the ball of radius
/// scene.report.blowup), recording a report row every `every` steps.
/// @param sim     the simulation
/// @param steps   number of steps
/// @param every   report interval in steps (≥ 1)
/// @param on_row  called with each row as it is recorded (progress output); may be empty
RunResult runSimulation(Simulation& sim, long long steps, long long every,
                        const std::function<void(const ReportRow&)>& on_row = {});

}  // namespace clothlab
