/// @file pass_timer.h
/// @brief Wall-clock time per pass of a step, for the run report.
///
/// A simulation registers only the passes its scene uses, so the report's timing
/// table lists exactly what ran.
#pragma once
#include <chrono>
#include <string>
#include <vector>

namespace clothlab {

/// Accumulates wall time and call counts per named pass.
class PassTimer {
public:
    /// One named pass.
    struct Pass {
        std::string name;      ///< e.g. "forces: springs"
        double seconds = 0.0;  ///< total wall time, s
        long long calls = 0;   ///< how often it ran
    };
    /// Registers a pass (or finds it) and returns its id for run().
    int add(const std::string& name) {
        for (size_t i = 0; i < passes_.size(); ++i)
            if (passes_[i].name == name) return static_cast<int>(i);
        passes_.push_back({name, 0.0, 0});
        return static_cast<int>(passes_.size()) - 1;
    }
    /// Runs f() and books its wall time on pass id.
    template <class F>
    void run(int id, F&& f) {
        const auto t0 = std::chrono::steady_clock::now();
        f();
        const auto t1 = std::chrono::steady_clock::now();
        passes_[static_cast<size_t>(id)].seconds += std::chrono::duration<double>(t1 - t0).count();
        ++passes_[static_cast<size_t>(id)].calls;
    }
    /// Subtracts time already booked on nested passes (e.g. forces inside an integrator).
    void subtract(int id, double seconds) { passes_[static_cast<size_t>(id)].seconds -= seconds; }
    /// All registered passes in registration order.
    const std::vector<Pass>& passes() const { return passes_; }
    /// Sets every pass's time and count to zero.
    void reset() {
        for (auto& p : passes_) p.seconds = 0.0, p.calls = 0;
    }

private:
    std::vector<Pass> passes_;
};

}  // namespace clothlab
