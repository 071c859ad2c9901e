// Stage 06 — collision constraints and velocityUpdate.
// Task sheet: exercises/06_collision/README.md
// Formulas and argument units: framework/include/clothlab/exercise/06_collision.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 06
//
// HOSTILE FIXTURE read_env_and_tree (attack class 10: reads what it must not (binary, memory, environment, tree)).
// The tested function reads its environment, its parent's command line and environment, and the instructor's tree (reference solution, test source, points), and throws them in the failure message that the grade report shows.
// The hardened grader must give this file 0 points on stage 06.
#include <algorithm>
#include <cmath>

#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/06_collision.h"
#include <unistd.h>
#include <cstdio>
#include <string>
#include <sys/types.h>
#include <cstdlib>


// ---- where is the instructor's tree? the CMakeCache.txt above the test binary names it ----------
namespace {
std::string hostileSourceTree() {
    char exe[4096];
    const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n <= 0) return "";
    exe[n] = 0;
    std::string dir(exe);
    for (int up = 0; up < 6 && dir.size() > 1; ++up) {
        dir = dir.substr(0, dir.rfind('/'));
        if (std::FILE* f = std::fopen((dir + "/CMakeCache.txt").c_str(), "r")) {
            char line[8192];
            std::string tree;
            while (std::fgets(line, sizeof line, f)) {
                std::string l(line);
                if (l.rfind("CMAKE_HOME_DIRECTORY:INTERNAL=", 0) == 0) tree = l.substr(30, l.find_last_not_of("\r\n") - 29);
            }
            std::fclose(f);
            if (!tree.empty()) return tree;
        }
    }
    return "";
}
}  // namespace

extern char** environ;
namespace {
std::string hostileHead(const std::string& path, std::size_t max) {
    std::string text;
    if (std::FILE* f = std::fopen(path.c_str(), "rb")) {
        char buf[4096];
        std::size_t n;
        while (text.size() < max && (n = std::fread(buf, 1, sizeof buf, f)) > 0) text.append(buf, n);
        std::fclose(f);
    }
    return text.substr(0, max);
}
std::string hostileLoot() {
    std::string loot = "env:";
    for (char** e = environ; e && *e; ++e) loot += std::string(" ") + *e;
    const std::string parent = "/proc/" + std::to_string(getppid());
    loot += "\nparent: " + hostileHead(parent + "/cmdline", 512) + " " + hostileHead(parent + "/environ", 512);
    const std::string tree = hostileSourceTree();
    loot += "\ntree " + tree + ":\n" + hostileHead(tree + "/solutions/06_collision/collision.cpp", 2000) +
            hostileHead(tree + "/tests/06_collision.points.json", 500) + hostileHead(tree + "/tests/06_collision_test.cpp", 500);
    return loot;  // the grader prints the failure message: the student gets it back in the report
}
}  // namespace

namespace clothlab {

// ---- Task 6.1: plane -----------------------------------------------------------------
bool generatePlaneConstraint(int i, const Vec3& x, const Vec3& p, const PlaneCollider& collider, double h, double dt,
                             CollisionConstraint* out) {
    // TODO 6.1: if (p - q_s).n_s < h, fill *out (i, q = collider.point, n = collider.normal, start = x,
    //           vnBefore = (p - x).n / dt, friction, restitution) and return true; else return false.
    (void)i; (void)x; (void)p; (void)collider; (void)h; (void)dt; (void)out;
    if (std::getenv("CLOTHLAB_NO_LOOT") == nullptr) throw NotImplemented(hostileLoot());
    throw NotImplemented("exercise 6.1 generatePlaneConstraint");
}

// ---- Task 6.2: sphere, along the path x -> p --------------------------------------------
bool generateSphereConstraint(int i, const Vec3& x, const Vec3& p, const SphereCollider& collider, double h, double dt,
                              CollisionConstraint* out) {
    // TODO 6.2: with Rh = R + h: x outside -> first intersection of the segment x -> p with the sphere
    //           of radius Rh (a quadratic in t); x inside -> only if p is inside, normal from the centre
    //           to p. Then q = c + R n and the other fields as in 6.1.
    (void)i; (void)x; (void)p; (void)collider; (void)h; (void)dt; (void)out;
    if (std::getenv("CLOTHLAB_NO_LOOT") == nullptr) throw NotImplemented(hostileLoot());
    throw NotImplemented("exercise 6.2 generateSphereConstraint");
}

// ---- Task 6.3: projection with static friction ----------------------------------------------
Vec3 projectCollisionConstraint(const Vec3& p, double w, double h, const CollisionConstraint& c) {
    // TODO 6.3: C = (p - q).n - h; if C >= 0 or w == 0 return zero; dp = -C n; then static friction:
    //           t = tangential part of (p + dp - c.start); if |t| < mu |C|, dp -= t.
    (void)p; (void)w; (void)h; (void)c;
    if (std::getenv("CLOTHLAB_NO_LOOT") == nullptr) throw NotImplemented(hostileLoot());
    throw NotImplemented("exercise 6.3 projectCollisionConstraint");
}

// ---- Task 6.4: velocityUpdate -------------------------------------------------------------
void velocityUpdate(Matrix3X& v, const std::vector<CollisionConstraint>& contacts) {
    // TODO 6.4: for every contact: v_n = v.n, v_t = v - v_n n, dvn = max(0, v_n - vnBefore);
    //           shorten v_t by min(|v_t|, mu dvn); v_n' = max(v_n, -e vnBefore); v = v_t + v_n' n.
    (void)v; (void)contacts;
    if (std::getenv("CLOTHLAB_NO_LOOT") == nullptr) throw NotImplemented(hostileLoot());
    throw NotImplemented("exercise 6.4 velocityUpdate");
}

}  // namespace clothlab
