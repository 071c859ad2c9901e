// Messages between the test process and the submission process (see wire/peer.h).
#include "wire/peer.h"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace clothlab::wire {

namespace {

constexpr uint32_t kMaxMessage = 1u << 30;  // bytes
constexpr uint32_t kFirstCallback = 1u << 24;
constexpr int kMessageStallMs = 5000;  // the longest pause inside one message

enum class Thrown : uint8_t { NotImplemented = 1, InvalidArgument, OutOfRange, DomainError, LogicError, Other, Callback };

bool writeAll(int fd, const char* p, size_t n) {
    while (n > 0) {
        const ssize_t k = ::write(fd, p, n);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) return false;
        p += k;
        n -= static_cast<size_t>(k);
    }
    return true;
}

std::string thrown(Thrown kind, const std::string& text) { return std::string(1, static_cast<char>(kind)) + text.substr(0, 4000); }

}  // namespace

CallContext& callContext() {
    thread_local CallContext context;
    return context;
}

void Peer::send(Kind kind, uint32_t id, const std::string& body) {
    if (body.size() + 5 > kMaxMessage) throw PeerFailure("a message of " + std::to_string(body.size()) + " bytes is too long");
    std::string message(9, '\0');  // one write() per message
    const uint32_t length = static_cast<uint32_t>(body.size() + 5);
    std::memcpy(&message[0], &length, 4);
    message[4] = static_cast<char>(kind);
    std::memcpy(&message[5], &id, 4);
    message += body;
    if (!writeAll(out_, message.data(), message.size())) throw PeerFailure("the other process is gone");
}

bool Peer::fill(size_t n, bool started) {
    while (buffered_.size() - used_ < n) {
        if (used_ > 0) {
            buffered_.erase(0, used_);
            used_ = 0;
        }
        // A message is written with one write(): once it has begun, the rest follows at once. A
        // message that stops halfway (a forged length, say) is an error, not a wait for ever.
        if (started) {
            pollfd p{in_, POLLIN, 0};
            int ready;
            while ((ready = ::poll(&p, 1, kMessageStallMs)) < 0 && errno == EINTR) {
            }
            if (ready == 0) throw ProtocolError("a message stopped halfway");
        }
        char chunk[65536];
        const ssize_t k = ::read(in_, chunk, sizeof chunk);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) return false;
        buffered_.append(chunk, static_cast<size_t>(k));
    }
    return true;
}

bool Peer::receive(Message& m) {
    uint32_t length = 0;
    if (!fill(9, false)) return false;  // length, kind, id
    std::memcpy(&length, buffered_.data() + used_, 4);
    if (length < 5 || length > kMaxMessage) throw ProtocolError("a message of impossible length");
    const auto kind = static_cast<Kind>(buffered_[used_ + 4]);
    if (kind != Kind::Invoke && kind != Kind::Return && kind != Kind::Throw) throw ProtocolError("a message of unknown kind");
    if (!fill(4 + length, true)) return false;
    const char* all = buffered_.data() + used_ + 4;
    m.kind = kind;
    std::memcpy(&m.id, all + 1, 4);
    m.body.assign(all + 5, length - 5);
    used_ += 4 + length;
    return true;
}

uint32_t Peer::addCallback(Handler h, long long particles) {
    callbacks_.push_back({std::move(h), particles});
    return kFirstCallback + static_cast<uint32_t>(callbacks_.size() - 1);
}

// A message's body: [u64 n][n bytes of CBOR][the long byte strings, one after the other]. In the
// CBOR a byte string of kMovedOut bytes or more is replaced by {"bytes": its length}: nlohmann's CBOR
// reader takes a byte string byte by byte, which made grading three times slower than one memcpy()
// per string; a short one (a Vec3's 24 bytes) stays inside, where the object in its place would cost
// more allocations than the bytes it stands for (both changes measured together: docs/performance.md).
constexpr size_t kMovedOut = 256;

/// Moves every long byte string of j (depth first, in order) to the end of `tail`.
static void moveBytesOut(json& j, std::string& tail) {
    if (j.is_binary() && j.get_binary().size() >= kMovedOut) {
        const auto& b = j.get_binary();
        tail.append(reinterpret_cast<const char*>(b.data()), b.size());
        j = json{{"bytes", b.size()}};
    } else if (j.is_array()) {
        for (auto& e : j) moveBytesOut(e, tail);
    }
}
/// Puts the moved byte strings back, in the same order, from `tail` (from `at` on).
static void moveBytesIn(json& j, const std::string& tail, size_t& at) {
    if (j.is_object()) {
        const size_t n = j.at("bytes").get<size_t>();
        if (j.size() != 1 || n > tail.size() - at) throw ProtocolError("a byte string of impossible length");
        const auto* b = reinterpret_cast<const std::uint8_t*>(tail.data() + at);
        j = json::binary(std::vector<std::uint8_t>(b, b + n));
        at += n;
    } else if (j.is_array()) {
        for (auto& e : j) moveBytesIn(e, tail, at);
    }
}

static std::string encode(json j) {
    std::string cbor, tail;
    moveBytesOut(j, tail);
    json::to_cbor(j, cbor);
    const uint64_t n = cbor.size();
    return std::string(reinterpret_cast<const char*>(&n), 8) + cbor + tail;
}

static json decode(const std::string& body) {
    uint64_t n = 0;
    if (body.size() < 8 || (std::memcpy(&n, body.data(), 8), n > body.size() - 8)) throw ProtocolError("a message of impossible length");
    json j = json::from_cbor(body.begin() + 8, body.begin() + 8 + static_cast<std::ptrdiff_t>(n), true, false);
    if (j.is_discarded()) throw ProtocolError("a message that is not CBOR");
    size_t at = 8 + n;
    try {
        moveBytesIn(j, body, at);
    } catch (const json::exception& e) {
        throw ProtocolError(std::string("a message of the wrong form: ") + e.what());
    }
    if (at != body.size()) throw ProtocolError("a message longer than its values");
    return j;
}

void Peer::handle(const Message& m) {
    const Handler* h = nullptr;
    long long particles = -1;
    if (m.id >= kFirstCallback && m.id - kFirstCallback < callbacks_.size()) {
        h = &callbacks_[m.id - kFirstCallback].handler;
        particles = callbacks_[m.id - kFirstCallback].particles;
    } else if (const auto it = functions_.find(m.id); it != functions_.end()) {
        h = &it->second;
    }
    if (!h) throw ProtocolError("a call of an unknown function or callback");
    const json arguments = decode(m.body);
    std::string error, results;
    try {
        ContextScope scope(this, particles);
        results = encode((*h)(arguments));  // may register callbacks: the deque keeps *h where it is
    } catch (const PeerFailure&) {
        throw;
    } catch (const ProtocolError&) {
        throw;
    } catch (const NotImplemented& e) {
        const std::string what = e.what(), prefix = "not implemented: ";
        error = thrown(Thrown::NotImplemented, what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what);
    } catch (const std::exception& e) {  // the most derived of the types that keep their type
        const Thrown kind = dynamic_cast<const CallbackFailed*>(&e) ? Thrown::Callback
                          : dynamic_cast<const std::invalid_argument*>(&e) ? Thrown::InvalidArgument
                          : dynamic_cast<const std::out_of_range*>(&e) ? Thrown::OutOfRange
                          : dynamic_cast<const std::domain_error*>(&e) ? Thrown::DomainError
                          : dynamic_cast<const std::logic_error*>(&e) ? Thrown::LogicError : Thrown::Other;
        error = thrown(kind, e.what());
    } catch (...) {
        error = thrown(Thrown::Other, "an exception that is not a std::exception");
    }
    if (error.empty()) send(Kind::Return, m.id, results);
    else send(Kind::Throw, m.id, error);
}

void Peer::rethrow(const std::string& body, const char* name) {
    if (body.empty()) throw ProtocolError("an empty exception");
    const auto kind = static_cast<Thrown>(body[0]);
    const std::string text = body.substr(1);
    switch (kind) {
        case Thrown::NotImplemented: throw NotImplemented(text);
        case Thrown::InvalidArgument: throw std::invalid_argument(text);
        case Thrown::OutOfRange: throw std::out_of_range(text);
        case Thrown::DomainError: throw std::domain_error(text);
        case Thrown::LogicError: throw std::logic_error(text);
        case Thrown::Callback: throw CallbackFailed(text);
        default: throw std::runtime_error(pid_ > 0 ? std::string(name) + " threw: " + text : text);
    }
}

json Peer::roundTrip(uint32_t id, const json& args, const char* name) {
    if (!connected()) throw PeerFailure(std::string(name) + ": no process to call");
    try {
        send(Kind::Invoke, id, encode(args));
        for (Message m; receive(m);) {
            if (m.kind == Kind::Return) return decode(m.body);
            if (m.kind == Kind::Throw) rethrow(m.body, name);
            handle(m);
        }
    } catch (const ProtocolError& e) {
        if (pid_ <= 0) throw;
        disconnect();
        throw PeerFailure(std::string("your code's process broke the protocol in ") + name + ": " + e.what());
    } catch (const PeerFailure&) {
        if (pid_ <= 0) throw;
        // fall through: the process is gone
    }
    if (pid_ <= 0) throw PeerFailure("the connection ended");
    const std::string how = disconnect(true);
    throw PeerFailure(std::string("your code crashed in ") + name + (how.empty() ? "" : " (" + how + ")"));
}

void Peer::serveUntilClosed() {
    for (Message m; receive(m);) {
        if (m.kind != Kind::Invoke) throw ProtocolError("a reply without a call");
        handle(m);
    }
}

std::string Peer::disconnect(bool ended) {
    if (in_ >= 0) ::close(in_);
    if (out_ >= 0) ::close(out_);
    in_ = out_ = -1;  // callbacks stay: the calls that registered them release them as they unwind
    buffered_.clear();
    used_ = 0;
    std::string how;
    if (pid_ > 0) {
        // A process that closed its pipes is ending: give it a moment to be reaped with its status.
        int status = 0;
        pid_t done = 0;
        for (int i = 0; i < (ended ? 200 : 0) && (done = ::waitpid(pid_, &status, WNOHANG)) == 0; ++i) ::usleep(5000);
        if (done == 0) {  // still running: it broke the protocol, or closed its pipes and went on
            ::kill(pid_, SIGKILL);
            ::waitpid(pid_, &status, 0);
        } else if (WIFSIGNALED(status)) {
            const int sig = WTERMSIG(status);
            how = "signal " + std::to_string(sig) + ", " + ::strsignal(sig);
            if (onSignal) onSignal(sig);
        } else if (WIFEXITED(status)) {
            how = "it called exit(" + std::to_string(WEXITSTATUS(status)) + ")";
        }
    }
    pid_ = -1;
    return how;
}

}  // namespace clothlab::wire
