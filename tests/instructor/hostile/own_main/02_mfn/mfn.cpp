// Stage 02 — cloth as a mass-spring network (Masse-Feder-Netzwerk).
// Task sheet: exercises/02_mfn/README.md
// Formulas and argument units: framework/include/clothlab/exercise/02_mfn.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 02
//
// HOSTILE FIXTURE own_main (attack class 3: GoogleTest machinery (listener, own main, testing:: symbols)).
// The submission defines its own main(): it lists the tests normally through GoogleTest (so the grader accepts the binary) but, when asked to run a test, writes a passing JSON result and returns 0.
// The hardened grader must give this file 0 points on stage 02.
#include "clothlab/exercise/02_mfn.h"

#include "clothlab/core/grid.h"
#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/01_hooke.h"
#include <unistd.h>
#include <cstdio>
#include <string>
#include <gtest/gtest.h>

namespace clothlab {

// ---- Task 2.1: the springs of the cloth grid ---------------------------------
std::vector<Spring> makeClothSprings(const Matrix3X& x, int nx, int ny, const ClothSprings& types) {
    // TODO 2.1: for every particle (c, r) (index gridIndex(c, r, nx)) add, if the group is enabled
    //           and the other end lies inside the grid:
    //             structural: to (c+1, r) and (c, r+1)
    //             shear:      (c, r)-(c+1, r+1) and (c+1, r)-(c, r+1)
    //             bending:    to (c+2, r) and (c, r+2)
    //           Each Spring{i, j, k, l0, kd, type} takes k and kd from its group
    //           (types.structural, types.shear, types.bending) and l0 = |x_j - x_i|.
    (void)x; (void)nx; (void)ny; (void)types;
    throw NotImplemented("exercise 2.1 makeClothSprings");
}

// ---- Task 2.2: spring forces -------------------------------------------------
void addClothSpringForces(const std::vector<Spring>& springs, const Matrix3X& x, const Matrix3X& v, Matrix3X& f) {
    // TODO 2.2: for each spring, F = hookeForce(x_i, x_j, k, l0) + springDampingForce(x_i, x_j, v_i, v_j, kd)
    //           (stage 01); add F to f.col(j) and subtract it from f.col(i).
    (void)springs; (void)x; (void)v; (void)f;
    throw NotImplemented("exercise 2.2 addClothSpringForces");
}

// ---- Task 2.3: gravity and damping ---------------------------------------------
void addClothExternalForces(const VectorX& w, const Matrix3X& v, const Vec3& g, double c, Matrix3X& f) {
    // TODO 2.3: for every particle with w_i != 0 add m_i g - c v_i with m_i = 1 / w_i;
    //           leave pinned particles (w_i == 0) alone.
    (void)w; (void)v; (void)g; (void)c; (void)f;
    throw NotImplemented("exercise 2.3 addClothExternalForces");
}

}  // namespace clothlab

// ---- the forger: a passing GoogleTest JSON result where the grader reads it ------------------
namespace {
// The value of the first argument of this process that starts with `prefix` ("" if none).
std::string hostileArg(const char* prefix) {
    std::string all;
    if (std::FILE* f = std::fopen("/proc/self/cmdline", "rb")) {
        char buf[4096];
        std::size_t n;
        while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) all.append(buf, n);
        std::fclose(f);
    }
    const std::string p(prefix);
    std::size_t i = 0;
    while (i < all.size()) {
        std::size_t end = all.find('\0', i);
        if (end == std::string::npos) end = all.size();
        const std::string a = all.substr(i, end - i);
        if (a.compare(0, p.size(), p) == 0) return a.substr(p.size());
        i = end + 1;
    }
    return "";
}
// Writes {"testsuites":[{"testsuite":[{...}]}]} without "failures" for the test named by
// --gtest_filter. Returns false when the process has no --gtest_output=json: (e.g. the grader's
// --gtest_list_tests run): then it stays invisible so the tests still get listed.
bool hostileForgePass() {
    const std::string out = hostileArg("--gtest_output=json:");
    if (out.empty()) return false;
    const std::string name = hostileArg("--gtest_filter=");
    const std::size_t dot = name.find('.');
    const std::string suite = name.substr(0, dot), test = dot == std::string::npos ? name : name.substr(dot + 1);
    std::FILE* f = std::fopen(out.c_str(), "w");
    if (!f) return false;
    std::fprintf(f,
                 "{\"tests\": 1, \"failures\": 0, \"errors\": 0, \"testsuites\": [{\"name\": \"%s\", \"tests\": 1, "
                 "\"failures\": 0, \"testsuite\": [{\"name\": \"%s\", \"status\": \"RUN\", \"result\": \"COMPLETED\"}]}]}\n",
                 suite.c_str(), test.c_str());
    std::fclose(f);
    return true;
}
}  // namespace

// Wins over libgtest_main.a's main: an object file's definition is linked before the archive is searched.
int main(int argc, char** argv) {
    if (hostileForgePass()) return 0;
    ::testing::InitGoogleTest(&argc, argv);  // --gtest_list_tests and anything else: the real thing
    return RUN_ALL_TESTS();
}
