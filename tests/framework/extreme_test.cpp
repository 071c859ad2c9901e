// Extreme cases: k from 1 to 1e9 N/m, dt from 1e-5 to 1 s, mass ratios of 1e6, zero-length springs,
// coincident particles. No NaN or Inf may reach the state or the report unannounced: a run either
// ends finite or stops with "unstable at step N (t = ...)". Implicit Euler stays bounded in every case.
#include <cmath>

#include <gtest/gtest.h>

#include "clothlab/io/scene_json.h"
#include "clothlab/sim/mass_spring.h"
#include "clothlab/sim/run.h"

using namespace clothlab;

namespace {

Scene load(const std::string& name, const std::vector<std::string>& sets) {
    return loadScene(std::string(CLOTHLAB_SOURCE_DIR) + "/scenes/" + name, sets);
}

std::string num(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
}

// One case of the matrix: a name and a factory for the simulation at (method, k, dt).
struct Case {
    std::string name;
    std::function<std::unique_ptr<Simulation>(const std::string&, double, double)> make;
};

std::vector<std::string> solverSets(const std::string& method, double dt) {
    return {"solver.method=" + method, "solver.dt=" + num(dt)};
}

std::vector<Case> cases() {
    std::vector<Case> c;
    c.push_back({"single spring", [](const std::string& m, double k, double dt) {
                     auto s = solverSets(m, dt);
                     s.push_back("spring.k=" + num(k));
                     return makeSimulation(load("spring.json", s));
                 }});
    c.push_back({"chain, masses 1e-3 and 1e3 kg (ratio 1e6)", [](const std::string& m, double k, double dt) {
                     auto s = solverSets(m, dt);
                     s.insert(s.end(), {"chain.k=" + num(k), "chain.particles=6"});
                     const Scene sc = load("chain.json", s);
                     MassSpringModel model = makeChain(sc.chain);
                     for (int i = 1; i < model.state.size(); ++i) model.state.w[i] = i % 2 ? 1e3 : 1e-3;  // w = 1/m
                     return std::unique_ptr<Simulation>(new MassSpringSimulation(sc, model));
                 }});
    c.push_back({"chain of zero-length springs, all particles coincident", [](const std::string& m, double k, double dt) {
                     auto s = solverSets(m, dt);
                     s.insert(s.end(), {"chain.k=" + num(k), "chain.l0=0", "chain.particles=5"});
                     return makeSimulation(load("chain.json", s));
                 }});
    c.push_back({"chain with two coincident particles (l0 > 0)", [](const std::string& m, double k, double dt) {
                     auto s = solverSets(m, dt);
                     s.insert(s.end(), {"chain.k=" + num(k), "chain.particles=5"});
                     const Scene sc = load("chain.json", s);
                     MassSpringModel model = makeChain(sc.chain);
                     model.state.x.col(3) = model.state.x.col(2);
                     return std::unique_ptr<Simulation>(new MassSpringSimulation(sc, model));
                 }});
    c.push_back({"4 x 4 cloth", [](const std::string& m, double k, double dt) {
                     auto s = solverSets(m, dt);
                     s.insert(s.end(), {"cloth.nx=4", "cloth.ny=4", "springs.structural.k=" + num(k), "springs.shear.k=" + num(k / 2),
                                        "springs.bending.k=" + num(k / 10)});
                     return makeSimulation(load("mfn_hanging.json", s));
                 }});
    return c;
}

bool finiteMetrics(const RunResult& r) {
    for (const ReportRow& row : r.rows)
        for (const Metric& m : row.metrics)
            if (!std::isfinite(m.value)) return false;
    return true;
}

void runMatrix(const std::string& method) {
    int runs = 0, unstable = 0;
    for (const Case& c : cases())
        for (double k : {1.0, 1e3, 1e6, 1e9})
            for (double dt : {1e-5, 1e-3, 1e-1, 1.0}) {
                const std::string what = c.name + ", " + method + ", k = " + num(k) + " N/m, dt = " + num(dt) + " s";
                auto sim = c.make(method, k, dt);
                const RunResult r = runSimulation(*sim, 40, 10);
                ++runs;
                if (r.unstable) {
                    ++unstable;
                    EXPECT_EQ(r.message.rfind("unstable at step ", 0), 0u) << what << ": " << r.message;
                    EXPECT_NE(r.message.find("(t = "), std::string::npos) << what << ": " << r.message;
                    EXPECT_NE(method, "implicit_euler") << what << ": implicit Euler must stay bounded: " << r.message;
                } else {
                    EXPECT_TRUE(sim->state().isFinite()) << what << ": NaN/Inf in the state, unannounced";
                    EXPECT_TRUE(finiteMetrics(r)) << what << ": NaN/Inf in the report, unannounced";
                    EXPECT_EQ(r.steps, 40) << what;
                }
                if (method == "implicit_euler" && !r.rows.empty()) {
                    // Bounded: the energy never rises by more than the system could gain by falling
                    // its own extent plus 1 m. (It is not monotone: one linearised Newton step per
                    // time step stretches links that rotate a lot within a step.)
                    const auto fresh = c.make(method, k, dt);
                    const State& s0 = fresh->state();
                    double mass = 0.0;
                    for (int i = 0; i < s0.size(); ++i) mass += s0.w[i] > 0 ? 1.0 / s0.w[i] : 0.0;
                    const double extent = (s0.x.rowwise().maxCoeff() - s0.x.rowwise().minCoeff()).norm();
                    const double e0 = r.rows.front().metrics[0].value;
                    const double allowed = e0 + mass * 9.81 * (extent + 1.0) + 1e-6 * std::abs(e0);
                    for (const ReportRow& row : r.rows)
                        EXPECT_LE(row.metrics[0].value, allowed) << what << ": energy rose at step " << row.step << " from " << e0 << " to "
                                                                 << row.metrics[0].value;
                }
            }
    std::printf("%s: %d runs, %d stopped as unstable\n", method.c_str(), runs, unstable);
}

}  // namespace

TEST(Extreme, ExplicitEulerFiniteOrAnnounced) { runMatrix("explicit_euler"); }
TEST(Extreme, SymplecticEulerFiniteOrAnnounced) { runMatrix("symplectic_euler"); }
TEST(Extreme, VelocityVerletFiniteOrAnnounced) { runMatrix("velocity_verlet"); }
TEST(Extreme, Rk4FiniteOrAnnounced) { runMatrix("rk4"); }
TEST(Extreme, ImplicitEulerBoundedInEveryCase) { runMatrix("implicit_euler"); }
