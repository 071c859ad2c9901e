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
    using Handler = std::function<void(Reader& in, Writer& out)>;

    Peer() = default;
    Peer(int in_fd, int out_fd) : in_(in_fd), out_(out_fd) {}
    Peer(const Peer&) = delete;
    Peer& operator=(const Peer&) = delete;

    /// Serves calls (id → handler) until the other side closes the connection.
    void addFunction(uint32_t id, Handler h) { functions_[id] = std::move(h); }
    void serveUntilClosed();

    /// Sends the call `id` with `args`; serves the calls that come back; returns the reply's body.
    std::string roundTrip(uint32_t id, const std::string& args, const char* name);

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

template <class P> void putArg(Writer& w, const std::remove_reference_t<P>& a) {
    if constexpr (std::is_pointer_v<P>) {
        putValue(w, a != nullptr);
        if (a) put(w, *a);
    } else {
        put(w, a);
    }
}
template <class P> void getArg(Reader& r, Held<P>& a) {
    if constexpr (std::is_pointer_v<P>) {
        getValue(r, a.present);
        if (a.present) get(r, a.value);
    } else {
        get(r, a);
    }
}
template <class P> P pass(Held<P>& a) {
    if constexpr (std::is_pointer_v<P>) return a.present ? &a.value : nullptr;
    else return a;
}

template <class P> constexpr bool isOut = (std::is_lvalue_reference_v<P> && !std::is_const_v<std::remove_reference_t<P>>) ||
                                         std::is_pointer_v<P>;

/// The number of particles of a call: the columns of its first 3 x N matrix (or particle set).
inline long long particlesOf() { return -1; }
template <class A, class... B> long long particlesOf(const A& a, const B&... b) {
    if constexpr (std::is_same_v<std::decay_t<A>, Matrix3X>) return a.cols();
    else if constexpr (std::is_same_v<std::decay_t<A>, PbdParticles>) return a.x.cols();
    else return particlesOf(b...);
}

template <class Sig> struct Invoke;
template <class R, class... P> struct Invoke<R(P...)> {
    /// The calling side: sends the arguments, waits, takes the results (in/out arguments keep their sizes).
    static R call(Peer& peer, uint32_t id, const char* name, P... args) {
        struct Release {
            Peer& p;
            size_t m;
            ~Release() { p.release(m); }
        } release{peer, peer.mark()};
        Writer w(&peer);
        w.particles = particlesOf(args...);
        (putArg<P>(w, args), ...);
        const std::string reply = peer.roundTrip(id, w.buffer(), name);
        Reader r(reply, &peer);
        if constexpr (std::is_void_v<R>) {
            (takeOut<P>(r, args, name), ...);
            done(r, name);
        } else {
            R result{};
            get(r, result);
            (takeOut<P>(r, args, name), ...);
            done(r, name);
            return result;
        }
    }

    /// The called side: reads the arguments, calls f, writes the result and the in/out arguments.
    template <class F> static void serve(const F& f, Reader& in, Writer& out) {
        std::tuple<Held<P>...> held;
        std::apply([&](auto&... a) { (getArg<P>(in, a), ...); }, held);
        if (in.left()) throw ProtocolError("a call has more arguments than its function");
        std::apply(
            [&](auto&... a) {
                if constexpr (std::is_void_v<R>) {
                    f(pass<P>(a)...);
                } else {
                    const R result = f(pass<P>(a)...);
                    put(out, result);
                }
                (giveOut<P>(out, a), ...);
            },
            held);
    }

private:
    template <class Q> static void takeOut(Reader& r, Q& a, const char* name) {
        if constexpr (std::is_pointer_v<Q>) {
            bool present = false;
            getValue(r, present);
            if (present != (a != nullptr)) throw ProtocolError(std::string(name) + ": an output that was not asked for");
            if (a) get(r, *a);
        } else if constexpr (isOut<Q>) {
            std::decay_t<Q> v = a;
            get(r, v);
            if (shapeOf(v) != shapeOf(a))
                throw std::runtime_error(std::string(name) + " changed the size of an argument it should only update in place");
            a = std::move(v);
        }
    }
    template <class Q, class H> static void giveOut(Writer& w, H& a) {
        if constexpr (std::is_pointer_v<Q>) {
            putValue(w, a.present);
            if (a.present) put(w, a.value);
        } else if constexpr (isOut<Q>) {
            put(w, a);
        }
    }
    static void done(const Reader& r, const char* name) {
        if (r.left()) throw ProtocolError(std::string(name) + ": a reply longer than its results");
    }
};

// std::function across the wire: the sending side registers it for the duration of the call.
template <class R, class... P> void put(Writer& w, const std::function<R(P...)>& f) {
    uint32_t id = 0;
    if (f) id = w.peer()->addCallback([&f](Reader& in, Writer& out) { Invoke<R(P...)>::serve(f, in, out); }, w.particles);
    putValue(w, id);
}
template <class R, class... P> void get(Reader& r, std::function<R(P...)>& f) {
    uint32_t id = 0;
    getValue(r, id);
    if (id == 0) {
        f = nullptr;
        return;
    }
    Peer* peer = r.peer();
    f = [peer, id](P... args) -> R { return Invoke<R(P...)>::call(*peer, id, "a callback", std::forward<P>(args)...); };
}

}  // namespace clothlab::remote
