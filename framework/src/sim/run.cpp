#include "clothlab/sim/run.h"

#include <chrono>
#include <sstream>

namespace clothlab {
namespace {
/// Why the state is not usable any more, or "" when it is fine.
std::string instability(const State& s, double bound) {
    if (!s.x.allFinite()) return "position is NaN or infinite";
    if (!s.v.allFinite()) return "velocity is NaN or infinite";
    if (s.x.size() > 0 && s.x.colwise().norm().maxCoeff() > bound) {
        std::ostringstream m;
        m << "a particle left the region |x| < " << bound << " m";
        return m.str();
    }
    return "";
}
}  // namespace

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
        sim.step();
        ++result.steps;
        result.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const std::string why = instability(sim.state(), sim.scene().report.blowup);
        if (!why.empty()) {
            std::ostringstream m;
            m << "unstable at step " << result.steps << " (t = " << sim.state().t << " s): " << why;
            result.unstable = true;
            result.message = m.str();
            return result;  // no metrics of a broken state
        }
        if (result.steps % every == 0 || result.steps == steps) record();
    }
    return result;
}

}  // namespace clothlab
