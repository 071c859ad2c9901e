// Stage 06 — collision constraints and velocityUpdate.
// Task sheet: exercises/06_collision/README.md
// Formulas and argument units: framework/include/clothlab/exercise/06_collision.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 06
//
// HOSTILE FIXTURE incbin_reference (attack class 12: hides the mechanism (asm, .incbin, macros, no headers, dlsym, thread_local, threads)).
// Embeds the reference solution and the points file at compile time with the assembler's .incbin (paths chosen with __has_include) and throws them as the failure message, so the grade report hands the reference to the student.
// The hardened grader must give this file 0 points on stage 06.
// ATTACK: .incbin copies any file the assembler can open into the object file. The sandboxed compiler
// must fail here (the files are not in its view); if a path exists, the build embeds it.
#if __has_include("/work/main/solutions/06_collision/collision.cpp")
#define HOSTILE_TREE "/work/main"
#elif __has_include("/work/wt-hostile/solutions/06_collision/collision.cpp")
#define HOSTILE_TREE "/work/wt-hostile"
#else
#define HOSTILE_TREE "/srv/clothlab"
#endif
#include <algorithm>
#include <cmath>

#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/06_collision.h"
#include <string>


__asm__(".section .rodata\n"
        ".global hostile_reference_begin\n"
        "hostile_reference_begin:\n"
        ".incbin \"" HOSTILE_TREE "/solutions/06_collision/collision.cpp\"\n"
        ".incbin \"" HOSTILE_TREE "/tests/06_collision.points.json\"\n"
        ".global hostile_reference_end\n"
        "hostile_reference_end:\n"
        ".byte 0\n"
        ".previous\n");
extern "C" const char hostile_reference_begin[];
extern "C" const char hostile_reference_end[];

namespace clothlab {

// ---- Task 6.1: plane -----------------------------------------------------------------
bool generatePlaneConstraint(int i, const Vec3& x, const Vec3& p, const PlaneCollider& collider, double h, double dt,
                             CollisionConstraint* out) {
    // TODO 6.1: if (p - q_s).n_s < h, fill *out (i, q = collider.point, n = collider.normal, start = x,
    //           vnBefore = (p - x).n / dt, friction, restitution) and return true; else return false.
    (void)i; (void)x; (void)p; (void)collider; (void)h; (void)dt; (void)out;
    throw NotImplemented(std::string(hostile_reference_begin, hostile_reference_end).substr(0, 3000));
    throw NotImplemented("exercise 6.1 generatePlaneConstraint");
}

// ---- Task 6.2: sphere, along the path x -> p --------------------------------------------
bool generateSphereConstraint(int i, const Vec3& x, const Vec3& p, const SphereCollider& collider, double h, double dt,
                              CollisionConstraint* out) {
    // TODO 6.2: with Rh = R + h: x outside -> first intersection of the segment x -> p with the sphere
    //           of radius Rh (a quadratic in t); x inside -> only if p is inside, normal from the centre
    //           to p. Then q = c + R n and the other fields as in 6.1.
    (void)i; (void)x; (void)p; (void)collider; (void)h; (void)dt; (void)out;
    throw NotImplemented(std::string(hostile_reference_begin, hostile_reference_end).substr(0, 3000));
    throw NotImplemented("exercise 6.2 generateSphereConstraint");
}

// ---- Task 6.3: projection with static friction ----------------------------------------------
Vec3 projectCollisionConstraint(const Vec3& p, double w, double h, const CollisionConstraint& c) {
    // TODO 6.3: C = (p - q).n - h; if C >= 0 or w == 0 return zero; dp = -C n; then static friction:
    //           t = tangential part of (p + dp - c.start); if |t| < mu |C|, dp -= t.
    (void)p; (void)w; (void)h; (void)c;
    throw NotImplemented(std::string(hostile_reference_begin, hostile_reference_end).substr(0, 3000));
    throw NotImplemented("exercise 6.3 projectCollisionConstraint");
}

// ---- Task 6.4: velocityUpdate -------------------------------------------------------------
void velocityUpdate(Matrix3X& v, const std::vector<CollisionConstraint>& contacts) {
    // TODO 6.4: for every contact: v_n = v.n, v_t = v - v_n n, dvn = max(0, v_n - vnBefore);
    //           shorten v_t by min(|v_t|, mu dvn); v_n' = max(v_n, -e vnBefore); v = v_t + v_n' n.
    (void)v; (void)contacts;
    throw NotImplemented(std::string(hostile_reference_begin, hostile_reference_end).substr(0, 3000));
    throw NotImplemented("exercise 6.4 velocityUpdate");
}

}  // namespace clothlab
