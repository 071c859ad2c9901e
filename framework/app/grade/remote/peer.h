// The submission's code runs in a process of its own.
//
// When the grader links a graded test binary, the functions of every stage whose code comes from
// the submission are replaced by proxies (remote/proxies_NN.cpp): a proxy sends its arguments to
// a second program, the *submission process* (remote/serve_main.cpp: the submission's objects and
// nothing of the tests), which calls the submission's function and sends the results back.
// The test process, which writes the verdict, never executes a
// byte of the submission's code; the submission process cannot read or write its memory.
//
// Callbacks (a ForceField, PbdCallbacks) go the other way: the submission process sends their
// arguments back, the test process runs them, so a test sees every call of its callbacks.
// Exceptions cross too (NotImplemented stays NotImplemented). If the submission process crashes,
// the call throws "your code crashed ..." and the next call starts a new process.
//
// Both sides are a Peer: send a call, then serve whatever calls come back until the reply.
#pragma once
#include <sys/types.h>

#include <algorithm>
#include <deque>
#include <map>
#include <string>
#include <tuple>
#include <utility>

#include "clothlab/core/not_implemented.h"
#include "remote/wire.h"

namespace clothlab::remote {

/// The submission process ended or broke the protocol: the call cannot finish (never sent back).
struct PeerFailure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// An exception a callback threw in the test process, as the submission process sees it.
struct CallbackFailed : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class Peer {
public:
    /// A function or callback: its arguments in, its results out.
    using Handler = std::function<json(const json& arguments)>;

    Peer() = default;
    Peer(int in_fd, int out_fd) : in_(in_fd), out_(out_fd) {}
    Peer(const Peer&) = delete;
    Peer& operator=(const Peer&) = delete;

    /// Serves calls (id → handler) until the other side closes the connection.
    void addFunction(uint32_t id, Handler h) { functions_[id] = std::move(h); }
    void serveUntilClosed();

    /// Sends the call `id` with `args`; serves the calls that come back; returns the results.
    json roundTrip(uint32_t id, const json& args, const char* name);

    /// A callback the other side may call during the current call: its id; forgotten at release(mark).
    uint32_t addCallback(Handler h, long long particles);
    size_t mark() const { return callbacks_.size(); }
    void release(size_t mark) { callbacks_.resize(std::min(mark, callbacks_.size())); }

    // The test side: the submission process this peer talks to.
    bool connected() const { return in_ >= 0; }
    void attach(int in_fd, int out_fd, pid_t pid) { in_ = in_fd; out_ = out_fd; pid_ = pid; }
    /// Closes the connection, kills the process, and says how it ended ("" if it was still running).
    /// `ended`: it closed the connection, so wait up to a second for it to end on its own.
    std::string disconnect(bool ended = false);

private:
    enum class Kind : uint8_t { Invoke = 1, Return = 2, Throw = 3 };
    struct Message {
        Kind kind;
        uint32_t id;
        std::string body;
    };
    struct Callback {
        Handler handler;
        long long particles;
    };
    void send(Kind kind, uint32_t id, const std::string& body);
    bool receive(Message& m);  ///< false at the end of the connection
    /// At least n unread bytes in buffered_; false at the end of the connection. `started`: inside
    /// a message, whose rest must not pause longer than a few seconds.
    bool fill(size_t n, bool started);
    void handle(const Message& m);
    [[noreturn]] void rethrow(const std::string& body, const char* name);

    int in_ = -1, out_ = -1;
    pid_t pid_ = -1;
    std::map<uint32_t, Handler> functions_;
    std::deque<Callback> callbacks_;  ///< a deque: registering a callback moves none of the others
    std::string buffered_;  ///< bytes read, not yet taken (from used_ on)
    size_t used_ = 0;
};

/// The test side's peer, started on first use (remote/client.cpp).
Peer& submissionProcess();

// ---- calls of a function R(P...) across the wire ----

/// How the receiving side holds a parameter of type P: a copy; a pointer as an optional value.
template <class T> struct Optional {
    bool present = false;
    T value{};
};
template <class P> struct HeldOf { using type = std::decay_t<P>; };
template <class T> struct HeldOf<T*> { using type = Optional<T>; };
template <class P> using Held = typename HeldOf<P>::type;

/// An argument as it is sent: a pointer as null or the value it points to.
template <class P> json sent(const std::remove_reference_t<P>& a) {
    if constexpr (std::is_pointer_v<P>) return a ? toWire(*a) : json(nullptr);
    else return toWire(a);
}
template <class P> void received(const json& j, Held<P>& a) {
    if constexpr (std::is_pointer_v<P>) {
        a.present = !j.is_null();
        if (a.present) fromWire(j, a.value);
    } else {
        fromWire(j, a);
    }
}
template <class P> P pass(Held<P>& a) {
    if constexpr (std::is_pointer_v<P>) return a.present ? &a.value : nullptr;
    else return a;
}

/// An in/out argument: a non-const reference or a pointer; it is sent back after the call.
template <class P> constexpr bool isOut = (std::is_lvalue_reference_v<P> && !std::is_const_v<std::remove_reference_t<P>>) ||
                                         std::is_pointer_v<P>;

/// The number of particles of a call: the columns of its first 3 x N matrix (or particle set).
inline long long particlesOf() { return -1; }
template <class A, class... B> long long particlesOf(const A& a, const B&... b) {
    if constexpr (std::is_same_v<std::decay_t<A>, Matrix3X>) return a.cols();
    else if constexpr (std::is_same_v<std::decay_t<A>, PbdParticles>) return a.x.cols();
    else return particlesOf(b...);
}

/// Runs `decode`; a value of the wrong type or shape is a ProtocolError.
template <class F> void decoding(const char* name, F&& decode) {
    try {
        decode();
    } catch (const json::exception& e) {
        throw ProtocolError(std::string(name) + ": " + e.what());
    }
}

template <class Sig> struct Invoke;
template <class R, class... P> struct Invoke<R(P...)> {
    /// The calling side: sends [arguments...], waits, takes [result, in/out arguments...] (the
    /// in/out arguments must keep their sizes).
    static R call(Peer& peer, uint32_t id, const char* name, P... args) {
        struct Release {
            Peer& p;
            size_t m;
            ~Release() { p.release(m); }
        } release{peer, peer.mark()};
        json arguments = json::array();
        {
            ContextScope scope(&peer, particlesOf(args...));  // callbacks among the arguments register here
            (arguments.push_back(sent<P>(args)), ...);
        }
        const json reply = peer.roundTrip(id, arguments, name);
        ContextScope scope(&peer, -1, particlesOf(args...));
        size_t k = 0, n = 0;
        const auto next = [&]() -> const json& {
            if (!reply.is_array() || k >= reply.size()) throw ProtocolError(std::string(name) + ": a reply shorter than its results");
            return reply[k++];
        };
        std::conditional_t<std::is_void_v<R>, int, R> result{};
        try {
            decoding(name, [&] {
                if constexpr (!std::is_void_v<R>) fromWire(next(), result);
                (takeOut<P>(next, arguments[n++], args, name), ...);
            });
        } catch (const std::out_of_range& e) {
            throw std::out_of_range(std::string(name) + " returned a " + e.what());
        }
        if (k != reply.size()) throw ProtocolError(std::string(name) + ": a reply longer than its results");
        if constexpr (!std::is_void_v<R>) return result;
    }

    /// The called side: takes the arguments, calls f, returns [result, in/out arguments...].
    template <class F> static json serve(const F& f, const json& in) {
        if (!in.is_array() || in.size() != sizeof...(P)) throw ProtocolError("a call with the wrong number of arguments");
        std::tuple<Held<P>...> held;
        size_t k = 0;
        decoding("a call", [&] { std::apply([&](auto&... a) { (received<P>(in[k++], a), ...); }, held); });
        json out = json::array();
        std::apply(
            [&](auto&... a) {
                if constexpr (std::is_void_v<R>) f(pass<P>(a)...);
                else out.push_back(toWire(f(pass<P>(a)...)));
                (giveOut<P>(out, a), ...);
            },
            held);
        return out;
    }

private:
    template <class Q, class Next> static void takeOut(const Next& next, const json& before, Q& a, const char* name) {
        if constexpr (isOut<Q>) {
            const json& after = next();
            if constexpr (std::is_pointer_v<Q>) {
                if (after.is_null() != (a == nullptr)) throw ProtocolError(std::string(name) + ": an output that was not asked for");
                if (a) fromWire(after, *a);
            } else {
                std::vector<long long> was, is;
                shapeOf(before, was);
                shapeOf(after, is);
                if (was != is) throw std::runtime_error(std::string(name) + " changed the size of an argument it should only update in place");
                fromWire(after, a);
            }
        }
    }
    template <class Q, class H> static void giveOut(json& out, H& a) {
        if constexpr (std::is_pointer_v<Q>) out.push_back(a.present ? toWire(a.value) : json(nullptr));
        else if constexpr (isOut<Q>) out.push_back(toWire(a));
    }
};

template <class R, class... P> uint32_t callbackId(const std::function<R(P...)>& f) {
    const CallContext c = callContext();
    if (!f) return 0;
    if (!c.peer) throw ProtocolError("a callback outside a call");
    return c.peer->addCallback([&f](const json& in) { return Invoke<R(P...)>::serve(f, in); }, c.particles);
}
template <class R, class... P> void callbackOf(uint32_t id, std::function<R(P...)>& f) {
    Peer* peer = callContext().peer;
    if (id != 0 && !peer) throw ProtocolError("a callback outside a call");
    if (id == 0) f = nullptr;
    else f = [peer, id](P... args) -> R { return Invoke<R(P...)>::call(*peer, id, "a callback", std::forward<P>(args)...); };
}

}  // namespace clothlab::remote
