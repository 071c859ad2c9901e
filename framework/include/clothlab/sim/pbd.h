/// @file pbd.h
/// @brief Position Based Dynamics (Müller et al. 2007) and XPBD (Macklin et al. 2016) on a cloth.
///
/// The step is the student's pbdStep() (stage 03) with the callbacks this class builds from the
/// scene: gravity and wind as external forces, distance (stage 04) and bending (stage 05)
/// constraints, collision constraints and velocityUpdate (stage 06). Only what the scene enables
/// becomes a pass: a scene without colliders never calls the collision code, one without
/// constraints.bending never calls the bending code.
#pragma once
#include <memory>
#include <vector>

#include "clothlab/exercise/03_pbd_loop.h"
#include "clothlab/exercise/05_bending.h"
#include "clothlab/exercise/06_collision.h"
#include "clothlab/sim/simulation.h"

namespace clothlab {

struct BendingBlocks;  // solutions/kernels/bending_batched.h (instructor copy only)

/// A distance constraint between particles i and j with rest length d (an edge of the cloth).
struct DistanceLink {
    int i = 0;        ///< first particle
    int j = 0;        ///< second particle
    double d = 0.0;   ///< rest length, m
};

/// One Gauss–Seidel sweep of the PBD solver over its distance constraints (lines (9)–(10) for
/// one iteration): for every link in the given order, p_i += Δp1, p_j += Δp2 with the corrections of
/// projectDistanceConstraint() (exercise 4.3, the student's or the reference code).
/// @param links  the constraints, in the order they are projected (the solver uses colourOrder())
/// @param w      inverse masses, length N, 1/kg
/// @param k      per-iteration stiffness k' in [0, 1]
/// @param p      predicted positions, 3 x N, m (updated in place)
void projectDistanceSweep(const std::vector<DistanceLink>& links, const VectorX& w, double k, Matrix3X& p);

/// One Gauss–Seidel sweep over the bending stencils: for every stencil in the given order,
/// p_i += Δp_i (i = 1..4) with the corrections of projectBendingConstraint() (exercise 5.2).
/// @param stencils  the constraints with their rest angles φ0, in the order they are projected
/// @param w         inverse masses, length N, 1/kg
/// @param k         per-iteration stiffness k' in [0, 1]
/// @param p         predicted positions, 3 x N, m (updated in place)
void projectBendingSweep(const std::vector<BendingStencil>& stencils, const VectorX& w, double k, Matrix3X& p);

/// PBD or XPBD (solver.method "pbd" or "xpbd") on a cloth scene.
class PbdSimulation : public Simulation {
public:
    /// @param scene  a scene with model "cloth" and solver.method "pbd" or "xpbd"
    /// @throws InputError for settings PBD cannot use (forces.damping > 1; solver.bending_kernel
    ///         "batched" with bending constraints under XPBD, or in a copy without solutions/kernels)
    explicit PbdSimulation(const Scene& scene);
    void step() override;
    /// energy (kinetic + gravity), and only for what the scene uses: max_strain and rms_strain
    /// (distance), rms_bending_error (bending), max_penetration (colliders).
    std::vector<Metric> metrics() const override;

    /// Largest relative edge strain max |(|x_i − x_j| − d)/d| over the distance links (0 without them).
    double maxStrain() const;
    /// RMS relative edge strain over the distance links (0 without them).
    double rmsStrain() const;
    /// RMS of arccos(d) − φ0 over the bending stencils, rad (0 without them).
    double rmsBendingError() const;
    /// Deepest violation of a collision constraint over particles and colliders, max(0, h − dist), m.
    double maxPenetration() const;
    /// Kinetic plus gravitational potential energy, J.
    double energy() const;
    /// The distance constraints (empty unless constraints.distance is enabled).
    const std::vector<DistanceLink>& distanceLinks() const { return links_; }
    /// The bending stencils (empty unless constraints.bending is enabled).
    const std::vector<BendingStencil>& bendingStencilList() const { return stencils_; }

private:
    void addExternalForces(const Matrix3X& x, const Matrix3X& v, Matrix3X& f);
    void generateCollisions(const Matrix3X& x, const Matrix3X& p);
    void projectAll(Matrix3X& p);
    void updateState();

    bool xpbd_ = false;                      ///< XPBD instead of PBD
    double subDt_ = 0.0;                     ///< Δt / substeps, s
    PbdParticles P_;                         ///< particles
    std::vector<DistanceLink> links_;        ///< distance constraints
    std::vector<double> linkLambda_;         ///< XPBD multipliers of the links
    std::vector<BendingStencil> stencils_;   ///< bending constraints
    std::shared_ptr<const BendingBlocks> blocks_;  ///< stencils of bending_kernel "batched" (else null)
    std::vector<double> bendLambda_;         ///< XPBD multipliers of the stencils
    std::vector<CollisionConstraint> contacts_;  ///< collision constraints of the current step
    double kDistance_ = 1.0, kBending_ = 1.0;    ///< per-iteration PBD stiffness k'
    int gravityPass_ = -1, windPass_ = -1, stepPass_ = -1, generatePass_ = -1;
    int distancePass_ = -1, bendingPass_ = -1, collisionPass_ = -1, velocityPass_ = -1;
    double nested_ = 0.0;                    ///< time booked on nested passes during one pbdStep, s
};

}  // namespace clothlab
