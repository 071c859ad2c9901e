#include "clothlab/sim/run.h"

#include <chrono>
#include <sstream>

namespace clothlab {

std::string instabilityReason(const State& s, double bound) {
    if (!s.x.allFinite()) return "position is NaN or infinite";
    if (!s.v.allFinite()) return "velocity is NaN or infinite";
    if (s.x.size() > 0 && s.x.colwise().norm().maxCoeff() > bound) {
        std::ostringstream m;
        m << "a particle left the region |x| < " << bound << " m (report.blowup)";
        return m.str();
    }
    return "";
}

std::string stepAndCheck(Simulation& sim, long long step, double bound) {
    std::string why;
    try {
        sim.step();
        why = instabilityReason(sim.state(), bound);
    } catch (const SolverFailure& e) {
        why = e.what();
    }
    if (why.empty()) return why;
    std::ostringstream m;
    m << "unstable at step " << step << " (t = " << sim.state().t << " s): " << why;
    return m.str();
}

RunResult runSimulation(Simulation& sim, long long steps, long long every,
                        const std::function<void(const ReportRow&)>& on_row) {
    RunResult result;
    const auto t0 = std::chrono::steady_clock::now();
    auto record = [&] {
        ReportRow row{result.steps, sim.state().t, result.wall, sim.metrics()};
        if (on_row) on_row(row);
        result.rows.push_back(std::move(row));
    };
    record();
    while (result.steps < steps) {
        const std::string unstable = stepAndCheck(sim, result.steps + 1);
        ++result.steps;
        result.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (!unstable.empty()) {
            result.unstable = true;
            result.message = unstable;
            return result;  // no metrics of a broken state
        }
        if (result.steps % every == 0 || result.steps == steps) record();
    }
    return result;
}

}  // namespace clothlab
