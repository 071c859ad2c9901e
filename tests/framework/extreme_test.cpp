// Extreme cases: the matrix of `clothlab study extremes` (study/extremes.h) in a small version on
// every ./lab test: k from 1 to 1e9 N/m, dt from 1e-5 to 1 s, mass ratios of 1e6, zero-length
// springs, coincident particles, zero-area triangles, folded and flat dihedrals, all-pinned
// stencils, PBD iterations 1 to 1000, XPBD compliance 0 to 1. No cell may be silently wrong (NaN or
// Inf in the state or the report without a message, a collider passed through without a flag, the
// energy past E(0) + 100 E_scale without a word): a run either ends fine, ends with a warning, or
// stops with "unstable at step N (t = ...)". Implicit Euler stays bounded in every case.
#include <cmath>
#include <cstdio>
#include <sstream>

#include <gtest/gtest.h>

#include "clothlab/sim/run.h"
#include "clothlab/study/extremes.h"

using namespace clothlab;

namespace {

std::string num(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
}

const std::vector<ExtremeCase>& cases() {
    static const std::vector<ExtremeCase> c = extremeCases(std::string(CLOTHLAB_SOURCE_DIR) + "/scenes");
    return c;
}

// The small matrix for one method: 4 values of its axis x 4 time steps x every case that applies, 40 steps.
void runMatrix(Method method) {
    ExtremesOptions o;
    o.methods = {method};
    o.ks = {1, 1e3, 1e6, 1e9};
    o.dts = {1e-5, 1e-3, 1e-1, 1};
    o.iterations = {1, 10, 100, 1000};
    o.compliances = {0, 1e-6, 1e-3, 1};
    o.steps = 40;
    int count[4] = {0, 0, 0, 0};
    for (const ExtremeCell& c : extremesStudy(cases(), o)) {
        const std::string what = c.case_name + ", " + methodName(method) + ", " + extremeAxis(method) + " " + num(c.p) + ", dt = " + num(c.dt) + " s";
        ++count[static_cast<int>(c.outcome)];
        EXPECT_NE(c.outcome, ExtremeOutcome::SilentlyWrong) << what << ": " << c.message;
        if (c.outcome == ExtremeOutcome::Stopped) {
            EXPECT_EQ(c.message.rfind("unstable at step ", 0), 0u) << what << ": " << c.message;
            EXPECT_NE(c.message.find("(t = "), std::string::npos) << what << ": " << c.message;
            EXPECT_NE(method, Method::ImplicitEuler) << what << ": implicit Euler must stay bounded: " << c.message;
        }
        if (c.outcome == ExtremeOutcome::Warned) {
            EXPECT_GT(c.step, 0) << what << ": a warning names its step";
        }
    }
    std::printf("%s: %d stable, %d warned, %d stopped, %d silently wrong\n", methodName(method), count[0], count[2], count[1], count[3]);
}

// A stand-in simulation of one particle whose step does what a test plants.
class Planted : public Simulation {
public:
    Planted(const Scene& scene, std::function<void(State&, double&)> step) : Simulation(scene), plant_(std::move(step)) {
        s_.resize(1);
        s_.x.col(0) = Vec3(0, 1, 0);
        s_.v.col(0) = Vec3(1, 0, 0);
        initMeasures();
    }
    void step() override {
        plant_(s_, metric_);
        s_.t += scene_.solver.dt;
    }
    const State& state() const override { return s_; }
    State& state() override { return s_; }

protected:
    void addMetrics(std::vector<Metric>& m) const override { m.push_back({"planted", metric_, "1"}); }

private:
    State s_;
    double metric_ = 0.0;
    std::function<void(State&, double&)> plant_;
};

}  // namespace

TEST(Extreme, ExplicitEulerFiniteOrAnnounced) { runMatrix(Method::ExplicitEuler); }
TEST(Extreme, SymplecticEulerFiniteOrAnnounced) { runMatrix(Method::SymplecticEuler); }
TEST(Extreme, VelocityVerletFiniteOrAnnounced) { runMatrix(Method::VelocityVerlet); }
TEST(Extreme, Rk4FiniteOrAnnounced) { runMatrix(Method::Rk4); }
TEST(Extreme, ImplicitEulerNeverStops) { runMatrix(Method::ImplicitEuler); }
TEST(Extreme, PbdFiniteOrAnnounced) { runMatrix(Method::Pbd); }
TEST(Extreme, XpbdFiniteOrAnnounced) { runMatrix(Method::Xpbd); }

// Bounded: implicit Euler's energy never rises by more than the system could gain by falling its own
// extent plus 1 m. (It is not monotone: one linearised Newton step per time step stretches links
// that rotate a lot within a step; the run checks then warn "energy grew".) One case breaks the
// bound, found by the extremes matrix: a chain of masses 1/sqrt(1000) and sqrt(1000) kg at dt = 1 s
// and k >= 1e6 N/m gains up to 1e8 J within 10 steps before it falls back; there the run must carry
// the "energy grew" warning, so it is reported, not silently wrong.
TEST(Extreme, ImplicitEulerBoundedInEveryCase) {
    for (const ExtremeCase& c : cases()) {
        if (c.position_based) continue;
        for (double k : {1.0, 1e3, 1e6, 1e9})
            for (double dt : {1e-5, 1e-3, 1e-1, 1.0}) {
                const std::string what = c.name + ", k = " + num(k) + " N/m, dt = " + num(dt) + " s";
                auto sim = c.make(Method::ImplicitEuler, k, dt);
                const State s0 = sim->state();
                double mass = 0.0;
                for (int i = 0; i < s0.size(); ++i) mass += s0.w[i] > 0 ? 1.0 / s0.w[i] : 0.0;
                const double extent = (s0.x.rowwise().maxCoeff() - s0.x.rowwise().minCoeff()).norm();
                const RunResult r = runSimulation(*sim, 40, 10);
                ASSERT_FALSE(r.unstable) << what << ": " << r.message;
                const double e0 = r.rows.front().metrics[0].value;
                const double allowed = e0 + mass * 9.81 * (extent + 1.0) + 1e-6 * std::abs(e0);
                bool warned = false;
                for (const RunWarning& w : r.warnings) warned = warned || w.kind == WarningKind::EnergyGrowth;
                const bool known = c.name == "chain, mass ratio 1000";
                for (const ReportRow& row : r.rows) {
                    if (known && warned) continue;
                    EXPECT_LE(row.metrics[0].value, allowed) << what << ": energy rose at step " << row.step << " from " << e0 << " to "
                                                             << row.metrics[0].value << (known ? " without an \"energy grew\" warning" : "");
                }
            }
    }
}

// The classification can say "silently wrong": a NaN metric with a finite state, and an energy that
// doubles every step in a scene with wind (which the run checks do not judge: wind brings energy in),
// are silently wrong; the same growth without wind is warned.
TEST(Extreme, ClassifierCatchesSilentlyWrongRuns) {
    Scene scene;
    scene.solver.dt = 0.01;
    Planted nan(scene, [](State&, double& metric) { metric = NAN; });
    const ExtremeCell a = classifyExtremeRun(nan, 10);
    EXPECT_EQ(a.outcome, ExtremeOutcome::SilentlyWrong) << "a NaN metric without a stop: " << a.message;
    EXPECT_NE(a.message.find("planted"), std::string::npos) << a.message;

    auto doubling = [](State& s, double&) { s.v *= 2.0; };  // kinetic energy x 4 per step, positions kept
    Scene windy = scene;
    windy.forces.wind = Vec3(5, 0, 0);
    Planted grows(windy, doubling);
    const ExtremeCell b = classifyExtremeRun(grows, 10);
    EXPECT_EQ(b.outcome, ExtremeOutcome::SilentlyWrong) << "energy x 4^10 without a word: " << b.message;
    Planted warned(scene, doubling);
    const ExtremeCell c = classifyExtremeRun(warned, 10);
    EXPECT_EQ(c.outcome, ExtremeOutcome::Warned) << c.message;
    EXPECT_EQ(c.step, 1) << "kinetic energy 0.5 J x 4 after step 1: 1.5 J > 0.1 E_scale = 0.1 max(|E0|, m g L) ≈ 1.03 J";
}
