/// @file scene.h
/// @brief A scene: which model, which forces, springs, constraints, colliders and solver.
///
/// A scene names only what it uses; the simulation built from it runs only those parts.
/// Scenes are JSON files (see io/scene_json.h and docs/scenes.md); every field has a default.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "clothlab/core/spring.h"
#include "clothlab/core/types.h"

namespace clothlab {

struct TriangleMesh;
class MeshShape;

/// What is simulated (scene field `model`).
enum class Model {
    Spring,  ///< "spring": one particle on one spring (stage 01)
    Chain,   ///< "chain": particles joined in a line by springs (stage 02's forces)
    Cloth    ///< "cloth": a grid of particles (stages 02-06)
};

/// How a scene is stepped (scene field `solver.method`).
enum class Method {
    ExplicitEuler,    ///< "explicit_euler" (stage 01, task 1.3)
    SymplecticEuler,  ///< "symplectic_euler" (stage 01, task 1.4)
    VelocityVerlet,   ///< "velocity_verlet" (stage 01, task 1.5)
    Rk4,              ///< "rk4": classical Runge-Kutta (framework)
    ImplicitEuler,    ///< "implicit_euler": linearised backward Euler, Baraff & Witkin 1998 (framework)
    Pbd,              ///< "pbd": Position Based Dynamics, Müller et al. 2007 (stages 03-06)
    Xpbd              ///< "xpbd": extended PBD with compliance, Macklin et al. 2016 (framework)
};

/// The scene-file name of a model, e.g. "cloth".
const char* modelName(Model m);
/// The scene-file name of a method, e.g. "symplectic_euler".
const char* methodName(Method m);
/// The method called `name` in a scene file, or nothing for an unknown name.
std::optional<Method> parseMethod(const std::string& name);
/// Every method, in the order of the course.
const std::vector<Method>& allMethods();
/// True for the position-based methods (pbd, xpbd), false for the force-based ones.
bool isPositionBased(Method m);

/// "spring": one particle hanging from a fixed point (stage 01).
struct SingleSpringSpec {
    Vec3 anchor{0, 0, 0};       ///< fixed end point, m
    Vec3 start{0, -1.5, 0};     ///< initial position of the particle, m
    Vec3 velocity{0, 0, 0};     ///< initial velocity of the particle, m/s
    double mass = 1.0;          ///< particle mass m, kg
    double k = 100.0;           ///< stiffness (Federhärte), N/m
    double l0 = 1.0;            ///< rest length (Ruhelänge), m
    double kd = 0.0;            ///< damping along the spring, N s/m
};

/// "chain": n particles joined by n-1 springs, the first one pinned (and the last one too when `end` is given).
struct ChainSpec {
    int particles = 10;         ///< number of particles n (≥ 2)
    Vec3 anchor{0, 0, 0};       ///< position of particle 0 (pinned), m
    Vec3 direction{1, 0, 0};    ///< direction in which the chain is laid out (normalised on load)
    double mass = 0.1;          ///< mass of each particle, kg
    double k = 1000.0;          ///< stiffness of each link, N/m
    double l0 = 0.1;            ///< rest length of each link, m
    double kd = 0.0;            ///< damping along each link, N s/m
    /// Second anchor (scene field `chain.end`): the last particle is pinned there and the chain starts as a
    /// symmetric V below the two anchors (links at rest length, in the vertical plane through both), so it
    /// hangs slack between them; needs (n-1) l0 > |end − anchor|. `direction` is then unused.
    std::optional<Vec3> end;
};

/// A pinned particle moved to a given position when the simulation starts (scene field `cloth.pins`
/// entry with `"to"`): the cloth keeps its rest shape (rest lengths, bending angles) and is held there.
struct PinMove {
    int index = 0;      ///< particle index
    Vec3 to{0, 0, 0};   ///< where it is held, m
};

/// "cloth": nx x ny particles on a regular grid, or the vertices of a triangle mesh (`mesh`).
/// Grid particle (c, r) has index r*nx + c; row 0 is the top edge, column 0 the left edge.
struct ClothSpec {
    int nx = 10;                     ///< particles along the width (≥ 2)
    int ny = 10;                     ///< particles along the height (≥ 2)
    double width = 1.0;              ///< extent along x, m
    double height = 1.0;             ///< extent along y (vertical) or z (horizontal), m
    double mass = 1.0;               ///< total mass m_gesamt = Σ m_i, kg
    Vec3 origin{0, 0, 0};            ///< position of the top-left particle, m
    bool horizontal = false;         ///< false: hangs in the x-y plane; true: lies in the x-z plane
    /// Turn about the top edge (the x axis through `origin`), degrees in [-90, 90]: a vertical cloth
    /// swings its bottom edge towards +z, a horizontal one lowers its far edge (0: not tilted)
    double tilt = 0.0;
    /// Turn of the whole cloth about `origin`, applied after orientation and tilt (scene fields
    /// `cloth.rotation`, Euler angles in degrees, R = R_z R_y R_x, or `cloth.normal`, the shortest turn of
    /// the vertical cloth's normal +z onto it); identity: not turned
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
    std::vector<int> pins;           ///< indices of pinned particles (w = 0)
    std::vector<PinMove> moves;      ///< pinned particles moved away from their rest position
    /// Mesh cloth (scene field `cloth.mesh`, an OBJ path relative to the scene file): particles at
    /// origin + rotation (scale · vertex), lumped masses (lumpedMasses()); nx, ny, width, height unused
    std::string mesh;
    double scale = 1.0;                              ///< mesh cloth: factor on the OBJ coordinates
    std::shared_ptr<const TriangleMesh> meshData;    ///< mesh cloth: the loaded, checked mesh
};

/// Provot's deformation constraint (1995): limit spring strain after each step.
struct ProvotSpec {
    bool enabled = false;      ///< apply the correction
    double max_strain = 0.1;   ///< critical strain τ (0.1 = 10 %)
};

/// One position-based constraint type.
struct ConstraintGroup {
    bool enabled = false;      ///< whether constraints of this type exist
    double stiffness = 1.0;    ///< PBD stiffness k in [0, 1]
    double compliance = 0.0;   ///< XPBD compliance α, m/N (distance) or 1/(N m) (bending)
};

/// Position-based constraints of the cloth.
struct ClothConstraints {
    ConstraintGroup distance;  ///< along structural and shear edges
    ConstraintGroup bending;   ///< dihedral angle across interior edges
};

/// A static collider. Its surface, signed distance and collision constraints: sim/colliders.h.
struct Collider {
    /// Kind of collider.
    enum class Type {
        Plane,    ///< infinite plane through `point` with outward `normal`
        Sphere,   ///< sphere around `point` with `radius`
        Box,      ///< oriented box: centre `point`, half extents `halfExtents` along the columns of `rotation`
        Capsule,  ///< capsule (a pole with round ends): the points within `radius` of the segment `point`–`end`
        Mesh      ///< static closed triangle mesh (`mesh`), outside = where its face normals point
    };
    Type type = Type::Plane;   ///< kind of collider
    Vec3 point{0, 0, 0};       ///< plane: a point on it; sphere, box: the centre; capsule: one end of the axis, m
    Vec3 normal{0, 1, 0};      ///< plane: outward unit normal (normalised on load)
    double radius = 0.5;       ///< sphere and capsule radius, m
    Vec3 end{0, 1, 0};         ///< capsule: the other end of the axis, m
    Vec3 halfExtents{0.5, 0.5, 0.5};  ///< box: half its size along its axes, m
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  ///< box: its axes as columns (Euler angles on load)
    std::string mesh;          ///< mesh: the OBJ file (resolved against the scene file's folder)
    std::shared_ptr<const MeshShape> shape;  ///< mesh: the loaded mesh with its bounding-volume hierarchy
    double friction = 0.0;     ///< Coulomb friction coefficient μ ≥ 0
    double restitution = 0.0;  ///< coefficient of restitution e in [0, 1]
};

/// The scene-file name of a collider type, e.g. "capsule".
const char* colliderTypeName(Collider::Type t);

/// Self-collision of the cloth with itself (stage 07; scene field `self_collision`).
struct SelfCollisionSpec {
    bool enabled = false;       ///< whether particles of the cloth are kept apart from each other
    double thickness = 0.01;    ///< separation distance h between two particles, m (pairs closer than h at rest are left out)
    double friction = 0.0;      ///< friction coefficient μ ≥ 0 between two layers in contact
};

/// External forces.
struct ForcesSpec {
    Vec3 gravity{0, -9.81, 0};  ///< gravitational acceleration g, m/s²
    double air_damping = 0.0;   ///< air damping c of the force-based methods: force −c v_i on every particle, N s/m
    Vec3 wind{0, 0, 0};         ///< wind velocity, m/s (zero: no wind pass)
    double drag = 1.0;          ///< wind drag coefficient, N s/m³ (force per unit area and unit relative velocity: f = drag · A · v_rel)
};

/// Settings only the position-based methods use.
struct PbdSpec {
    double damping = 0.0;       ///< k_damping of dampVelocities (line (6)), dimensionless, in [0, 1]
};

/// How the scene is stepped.
struct SolverSpec {
    Method method = Method::SymplecticEuler;  ///< the integrator or solver
    double dt = 1e-3;       ///< time step Δt, s
    int steps = 1000;       ///< number of steps of `./lab run`
    int iterations = 10;    ///< PBD solver iterations per step
    int substeps = 1;       ///< PBD substeps per step
    double thickness = 0.01;///< collision thickness h, m
    /// PBD/XPBD constraint sweeps: "exercise" calls exercises 4.3 and 5.2 per constraint (the student's
    /// or the reference code); any other name is a kernel registered with registerSweepKernel() (sim/kernel_registry.h)
    std::string kernel = "exercise";
    int threads = 0;        ///< threads that sweep a colour group / compute forces (0: all cores, 1: serial)
};

/// What the run report prints.
struct ReportSpec {
    int every = 0;             ///< print a line every R steps (0: about 10 lines per run)
    double blowup = 1e6;       ///< positions beyond this distance from the origin count as unstable, m
};

/// How the renderer looks at the scene (optional; without `view.eye` the camera is fitted to the scene).
struct ViewSpec {
    bool camera = false;        ///< true when the scene sets eye and target
    Vec3 eye{0, 0, 3};          ///< camera position, m
    Vec3 target{0, 0, 0};       ///< point looked at, m
    double fov = 35.0;          ///< vertical field of view, degrees
    std::string look;           ///< one line for the lecturer: what to look at in this scene ("" = none)
    std::string error;          ///< the metric a comparison plots as the error ("" = chosen: study/compare.h)
};

/// A whole scene, as loaded from JSON.
struct Scene {
    std::string file;            ///< where it was loaded from
    std::string description;     ///< one line for the report
    Model model = Model::Spring; ///< what is simulated
    SingleSpringSpec spring;     ///< used when model is Model::Spring
    ChainSpec chain;             ///< used when model is Model::Chain
    ClothSpec cloth;             ///< used when model is Model::Cloth
    ClothSprings springs;        ///< mass-spring network (force-based methods on a cloth)
    ProvotSpec provot;           ///< strain limiting for the mass-spring network
    ClothConstraints constraints;///< position-based constraints (pbd, xpbd)
    std::vector<Collider> colliders; ///< static colliders
    SelfCollisionSpec self_collision; ///< the cloth against itself (pbd, xpbd)
    ForcesSpec forces;           ///< gravity, air damping, wind
    PbdSpec pbd;                 ///< dampVelocities (pbd, xpbd)
    SolverSpec solver;           ///< method and step
    ReportSpec report;           ///< report settings
    ViewSpec view;               ///< camera of the renderer and the app
};

}  // namespace clothlab
