#include "clothlab/sim/run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "clothlab/sim/colliders.h"

namespace clothlab {
namespace {

std::string num(double x, int precision = 3) {
    std::ostringstream s;
    s.precision(precision);
    s << x;
    return s.str();
}

std::string percent(double fraction) { return num(100.0 * fraction) + " %"; }

// "collider 0 (sphere)": the index into scene.colliders and the type's scene-file name.
std::string colliderName(const Scene& scene, int i) {
    const std::string type = i >= 0 && i < static_cast<int>(scene.colliders.size())
                                 ? colliderTypeName(scene.colliders[static_cast<size_t>(i)].type) : "?";
    return "collider " + std::to_string(i) + " (" + type + ")";
}

std::string since(const RunWarning& w) { return "step " + std::to_string(w.step) + " (t = " + num(w.t, 4) + " s)"; }

double fellThroughDepth(const Scene& s) { return std::max(kFellThroughFactor * s.solver.thickness, kFellThroughMinDepth); }

// The scene means an inextensible cloth: distance constraints at PBD stiffness 1 or XPBD compliance 0.
bool meantInextensible(const Scene& s) {
    if (s.model != Model::Cloth || !isPositionBased(s.solver.method) || !s.constraints.distance.enabled) return false;
    return s.solver.method == Method::Pbd ? s.constraints.distance.stiffness >= 1.0 : s.constraints.distance.compliance == 0.0;
}

// "the pass 'constraints: distance' (stage 04, exercise 4.3)": a pass, and where its code is; without a
// pass (a method that does not check its passes): the method's step.
std::string passAndStage(const std::string& name, const Scene& s) {
    static const std::vector<std::pair<std::string, std::string>> stages = {
        {"constraints: distance", "stage 04, exercise 4.3"}, {"constraints: bending", "stage 05, exercise 5.2"},
        {"constraints: collision", "stage 06, exercises 6.1-6.3"}, {"collisions: velocity update", "stage 06, exercise 6.4"},
        {"constraints: self-collision", "stage 07, exercises 7.5-7.6"}, {"damp, predict, update", "stage 03, exercise 3.3"}};
    if (name.empty()) return std::string("the ") + methodName(s.solver.method) + " step";
    for (const auto& [pass, where] : stages)
        if (name.find(pass) != std::string::npos) return "the pass '" + name + "' (" + where + ")";
    return "the pass '" + name + "'";
}

// The pass that moved a pin: before the constraints, the prediction of lines (5)-(7).
std::string movedBy(const RunWarning& w, const Scene& s) {
    if (w.pass == "damp, predict, update") return "the pass '" + w.pass + "' (stage 03, exercise 3.3, lines (5)-(7))";
    return passAndStage(w.pass, s);
}

}  // namespace

const char* causeName(StopCause c) {
    switch (c) {
        case StopCause::None: return "none";
        case StopCause::PositionNotFinite: return "position_not_finite";
        case StopCause::VelocityNotFinite: return "velocity_not_finite";
        case StopCause::LeftRegion: return "left_region";
        case StopCause::SolverFailure: return "solver_failure";
        case StopCause::Strict: return "strict";
    }
    return "none";
}

const char* warningName(WarningKind k) {
    switch (k) {
        case WarningKind::PinMoved: return "pin_moved";
        case WarningKind::MomentumCreated: return "momentum_created";
        case WarningKind::NotConverged: return "not_converged";
        case WarningKind::Penetration: return "penetration";
        case WarningKind::FellThrough: return "fell_through";
        case WarningKind::EnergyGrowth: return "energy_growth";
    }
    return "";
}

std::string warningText(const RunWarning& w, const Scene& s) {
    const SolverSpec& sv = s.solver;
    const std::string h = num(sv.thickness) + " m";
    std::ostringstream m;
    switch (w.kind) {
        case WarningKind::PinMoved:
            m << "pinned particle moved: particle " << w.particle << " (w = 0, infinite mass) moved " << num(w.value) << " m by " << since(w)
              << (w.count > 1 ? " (" + std::to_string(w.count) + " pinned particles moved)" : "") << ", moved by " << movedBy(w, s)
              << ": a pinned particle never moves; every correction must be weighted by the inverse mass w (0 for a pin)";
            break;
        case WarningKind::MomentumCreated:
            m << "momentum created: at " << since(w) << " " << movedBy(w, s) << " changed the cloth's linear momentum by "
              << percent(w.value) << " of the momentum it moved (|sum m_i dp_i| / sum m_i |dp_i|): constraints between particles "
              << "must keep it (m_1 dp_1 + m_2 dp_2 + ... = 0; the gradients of a constraint sum to zero)";
            break;
        case WarningKind::NotConverged:
            m << "not converged: the RMS edge strain has stayed above " << percent(kNotConvergedRmsStrain) << " since " << since(w)
              << " (last " << percent(w.value) << ", max " << percent(w.extra) << "): the distance constraints are far from solved, "
              << "this is a stretching sheet, not the inextensible cloth the scene describes; more solver.iterations (now "
              << sv.iterations << "), solver.substeps (now " << sv.substeps << ")"
              << (sv.method == Method::Pbd ? ", solver.method=xpbd" : "") << " or a smaller solver.dt would help";
            break;
        case WarningKind::Penetration:
            m << "penetration: " << w.count << (w.count == 1 ? " particle" : " particles") << " more than " << num(kPenetrationFactor - 1)
              << " h inside " << colliderName(s, w.collider) << " (thickness h = " << h << ", penetration h - d > " << num(kPenetrationFactor)
              << " h), the first (particle " << w.particle << ") at " << since(w) << ", deepest penetration " << num(w.value)
              << " m; more solver.iterations or solver.substeps, or a smaller solver.dt would help";
            break;
        case WarningKind::FellThrough:
            m << "fell through: " << w.count << (w.count == 1 ? " particle" : " particles") << " passed into or through "
              << colliderName(s, w.collider) << ", the first (particle " << w.particle << ") at " << since(w) << ": its path in one step reached "
              << num(w.value) << " m inside (more than " << num(fellThroughDepth(s)) << " m = max(" << num(kFellThroughFactor) << " h, "
              << num(kFellThroughMinDepth) << " m))";
            if (!isPositionBased(sv.method))
                m << "; method " << methodName(sv.method) << " ignores colliders (use pbd or xpbd)";
            else
                m << "; a smaller solver.dt (now " << num(sv.dt) << " s), more solver.substeps or a larger solver.thickness would help";
            break;
        case WarningKind::EnergyGrowth:
            m << "energy grew: E - E(0) exceeded " << num(kEnergyGrowthBound) << " E_scale at " << since(w) << " and reached " << num(w.value)
              << " E_scale (E_scale = max(|E(0)|, m g L)) and did not stay in a band about a fixed level; "
                 "without an energy source the energy must not grow: ";
            switch (sv.method) {
                case Method::ExplicitEuler: m << "explicit Euler adds energy every step; symplectic_euler, velocity_verlet or implicit_euler keep it (or a much smaller solver.dt delays it)"; break;
                case Method::SymplecticEuler:
                case Method::VelocityVerlet: m << methodName(sv.method) << " keeps the energy bounded only while omega_max dt < 2: a smaller solver.dt (now " << num(sv.dt) << " s) would help"; break;
                case Method::Rk4: m << "rk4 is stable only while omega_max dt < 2.83: a smaller solver.dt (now " << num(sv.dt) << " s) would help"; break;
                case Method::Pbd:
                case Method::Xpbd: m << "a smaller solver.dt or more solver.iterations would help"; break;
                default: m << "a smaller solver.dt would help"; break;
            }
            break;
    }
    return m.str();
}

std::string warningHeadline(const RunWarning& w, const Scene& s) {
    switch (w.kind) {
        case WarningKind::PinMoved: return "pinned particle " + std::to_string(w.particle) + " moved by " + movedBy(w, s) + " at " + since(w);
        case WarningKind::MomentumCreated: return "momentum created by " + movedBy(w, s) + " at " + since(w);
        case WarningKind::FellThrough: return "fell through " + colliderName(s, w.collider) + " at " + since(w);
        case WarningKind::NotConverged: return "not converged: RMS strain " + percent(w.value) + " since " + since(w);
        case WarningKind::Penetration: return "penetration " + num(w.value) + " m into " + colliderName(s, w.collider) + " at " + since(w);
        case WarningKind::EnergyGrowth: return "energy grew by " + num(w.value) + " E_scale (still rising), from " + since(w);
    }
    return "";
}

StopCause instabilityCause(const State& s, double bound) {
    if (!s.x.allFinite()) return StopCause::PositionNotFinite;
    if (!s.v.allFinite()) return StopCause::VelocityNotFinite;
    if (s.x.size() > 0 && s.x.colwise().norm().maxCoeff() > bound) return StopCause::LeftRegion;
    return StopCause::None;
}

std::string stopReason(StopCause c, double bound, const std::string& detail) {
    switch (c) {
        case StopCause::None: return "";
        case StopCause::PositionNotFinite: return "position is NaN or infinite";
        case StopCause::VelocityNotFinite: return "velocity is NaN or infinite";
        case StopCause::LeftRegion:
            return "a particle left the region |x| < " + num(bound, 6) + " m (report.blowup): the state is finite but has blown up";
        case StopCause::SolverFailure: return detail.empty() ? "the solver could not take the step" : detail;
        case StopCause::Strict: return detail.empty() ? "a warning (--strict)" : detail;
    }
    return "";
}

std::string instabilityReason(const State& s, double bound) { return stopReason(instabilityCause(s, bound), bound); }

std::string stepAndCheck(Simulation& sim, long long step, double bound, StopCause* cause) {
    StopCause c = StopCause::None;
    std::string detail;
    const State before = sim.state();  // to trace a blow-up to its pass
    try {
        sim.step();
        c = instabilityCause(sim.state(), bound);
    } catch (const SolverFailure& e) {
        c = StopCause::SolverFailure;
        detail = e.what();
    }
    if (cause) *cause = c;
    if (c == StopCause::None) return "";
    std::ostringstream m;
    m << "unstable at step " << step << " (t = " << sim.state().t << " s): " << stopReason(c, bound, detail);
    if (c != StopCause::SolverFailure) {
        const std::string pass = sim.blowUpBy(before, bound);
        if (!pass.empty())
            m << "; it first blew up in " << passAndStage(pass, sim.scene()) << (step <= 3 ? ": at the start of a run, "
                 "that is a wrong sign or weight there, more often than a time step too large" : "");
    }
    return m.str();
}

double energyScale(const Simulation& sim) {
    const State& s = sim.state();
    const double extent = s.size() > 0 ? (s.x.rowwise().maxCoeff() - s.x.rowwise().minCoeff()).norm() : 0.0;
    double mass = 0.0;
    for (int i = 0; i < s.size(); ++i) mass += s.w[i] > 0.0 ? 1.0 / s.w[i] : 0.0;
    return std::max({std::abs(sim.energy()), mass * sim.scene().forces.gravity.norm() * extent, 1e-12});
}

namespace {
// colliderDistance(c, x), the same value; for a mesh with near (a surface point, NaN: none) bounding
// the search, and near set to x's closest point; a point asked for twice in a row is looked up once.
double distanceNear(const Collider& c, const Vec3& x, Vec3* near, Vec3* lastX, double* lastD) {
    if (!near || c.type != Collider::Type::Mesh) return colliderDistance(c, x);
    if (x == *lastX) return *lastD;
    const SurfacePoint s = c.shape->closest(x, *near);
    *near = s.q, *lastX = x, *lastD = s.d;
    return s.d;
}
}  // namespace

double pathDistance(const Collider& c, const Vec3& a, const Vec3& b, double depth, Vec3* near) {
    const double len = (b - a).norm();
    Vec3 lastX = Vec3::Constant(NAN);  // the last point looked up and its distance (NaN: none)
    double lastD = NAN;
    const auto d = [&](const Vec3& x) { return distanceNear(c, x, near, &lastX, &lastD); };
    double lowest = d(a), t = 0.0;
    while (lowest >= -depth && t < len) {
        t = std::min(len, t + std::max({d(a + (t / len) * (b - a)) + depth, 0.25 * depth, len / 64.0}));
        lowest = std::min(lowest, d(a + (t / len) * (b - a)));
    }
    return lowest;
}

RunChecks::RunChecks(const Simulation& sim, bool strict) : strict_(strict) {
    const Scene& sc = sim.scene();
    const State& s = sim.state();
    for (int i = 0; i < s.size(); ++i)
        if (s.w[i] == 0.0) pins_.push_back(i);
    pinAt_.resize(3, static_cast<Eigen::Index>(pins_.size()));
    for (size_t k = 0; k < pins_.size(); ++k) pinAt_.col(static_cast<Eigen::Index>(k)) = s.x.col(pins_[k]);
    e0_ = sim.energy();
    eScale_ = energyScale(sim);
    // Wind feeds energy in; pins moved onto hooks ("to") start the cloth away from its rest shape, and
    // the constraints release that stored energy: neither run is judged by its energy.
    checkEnergy_ = sc.forces.wind.squaredNorm() == 0.0 && !(sc.model == Model::Cloth && !sc.cloth.moves.empty());
    checkStrain_ = meantInextensible(sc);
    method_ = methodName(sc.solver.method);
    oscillates_ = sc.solver.method == Method::SymplecticEuler || sc.solver.method == Method::VelocityVerlet;
    const double h = sc.solver.thickness;
    for (const Collider& c : sc.colliders) {
        std::vector<char> outside(static_cast<size_t>(s.size()));
        for (int i = 0; i < s.size(); ++i) {
            outside[static_cast<size_t>(i)] = s.w[i] > 0.0 && colliderDistance(c, s.x.col(i)) >= -h;
            worstPenetration_ = std::max(worstPenetration_, h - colliderDistance(c, s.x.col(i)));
        }
        watch_.push_back(std::move(outside));
        penetrated_.emplace_back(static_cast<size_t>(s.size()), 0);
    }
}

bool RunChecks::fired(WarningKind k) const {
    return std::any_of(warnings_.begin(), warnings_.end(), [k](const RunWarning& w) { return w.kind == k; });
}

RunWarning& RunChecks::warn(WarningKind k, long long step, double t, int collider) {
    for (RunWarning& w : warnings_)
        if (w.kind == k && w.collider == collider) return w;
    RunWarning w;
    w.kind = k, w.step = step, w.t = t, w.collider = collider;
    warnings_.push_back(w);
    return warnings_.back();
}

void RunChecks::checkColliders(const Simulation& sim, long long step) {
    const Scene& sc = sim.scene();
    const State& s = sim.state();
    const double h = sc.solver.thickness, deep = fellThroughDepth(sc);
    for (size_t k = 0; k < sc.colliders.size(); ++k) {
        const Collider& c = sc.colliders[k];
        const int ck = static_cast<int>(k);
        if (nearest_.size() != sc.colliders.size()) nearest_.assign(sc.colliders.size(), Matrix3X());
        Matrix3X& nearest = nearest_[k];
        if (c.type == Collider::Type::Mesh && nearest.cols() != s.size()) nearest = Matrix3X::Constant(3, s.size(), NAN);
        for (int i = 0; i < s.size(); ++i) {
            Vec3 nearX = Vec3::Constant(NAN), *near = c.type == Collider::Type::Mesh ? &nearX : nullptr;
            if (near) nearX = nearest.col(i);
            Vec3 lastX = Vec3::Constant(NAN);
            double lastD = NAN;
            const double d = distanceNear(c, s.x.col(i), near, &lastX, &lastD);
            if (near) nearest.col(i) = nearX;
            if (h - d > worstPenetration_) worstPenetration_ = h - d, worstPenetrationStep_ = step;
            if (!watch_[k][static_cast<size_t>(i)]) continue;
            if (h - d > kPenetrationFactor * h) {
                RunWarning& w = warn(WarningKind::Penetration, step, s.t, ck);
                if (!penetrated_[k][static_cast<size_t>(i)]) penetrated_[k][static_cast<size_t>(i)] = 1, w.count++;
                if (w.particle < 0) w.particle = i;
                w.value = std::max(w.value, h - d);
            }
            const double lowest = pathDistance(c, xOld_.col(i), s.x.col(i), deep, near);
            if (lowest < -deep) {
                RunWarning& w = warn(WarningKind::FellThrough, step, s.t, ck);
                if (w.count++ == 0) w.particle = i;
                w.value = std::max(w.value, -lowest);
                watch_[k][static_cast<size_t>(i)] = 0;  // counted once
            }
        }
    }
}

void RunChecks::checkStrain(const Simulation& sim, long long step) {
    const EdgeStrain e = sim.strain();
    if (!(e.rms > kNotConvergedRmsStrain)) {
        strainSince_ = 0;
        return;
    }
    if (strainSince_ == 0) strainSince_ = step, strainSinceT_ = sim.state().t;
    bool fired = false;
    for (RunWarning& w : warnings_)
        if (w.kind == WarningKind::NotConverged) w.value = e.rms, w.extra = e.max, fired = true;
    if (!fired && sim.state().t - strainSinceT_ >= kNotConvergedDuration - 1e-12) {
        RunWarning& w = warn(WarningKind::NotConverged, strainSince_, strainSinceT_);
        w.value = e.rms, w.extra = e.max;
    }
}

std::string RunChecks::step(Simulation& sim, long long step) {
    if (!watch_.empty()) xOld_ = sim.state().x;
    const std::string stop = stepAndCheck(sim, step, sim.scene().report.blowup, &cause_);
    if (!stop.empty()) return stop;
    const size_t before = warnings_.size();
    if (!pins_.empty()) checkPins(sim, step);
    if (!sim.momentumCreatedBy().empty() && !fired(WarningKind::MomentumCreated)) {
        RunWarning& w = warn(WarningKind::MomentumCreated, step, sim.state().t);
        w.pass = sim.momentumCreatedBy(), w.value = sim.momentumCreated();
    }
    if (!watch_.empty()) checkColliders(sim, step);
    if (checkStrain_) checkStrain(sim, step);
    if (checkEnergy_) checkEnergy(sim, step);
    if (strict_ && warnings_.size() > before) {
        cause_ = StopCause::Strict;
        // The headline: the warning's whole text is in the run's warnings (said once).
        return "stopped at step " + std::to_string(step) + " by --strict: " + warningHeadline(warnings_.back(), sim.scene());
    }
    return "";
}

void RunChecks::checkPins(const Simulation& sim, long long step) {
    if (fired(WarningKind::PinMoved)) return;  // reported once, at the step it happened
    const State& s = sim.state();
    int moved = 0, first = -1;
    double distance = 0.0;
    for (size_t k = 0; k < pins_.size(); ++k) {
        const double d = (s.x.col(pins_[k]) - pinAt_.col(static_cast<Eigen::Index>(k))).norm();
        if (d > 0.0 && s.w[pins_[k]] == 0.0) {  // (still pinned: the app may release a pin)
            if (moved++ == 0) first = pins_[k], distance = d;
        }
    }
    if (moved == 0) return;
    RunWarning& w = warn(WarningKind::PinMoved, step, sim.state().t);
    w.particle = first, w.count = moved, w.value = distance, w.pass = sim.pinMovedBy();
}

void RunChecks::checkEnergy(const Simulation& sim, long long step) {
    const double g = (sim.energy() - e0_) / eScale_;
    gMax_ = std::max(gMax_, g);
    if (g > kEnergyGrowthBound && gAbove_ == 0) gAbove_ = step, gAboveT_ = sim.state().t;
    // Only the symplectic methods keep the energy in a band about a fixed level; for every other
    // method, and beyond kEnergyOscillationCap for these, a rise above the bound is growth at once.
    if (g > kEnergyGrowthBound && (!oscillates_ || g > kEnergyOscillationCap)) {
        RunWarning& w = warn(WarningKind::EnergyGrowth, gAbove_, gAboveT_);
        w.value = gMax_;
    }
    envWindow_ = std::max(envWindow_, g);
    for (RunWarning& w : warnings_)
        if (w.kind == WarningKind::EnergyGrowth) w.value = gMax_;
    if (step < nextCheckpoint_) return;
    if (step >= kEnergyFirstVerdict) judgeEnergy(envWindow_, envBefore_);
    lastWindow_ = envWindow_, lastBefore_ = envBefore_;
    envBefore_ = std::max(envBefore_, envWindow_), envWindow_ = -1e300;
    nextCheckpoint_ *= 2;
}

// EnergyGrowth when the envelope rose: the max over the later window above the bound and above
// (1 + kEnvelopeRise) times the max over the steps before it (see kEnvelopeRise).
void RunChecks::judgeEnergy(double later, double before) {
    if (gAbove_ == 0 || !(later > kEnergyGrowthBound)) return;
    if (later > (1.0 + kEnvelopeRise) * std::max(before, 0.0)) {
        RunWarning& w = warn(WarningKind::EnergyGrowth, gAbove_, gAboveT_);
        w.value = gMax_;
    }
}

void RunChecks::finish(const Simulation& sim) {
    if (checkEnergy_ && gAbove_ > 0) {
        bool grew = fired(WarningKind::EnergyGrowth);
        // A run that ended between checkpoints: its last steps against the ones before them; one that
        // ended at a checkpoint before the first verdict: that checkpoint's windows.
        if (!grew && envWindow_ > -1e300) judgeEnergy(envWindow_, envBefore_);
        else if (!grew && nextCheckpoint_ / 2 < kEnergyFirstVerdict) judgeEnergy(lastWindow_, lastBefore_);
        grew = fired(WarningKind::EnergyGrowth);
        if (!grew) {
            const std::string order = method_ == "symplectic_euler" ? " (first order: halving solver.dt at least halves it)"
                                    : method_ == "velocity_verlet"  ? " (its error is second order in solver.dt)" : "";
            notes_.push_back("energy error: E - E(0) reached " + num(gMax_) + " E_scale (first above " + num(kEnergyGrowthBound) + " at " +
                             "step " + std::to_string(gAbove_) + ") but stayed bounded: " + method_ +
                             "'s energy oscillates about a fixed level, it does not grow (an accuracy matter, not an instability); a smaller solver.dt narrows it" + order);
        }
    }
    if (strainSince_ == 0) return;
    if (fired(WarningKind::NotConverged)) return;
    const EdgeStrain e = sim.strain();
    RunWarning& w = warn(WarningKind::NotConverged, strainSince_, strainSinceT_);
    w.value = e.rms, w.extra = e.max;
}

void RunChecks::collect(RunResult& r) const {
    r.cause = cause_;
    r.warnings = warnings_;
    r.notes = notes_;
    std::stable_sort(r.warnings.begin(), r.warnings.end(), [](const RunWarning& a, const RunWarning& b) { return a.kind < b.kind; });
    r.worst_penetration = worstPenetration_;
    r.worst_penetration_step = worstPenetrationStep_;
}

RunResult runSimulation(Simulation& sim, long long steps, long long every,
                        const std::function<void(const ReportRow&)>& on_row, bool strict, const MetricWindow* window) {
    RunResult result;
    RunChecks checks(sim, strict);
    const auto t0 = std::chrono::steady_clock::now();
    if (window) result.windowed = true, result.window = *window;
    auto summarise = [&] {  // the state just reached, into the window's min, sum and max
        if (!window || !window->contains(sim.state().t)) return;
        const std::vector<Metric> now = sim.metrics();
        if (result.window_states++ == 0)
            for (const Metric& m : now) result.window_stats.push_back({m.name, m.unit, m.value, 0.0, m.value});
        for (size_t i = 0; i < now.size() && i < result.window_stats.size(); ++i) {
            WindowStat& w = result.window_stats[i];
            w.min = std::min(w.min, now[i].value), w.max = std::max(w.max, now[i].value), w.mean += now[i].value;
        }
    };
    auto record = [&] {
        ReportRow row{result.steps, sim.state().t, result.wall, sim.metrics()};
        if (on_row) on_row(row);
        result.rows.push_back(std::move(row));
    };
    auto done = [&] {
        checks.collect(result);
        for (WindowStat& w : result.window_stats) w.mean /= static_cast<double>(result.window_states);  // the sum so far
        return result;
    };
    record();
    summarise();
    while (result.steps < steps) {
        const std::string unstable = checks.step(sim, result.steps + 1);
        ++result.steps;
        result.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (!unstable.empty()) {
            result.unstable = true;
            result.message = unstable;
            return done();  // no metrics of a broken state
        }
        summarise();
        if (result.steps % every == 0 || result.steps == steps) record();
    }
    checks.finish(sim);
    return done();
}

}  // namespace clothlab
