/// @file pass_timer.h
/// @brief Wall-clock time per pass of a step, for the run report, with scoped self-nesting timers.
///
/// A simulation registers only the passes its scene uses, so the report's timing table lists
/// exactly what ran. A pass is timed by a scope: `{ auto t = timer.time(id); ... }`. Scopes nest:
/// time spent in an inner scope (the force pass inside an integrator, the constraint sweep inside
/// the PBD step) is booked on the inner pass only, so the passes add up to the wall time.
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
        double seconds = 0.0;  ///< wall time spent in the pass itself (not in passes nested in it), s
        long long calls = 0;   ///< how often it ran
    };

    /// Times one run of a pass from its construction to its destruction. Not copyable, not movable.
    class Scope {
    public:
        /// Starts timing pass `id` of `timer`, inside whatever scope of that timer is open.
        Scope(PassTimer& timer, int id) : timer_(timer), id_(id), outer_(timer.open_), start_(Clock::now()) {
            timer.open_ = this;
        }
        /// Books the elapsed time minus that of nested scopes on the pass, and the elapsed time
        /// as nested time on the enclosing scope.
        ~Scope() {
            const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
            Pass& pass = timer_.passes_[static_cast<size_t>(id_)];
            pass.seconds += elapsed - nested_;
            ++pass.calls;
            if (outer_) outer_->nested_ += elapsed;
            timer_.open_ = outer_;
        }
        Scope(const Scope&) = delete;             ///< not copyable
        Scope& operator=(const Scope&) = delete;  ///< not assignable

    private:
        using Clock = std::chrono::steady_clock;
        PassTimer& timer_;
        int id_;
        Scope* outer_;               ///< the scope this one is nested in, or null
        Clock::time_point start_;
        double nested_ = 0.0;        ///< wall time of scopes nested in this one, s
    };

    /// Registers a pass (or finds it) and returns its id for time().
    int add(const std::string& name) {
        for (size_t i = 0; i < passes_.size(); ++i)
            if (passes_[i].name == name) return static_cast<int>(i);
        passes_.push_back({name, 0.0, 0});
        return static_cast<int>(passes_.size()) - 1;
    }
    /// Starts timing pass `id` until the returned scope ends: `auto t = timer.time(id);`.
    [[nodiscard]] Scope time(int id) { return Scope(*this, id); }
    /// All registered passes in registration order.
    const std::vector<Pass>& passes() const { return passes_; }
    /// Sets every pass's time and count to zero.
    void reset() {
        for (auto& p : passes_) p.seconds = 0.0, p.calls = 0;
    }

private:
    std::vector<Pass> passes_;
    Scope* open_ = nullptr;  ///< the innermost open scope
};

}  // namespace clothlab
