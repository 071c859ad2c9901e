#include "clothlab/sim/rk4.h"

namespace clothlab {

void rk4Step(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt, Rk4Workspace& ws) {
    const Eigen::Index n = x.cols();
    ws.f.resize(3, n);
    // Stage slope k = (vs, w F(xs, vs)); returns nothing, leaves the acceleration in ws.f.
    auto accel = [&](const Matrix3X& xs, const Matrix3X& vs) {
        force(xs, vs, ws.f);
        ws.f.array().rowwise() *= w.transpose().array();  // a_i = w_i F_i
    };
    accel(x, v);                                            // k1 = (v, a(x, v))
    ws.dx = v;
    ws.dv = ws.f;
    ws.xs = x + 0.5 * dt * v;
    ws.vs = v + 0.5 * dt * ws.f;
    accel(ws.xs, ws.vs);                                    // k2 at t + dt/2
    ws.dx += 2.0 * ws.vs;
    ws.dv += 2.0 * ws.f;
    ws.xs = x + 0.5 * dt * ws.vs;
    ws.vs = v + 0.5 * dt * ws.f;
    accel(ws.xs, ws.vs);                                    // k3 at t + dt/2
    ws.dx += 2.0 * ws.vs;
    ws.dv += 2.0 * ws.f;
    ws.xs = x + dt * ws.vs;
    ws.vs = v + dt * ws.f;
    accel(ws.xs, ws.vs);                                    // k4 at t + dt
    ws.dx += ws.vs;
    ws.dv += ws.f;
    x += dt / 6.0 * ws.dx;
    v += dt / 6.0 * ws.dv;
}

void rk4Step(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt) {
    Rk4Workspace ws;
    rk4Step(x, v, w, force, dt, ws);
}

}  // namespace clothlab
