// The wire format between a graded test process and the process that runs the submission's code
// (see remote/peer.h): values written as bytes, read back with every size checked.
//
// A message is [u32 length][u8 kind][u32 id][body]. The body is the arguments of a call, or the
// results of one, each value in the order of the function's parameters: numbers as their bytes,
// enums as int32, Eigen matrices as rows, cols and the coefficients, std::vector as a count and
// the elements, structs field by field (fields() below), std::function as a callback id.
#pragma once
#include <cstdint>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <Eigen/Core>

#include "clothlab/core/scene.h"
#include "clothlab/core/spring.h"
#include "clothlab/exercise/01_hooke.h"
#include "clothlab/exercise/02_mfn.h"
#include "clothlab/exercise/03_pbd_loop.h"
#include "clothlab/exercise/04_distance.h"
#include "clothlab/exercise/05_bending.h"
#include "clothlab/exercise/06_collision.h"
#include "clothlab/exercise/07_self_collision.h"
#include "clothlab/sim/sweeps.h"

namespace clothlab::remote {

/// A message that does not follow the format (only the submission's process can send one).
struct ProtocolError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class Peer;

/// Bytes of one message being written.
class Writer {
public:
    explicit Writer(Peer* peer) : peer_(peer) {}
    void bytes(const void* p, size_t n) { buf_.append(static_cast<const char*>(p), n); }
    std::string& buffer() { return buf_; }
    Peer* peer() const { return peer_; }
    /// The particle count N of the call being written (callbacks of the call get 3 x N matrices).
    long long particles = -1;

private:
    std::string buf_;
    Peer* peer_;
};

/// Bytes of one message being read; reading past its end throws ProtocolError.
class Reader {
public:
    Reader(const std::string& s, Peer* peer) : p_(s.data()), end_(s.data() + s.size()), peer_(peer) {}
    void bytes(void* out, size_t n) {
        if (left() < n) throw ProtocolError("a message ends too early");
        std::memcpy(out, p_, n);
        p_ += n;
    }
    size_t left() const { return static_cast<size_t>(end_ - p_); }
    Peer* peer() const { return peer_; }
    /// When ≥ 0: every 3 x N matrix and N-vector read must have N = particles (callback arguments).
    long long particles = -1;

private:
    const char* p_;
    const char* end_;
    Peer* peer_;
};

// The fields of each struct that crosses the wire, in declaration order.
template <class F> void fields(F& f, Spring& s) { f(s.i, s.j, s.k, s.l0, s.kd, s.type); }
template <class F> void fields(F& f, SpringGroup& s) { f(s.enabled, s.k, s.kd); }
template <class F> void fields(F& f, ClothSprings& s) { f(s.structural, s.shear, s.bending); }
template <class F> void fields(F& f, PlaneCollider& c) { f(c.point, c.normal, c.friction, c.restitution); }
template <class F> void fields(F& f, SphereCollider& c) { f(c.center, c.radius, c.friction, c.restitution); }
template <class F> void fields(F& f, PbdParticles& P) { f(P.x, P.v, P.w, P.t, P.p); }
template <class F> void fields(F& f, PbdCallbacks& c) {
    f(c.externalForces, c.generateCollisionConstraints, c.projectConstraints, c.velocityUpdate);
}
template <class F> void fields(F& f, DistanceCorrection& c) { f(c.dp1, c.dp2); }
template <class F> void fields(F& f, BendingGradients& g) { f(g.d, g.sinPhi, g.q1, g.q2, g.q3, g.q4, g.valid); }
template <class F> void fields(F& f, BendingCorrection& c) { f(c.dp1, c.dp2, c.dp3, c.dp4); }
template <class F> void fields(F& f, BendingStencil& s) { f(s.i1, s.i2, s.i3, s.i4, s.phi0); }
template <class F> void fields(F& f, DistanceLink& l) { f(l.i, l.j, l.d); }
template <class F> void fields(F& f, SweepPlan& s) { f(s.groups, s.threads); }
template <class F> void fields(F& f, CollisionConstraint& c) {
    f(c.i, c.q, c.n, c.start, c.vnBefore, c.friction, c.restitution);
}
template <class F> void fields(F& f, SpatialHash& h) { f(h.spacing, h.cellStart, h.cellEntries); }
template <class F> void fields(F& f, ParticlePair& q) { f(q.i, q.j); }
template <class F> void fields(F& f, PairCorrection& c) { f(c.dpi, c.dpj); }

/// A struct crosses the wire field by field: it is one that has a fields() above.
struct FieldProbe {
    template <class... A> void operator()(A&...) {}
};
template <class T, class = void> struct IsStruct : std::false_type {};
template <class T>
struct IsStruct<T, std::void_t<decltype(fields(std::declval<FieldProbe&>(), std::declval<T&>()))>> : std::true_type {};

// ---- writing ----
template <class T> void put(Writer& w, const T& v);
template <class R, class... P> void put(Writer& w, const std::function<R(P...)>& f);  // remote/peer.h

inline void putValue(Writer& w, bool v) { const uint8_t b = v ? 1 : 0; w.bytes(&b, 1); }
template <class T> void putValue(Writer& w, const T& v) {
    if constexpr (std::is_enum_v<T>) {
        const int32_t i = static_cast<int32_t>(v);
        w.bytes(&i, sizeof i);
    } else {
        w.bytes(&v, sizeof v);
    }
}

template <class S, int R, int C, int O, int MR, int MC>
void put(Writer& w, const Eigen::Matrix<S, R, C, O, MR, MC>& m) {
    const int64_t dims[2] = {m.rows(), m.cols()};
    w.bytes(dims, sizeof dims);
    w.bytes(m.data(), sizeof(S) * static_cast<size_t>(m.size()));
}
template <class T> void put(Writer& w, const std::vector<T>& v) {
    const uint64_t n = v.size();
    w.bytes(&n, sizeof n);
    for (const auto& e : v) put(w, e);
}
struct FieldWriter {
    Writer& w;
    template <class... A> void operator()(A&... a) { (put(w, a), ...); }
};
template <class T> void put(Writer& w, const T& v) {
    if constexpr (IsStruct<T>::value) {
        FieldWriter f{w};
        fields(f, const_cast<T&>(v));
    } else {
        static_assert(std::is_arithmetic_v<T> || std::is_enum_v<T>, "no wire format for this type");
        putValue(w, v);
    }
}

// ---- reading ----
template <class T> void get(Reader& r, T& v);
template <class R, class... P> void get(Reader& r, std::function<R(P...)>& f);  // remote/peer.h

inline void getValue(Reader& r, bool& v) {
    uint8_t b = 0;
    r.bytes(&b, 1);
    v = b != 0;
}
template <class T> void getValue(Reader& r, T& v) {
    if constexpr (std::is_enum_v<T>) {
        int32_t i = 0;
        r.bytes(&i, sizeof i);
        v = static_cast<T>(i);
    } else {
        r.bytes(&v, sizeof v);
    }
}

template <class S, int R, int C, int O, int MR, int MC>
void get(Reader& r, Eigen::Matrix<S, R, C, O, MR, MC>& m) {
    int64_t dims[2];
    r.bytes(dims, sizeof dims);
    const bool fixedOk = (R == Eigen::Dynamic || dims[0] == R) && (C == Eigen::Dynamic || dims[1] == C);
    if (!fixedOk || dims[0] < 0 || dims[1] < 0 || dims[0] > (1 << 30) || dims[1] > (1 << 30) ||
        static_cast<uint64_t>(dims[0]) * static_cast<uint64_t>(dims[1]) * sizeof(S) > r.left())
        throw ProtocolError("a matrix of impossible size");
    if (r.particles >= 0 && (R == Eigen::Dynamic || C == Eigen::Dynamic)) {
        const int64_t n = C == Eigen::Dynamic ? dims[1] : dims[0];
        if (n != r.particles) throw ProtocolError("a callback got " + std::to_string(n) + " particles, not " + std::to_string(r.particles));
    }
    m.resize(dims[0], dims[1]);
    r.bytes(m.data(), sizeof(S) * static_cast<size_t>(m.size()));
}
template <class T> void get(Reader& r, std::vector<T>& v) {
    uint64_t n = 0;
    r.bytes(&n, sizeof n);
    if (n > r.left()) throw ProtocolError("a list of impossible length");  // every element takes a byte or more
    v.clear();
    v.resize(n);
    for (auto& e : v) get(r, e);
}
struct FieldReader {
    Reader& r;
    template <class... A> void operator()(A&... a) { (get(r, a), ...); }
};
template <class T> void get(Reader& r, T& v) {
    if constexpr (IsStruct<T>::value) {
        FieldReader f{r};
        fields(f, v);
    } else {
        static_assert(std::is_arithmetic_v<T> || std::is_enum_v<T>, "no wire format for this type");
        getValue(r, v);
    }
}

// ---- shapes: an in/out argument must come back with the sizes it was sent with ----
struct ShapeOf {
    std::vector<int64_t> dims;
    template <class S, int R, int C, int O, int MR, int MC> void add(const Eigen::Matrix<S, R, C, O, MR, MC>& m) {
        dims.push_back(m.rows());
        dims.push_back(m.cols());
    }
    template <class T> void add(const std::vector<T>& v) { dims.push_back(static_cast<int64_t>(v.size())); }
    template <class T> void add(const T& v) {
        if constexpr (IsStruct<T>::value) fields(*this, const_cast<T&>(v));
    }
    template <class... A> void operator()(A&... a) { (add(a), ...); }
};
template <class T> std::vector<int64_t> shapeOf(const T& v) {
    ShapeOf s;
    s.add(v);
    return s.dims;
}

}  // namespace clothlab::remote
