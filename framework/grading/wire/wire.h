// The values that cross between a graded test process and the submission process (wire/peer.h),
// as nlohmann::json in its binary form CBOR: a call's arguments are one JSON array, its results
// another. Each struct that crosses is declared once below with CLOTHLAB_WIRE. Numbers cross bit
// for bit: a single value as a JSON number (CBOR keeps a double's 64 bits), a fixed-size matrix as a
// CBOR byte string of its coefficients, a dynamic one as [rows, cols, coefficients], and a list of
// numbers, matrices or flat structs as byte strings, one per field (a step's thousands of springs in
// a few memcpy()s, not a JSON value per spring).
// std::function crosses as a callback id the other side calls back.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "clothlab/core/spring.h"
#include "clothlab/core/state.h"
#include "clothlab/exercise/01_hooke.h"
#include "clothlab/exercise/02_mfn.h"
#include "clothlab/exercise/03_pbd_loop.h"
#include "clothlab/exercise/04_distance.h"
#include "clothlab/exercise/05_bending.h"
#include "clothlab/exercise/06_collision.h"
#include "clothlab/exercise/07_self_collision.h"
#include "clothlab/sim/sweeps.h"

namespace clothlab::wire {

using json = nlohmann::json;

/// A message that does not follow the format (only the submission's process can send one).
struct ProtocolError : std::runtime_error { using std::runtime_error::runtime_error; };

class Peer;

/// What encoding and decoding a call needs to know (set for the duration of one call, per thread):
/// the peer that callbacks go through, and the particle count N of the call (a callback's 3 x N
/// matrices must have this N).
struct CallContext {
    Peer* peer = nullptr;
    long long particles = -1;
    /// When ≥ 0, while a reply is read: the particle count of the call, which every particle index
    /// in the reply must be below (the framework indexes its arrays with them).
    long long indexLimit = -1;
};
CallContext& callContext();

/// Sets the call context for a scope and puts the previous one back at its end.
struct ContextScope {
    ContextScope(Peer* peer, long long particles, long long indexLimit = -1) : saved(callContext()) {
        callContext() = {peer, particles, indexLimit};
    }
    ~ContextScope() { callContext() = saved; }
    ContextScope(const ContextScope&) = delete;  // (and no assignment: `saved` is const)
    const CallContext saved;
};

}  // namespace clothlab::wire

/// Declares how struct T crosses the wire: one name per field, in order. The structured binding
/// does not compile unless the list names every field of T (so none is left out by mistake).
#define CLOTHLAB_WIRE(T, ...)                                                                         \
    inline auto wireFields(T& value) {                                                                \
        auto& [__VA_ARGS__] = value;                                                                  \
        return std::tie(__VA_ARGS__);                                                                 \
    }

namespace clothlab {
CLOTHLAB_WIRE(Spring, i, j, k, l0, kd, type)
CLOTHLAB_WIRE(SpringGroup, enabled, k, kd)
CLOTHLAB_WIRE(ClothSprings, structural, shear, bending)
CLOTHLAB_WIRE(PlaneCollider, point, normal, friction, restitution)
CLOTHLAB_WIRE(SphereCollider, center, radius, friction, restitution)
CLOTHLAB_WIRE(State, x, v, w, t)
CLOTHLAB_WIRE(PbdCallbacks, externalForces, generateCollisionConstraints, projectConstraints, velocityUpdate)
CLOTHLAB_WIRE(DistanceCorrection, dp1, dp2)
CLOTHLAB_WIRE(BendingGradients, d, sinPhi, q1, q2, q3, q4, valid)
CLOTHLAB_WIRE(BendingCorrection, dp1, dp2, dp3, dp4)
CLOTHLAB_WIRE(BendingStencil, i1, i2, i3, i4, phi0)
CLOTHLAB_WIRE(DistanceLink, i, j, d)
CLOTHLAB_WIRE(SweepPlan, groups, threads)
CLOTHLAB_WIRE(CollisionConstraint, i, q, n, start, vnBefore, friction, restitution)
CLOTHLAB_WIRE(SpatialHash, spacing, cellStart, cellEntries)
CLOTHLAB_WIRE(ParticlePair, i, j)
CLOTHLAB_WIRE(PairCorrection, dpi, dpj)
// The fields that index particles: checked against the call's particle count in every reply.
// (An array, not a vector: a step's thousands of pairs are checked without allocating.)
inline std::array<int, 2> particleIndices(const Spring& s) { return {s.i, s.j}; }
inline std::array<int, 4> particleIndices(const BendingStencil& b) { return {b.i1, b.i2, b.i3, b.i4}; }
inline std::array<int, 2> particleIndices(const DistanceLink& l) { return {l.i, l.j}; }
inline std::array<int, 2> particleIndices(const ParticlePair& q) { return {q.i, q.j}; }
inline std::array<int, 1> particleIndices(const CollisionConstraint& c) { return {c.i}; }
// PbdParticles is a State with the predicted positions p (fields in two classes: no structured
// binding); the size check fails when either gains a field.
inline auto wireFields(PbdParticles& P) { return std::tie(P.x, P.v, P.w, P.t, P.p); }
static_assert(sizeof(PbdParticles) == sizeof(Matrix3X) * 3 + sizeof(VectorX) + sizeof(double), "PbdParticles: a field that does not cross");
}  // namespace clothlab

namespace clothlab::wire {

/// A fixed-size or dynamic Eigen matrix.
template <class T> struct IsMatrix : std::false_type {};
template <class S, int R, int C, int O, int MR, int MC> struct IsMatrix<Eigen::Matrix<S, R, C, O, MR, MC>> : std::true_type {};
template <class T> struct IsVector : std::false_type {};
template <class T> struct IsVector<std::vector<T>> : std::true_type {};
template <class T> struct IsFunction : std::false_type {};
template <class R, class... P> struct IsFunction<std::function<R(P...)>> : std::true_type {};
template <class T, class = void> struct HasFields : std::false_type {};
template <class T> struct HasFields<T, std::void_t<decltype(wireFields(std::declval<T&>()))>> : std::true_type {};

template <class T, class = void> struct HasIndices : std::false_type {};
template <class T> struct HasIndices<T, std::void_t<decltype(particleIndices(std::declval<const T&>()))>> : std::true_type {};

/// A value read from a reply whose particle indices name no particle of the call is refused.
template <class T> void checkParticles(const T& v) {
    const long long n = callContext().indexLimit;
    if constexpr (HasIndices<T>::value)
        if (n >= 0)
            for (int i : particleIndices(v))
                if (i < 0 || i >= n)
                    throw std::out_of_range("particle index " + std::to_string(i) + " in the result, but the call has " +
                                            std::to_string(n) + " particles (0.." + std::to_string(n - 1) + ")");
}

/// Values of fixed size, stored as their bytes in a list: numbers, enums and fixed-size matrices.
template <class T> constexpr bool isBits() {
    if constexpr (IsMatrix<T>::value) return T::SizeAtCompileTime != Eigen::Dynamic;
    else return std::is_arithmetic_v<T> || std::is_enum_v<T>;
}
/// The types of T's fields (T declared with CLOTHLAB_WIRE).
template <class T> using FieldsOf = decltype(wireFields(std::declval<T&>()));
template <class Tuple> struct AllBits;
template <class... F> struct AllBits<std::tuple<F...>> : std::bool_constant<(isBits<std::decay_t<F>>() && ...)> {};
/// A struct whose fields are all of fixed size: a list of them crosses as one column per field.
template <class T> constexpr bool isFlat() {
    if constexpr (HasFields<T>::value) return AllBits<FieldsOf<T>>::value;
    else return false;
}

/// Registers f as a callback of the current call (wire/peer.h): its id, 0 for an empty function.
template <class R, class... P> uint32_t callbackId(const std::function<R(P...)>& f);
/// Makes f call the other side's callback `id` through the current call's peer (none for id 0).
template <class R, class... P> void callbackOf(uint32_t id, std::function<R(P...)>& f);

template <class T> json toWire(const T& v);
template <class T> void fromWire(const json& j, T& v);

inline json bytesOf(const void* p, size_t n) {
    const auto* b = static_cast<const std::uint8_t*>(p);
    return json::binary(std::vector<std::uint8_t>(b, b + n));
}
/// The byte string j, which must hold `count` values of `size` bytes each.
inline const std::vector<std::uint8_t>& bytesIn(const json& j, size_t count, size_t size) {
    if (!j.is_binary() || j.get_binary().size() != count * size) throw ProtocolError("a value of impossible size");
    return j.get_binary();
}

/// A list of fixed-size values as one byte string: a bool as one byte, anything else as its bytes,
/// which for an enum are an int32's and for a fixed-size matrix only its coefficients.
template <class T> constexpr bool bytesAreTheValue() {
    if constexpr (IsMatrix<T>::value) return sizeof(T) == T::SizeAtCompileTime * sizeof(typename T::Scalar);
    else return !std::is_enum_v<T> || sizeof(T) == 4;
}
template <class T> json bitsToWire(const std::vector<T>& v) {
    static_assert(bytesAreTheValue<T>(), "a value whose bytes are not its wire format");
    if constexpr (!std::is_same_v<T, bool>) return bytesOf(v.data(), v.size() * sizeof(T));
    else return bytesOf(std::vector<std::uint8_t>(v.begin(), v.end()).data(), v.size());
}
template <class T> void bitsFromWire(const json& j, size_t count, std::vector<T>& v) {
    static_assert(bytesAreTheValue<T>(), "a value whose bytes are not its wire format");
    v.resize(count);
    const auto& b = bytesIn(j, count, sizeof(T));
    if constexpr (!std::is_same_v<T, bool>) std::memcpy(static_cast<void*>(v.data()), b.data(), b.size());
    else std::transform(b.begin(), b.end(), v.begin(), [](std::uint8_t x) { return x != 0; });
}

/// Field I of every element of a list of flat structs, as one byte string.
template <size_t I, class E> json columnToWire(const std::vector<E>& v) {
    std::vector<std::decay_t<std::tuple_element_t<I, FieldsOf<E>>>> c(v.size());
    for (size_t i = 0; i < v.size(); ++i) c[i] = std::get<I>(wireFields(const_cast<E&>(v[i])));
    return bitsToWire(c);
}
template <size_t I, class E> void columnFromWire(const json& j, std::vector<E>& v) {
    std::vector<std::decay_t<std::tuple_element_t<I, FieldsOf<E>>>> c;
    bitsFromWire(j, v.size(), c);
    for (size_t i = 0; i < v.size(); ++i) std::get<I>(wireFields(v[i])) = c[i];
}
template <class E, size_t... I> json columnsToWire(const std::vector<E>& v, std::index_sequence<I...>) {
    return json::array({json(v.size()), columnToWire<I>(v)...});
}
template <class E, size_t... I> void columnsFromWire(const json& j, std::vector<E>& v, std::index_sequence<I...>) {
    if (!j.is_array() || j.size() != 1 + sizeof...(I)) throw ProtocolError("a list of the wrong form");
    const size_t count = j[0].get<size_t>();
    if (count > (1u << 30)) throw ProtocolError("a list of impossible length");
    v.assign(count, E{});
    (columnFromWire<I>(j[1 + I], v), ...);
    for (const E& e : v) checkParticles(e);
}

template <class T> json toWire(const T& v) {
    if constexpr (IsFunction<T>::value) {
        return callbackId(v);
    } else if constexpr (IsMatrix<T>::value && isBits<T>()) {  // fixed size: its coefficients alone
        static_assert(bytesAreTheValue<T>(), "a matrix whose bytes are not its coefficients");
        return bytesOf(v.data(), sizeof(T));
    } else if constexpr (IsMatrix<T>::value) {
        return json::array({v.rows(), v.cols(), bytesOf(v.data(), sizeof(typename T::Scalar) * v.size())});
    } else if constexpr (IsVector<T>::value) {
        using E = typename T::value_type;
        if constexpr (isBits<E>()) {
            return json::array({v.size(), bitsToWire(v)});
        } else if constexpr (isFlat<E>()) {  // [count, column of the first field, column of the second, ...]
            return columnsToWire(v, std::make_index_sequence<std::tuple_size_v<FieldsOf<E>>>());
        } else {
            json j = json::array();
            for (const E& e : v) j.push_back(toWire(e));
            return j;
        }
    } else if constexpr (HasFields<T>::value) {
        json j = json::array();
        std::apply([&](const auto&... f) { (j.push_back(toWire(f)), ...); }, wireFields(const_cast<T&>(v)));
        return j;
    } else {
        static_assert(isBits<T>(), "no wire format for this type");
        return v;
    }
}

template <class T> void fromWire(const json& j, T& v) {
    if constexpr (IsFunction<T>::value) {
        callbackOf(j.get<std::uint32_t>(), v);
    } else if constexpr (IsMatrix<T>::value && isBits<T>()) {
        std::memcpy(v.data(), bytesIn(j, 1, sizeof(T)).data(), sizeof(T));
    } else if constexpr (IsMatrix<T>::value) {
        using S = typename T::Scalar;
        const long long rows = j.at(0).get<long long>(), cols = j.at(1).get<long long>();
        if ((T::RowsAtCompileTime != Eigen::Dynamic && rows != T::RowsAtCompileTime) ||
            (T::ColsAtCompileTime != Eigen::Dynamic && cols != T::ColsAtCompileTime) || rows < 0 || cols < 0 ||
            rows > (1 << 30) || cols > (1 << 30))
            throw ProtocolError("a matrix of impossible size");
        const long long particles = callContext().particles;
        const long long n = T::ColsAtCompileTime == Eigen::Dynamic ? cols : rows;
        if (particles >= 0 && T::SizeAtCompileTime == Eigen::Dynamic && n != particles)
            throw ProtocolError("a callback got a matrix for " + std::to_string(n) + " particles, not " + std::to_string(particles));
        const auto& b = bytesIn(j.at(2), static_cast<size_t>(rows) * static_cast<size_t>(cols), sizeof(S));
        v.resize(rows, cols);
        std::memcpy(v.data(), b.data(), b.size());
    } else if constexpr (IsVector<T>::value) {
        using E = typename T::value_type;
        if constexpr (isBits<E>()) {
            const size_t count = j.at(0).get<size_t>();
            if (j.size() != 2 || count > (1u << 30)) throw ProtocolError("a list of the wrong form");
            bitsFromWire(j[1], count, v);
        } else if constexpr (isFlat<E>()) {
            columnsFromWire(j, v, std::make_index_sequence<std::tuple_size_v<FieldsOf<E>>>());
        } else {
            if (!j.is_array()) throw ProtocolError("a list of the wrong form");
            v.assign(j.size(), E{});
            for (size_t i = 0; i < j.size(); ++i) fromWire(j[i], v[i]);
        }
    } else if constexpr (HasFields<T>::value) {
        auto fields = wireFields(v);
        if (!j.is_array() || j.size() != std::tuple_size_v<decltype(fields)>) throw ProtocolError("a struct with the wrong number of fields");
        size_t k = 0;
        std::apply([&](auto&... f) { (fromWire(j[k++], f), ...); }, fields);
        checkParticles(v);
    } else {
        static_assert(isBits<T>(), "no wire format for this type");
        if (!j.is_number() && !j.is_boolean()) throw ProtocolError("a number that is not a number");
        j.get_to(v);
    }
}

/// The sizes in a value (lengths of lists, matrix dimensions), in order: an in/out argument must
/// come back with the sizes it was sent with.
inline void shapeOf(const json& j, std::vector<long long>& out) {
    if (j.is_binary()) out.push_back(static_cast<long long>(j.get_binary().size()));
    if (j.is_array()) out.push_back(static_cast<long long>(j.size()));
    if (j.is_structured())
        for (const auto& e : j) shapeOf(e, out);
}

}  // namespace clothlab::wire
