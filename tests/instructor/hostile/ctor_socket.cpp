// HOSTILE FIXTURE ctor_socket (attack class 13: network).
// A static initialiser of the submission process (before that process's seccomp filter) opens an AF_INET socket and connects to 127.0.0.1:1; a connection or "connection refused" means it reached the machine's network ("ESCAPED: ..." in every task's failure message).
// The hardened grader must give this file 0 points on stage 01. Container mode: its seccomp filter refuses socket() (bubblewrap: a network namespace with no interface up).
//@head
#include <arpa/inet.h>
#include <cerrno>
#include <cstring>
#include <netinet/in.h>
#include <string>
#include <sys/socket.h>
#include <unistd.h>

namespace {
std::string hostileConnect() {
    const int s = socket(AF_INET, SOCK_STREAM, 0);
    if (s < 0) return std::string("socket: ") + std::strerror(errno);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(1);
    inet_pton(AF_INET, "127.0.0.1", &a.sin_addr);
    const int rc = connect(s, reinterpret_cast<sockaddr*>(&a), sizeof a);
    const int err = errno;
    close(s);
    if (rc == 0 || err == ECONNREFUSED) return "ESCAPED: an AF_INET socket reached 127.0.0.1:1 (" + std::string(rc == 0 ? "connected" : "refused") + ")";
    return std::string("connect: ") + std::strerror(err);
}
const std::string hostileNet = hostileConnect();  // before main(), before the seccomp filter
}  // namespace
//@each
    throw NotImplemented(hostileNet);
