/// @file simulation.h
/// @brief A running simulation built from a scene: state, step, metrics and pass timings.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "clothlab/core/scene.h"
#include "clothlab/core/state.h"
#include "clothlab/sim/pass_timer.h"

namespace clothlab {

/// One named number of the run report (energy, error against the analytic solution, strain, ...).
struct Metric {
    std::string name;  ///< short name, e.g. "energy_drift"
    double value;      ///< its value
    std::string unit;  ///< unit, e.g. "J", "m", "%"
};

/// Base of every method. A subclass assembles only the passes its scene uses.
class Simulation {
public:
    /// @param scene  the validated scene (copied)
    explicit Simulation(const Scene& scene) : scene_(scene) {}
    virtual ~Simulation() = default;

    /// Advances the state by one time step Δt = scene().solver.dt.
    virtual void step() = 0;
    /// The scene's error metrics for the current state (energy and drift, error against an analytic solution, ...).
    virtual std::vector<Metric> metrics() const = 0;

    /// Current particle state.
    const State& state() const { return state_; }
    /// Current particle state, writable (e.g. for dragging a particle in the app).
    State& state() { return state_; }
    /// Wall time per pass so far.
    const PassTimer& timer() const { return timer_; }
    /// The scene this simulation was built from.
    const Scene& scene() const { return scene_; }
    /// Edges to draw (springs or distance constraints), pairs of particle indices.
    const std::vector<Eigen::Vector2i>& edges() const { return edges_; }
    /// Triangles to draw (cloth surface), triples of particle indices; empty for springs and chains.
    const std::vector<Eigen::Vector3i>& triangles() const { return triangles_; }

protected:
    Scene scene_;                               ///< the scene
    State state_;                               ///< particles
    PassTimer timer_;                           ///< pass timings
    std::vector<Eigen::Vector2i> edges_;        ///< for display
    std::vector<Eigen::Vector3i> triangles_;    ///< for display
};

/// Builds the simulation for a scene's model and solver.method.
/// @throws InputError when the combination is not supported
std::unique_ptr<Simulation> makeSimulation(const Scene& scene);

}  // namespace clothlab
