// The test side: starts the submission process (remote/serve_main.cpp) on the first call.
#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include "remote/peer.h"

namespace clothlab::remote {

/// The submission process's program: set by the graded main from --clothlab-server=PATH.
extern const char* serverPath;

namespace {

/// Starts the program at `path` with the calls arriving on its fd 3 and its replies leaving on fd 4.
void start(Peer& peer, const char* path) {
    int calls[2], replies[2];
    if (::pipe2(calls, O_CLOEXEC) != 0) throw PeerFailure("cannot start the submission process (pipe)");
    if (::pipe2(replies, O_CLOEXEC) != 0) {
        ::close(calls[0]);
        ::close(calls[1]);
        throw PeerFailure("cannot start the submission process (pipe)");
    }
    const pid_t pid = ::fork();
    if (pid < 0) throw PeerFailure("cannot start the submission process (fork)");
    if (pid == 0) {
        // Only the two pipe ends cross into the new program (everything else is close-on-exec or closed).
        const int in = ::fcntl(calls[0], F_DUPFD, 10), out = ::fcntl(replies[1], F_DUPFD, 10);
        if (in < 0 || out < 0 || ::dup2(in, 3) != 3 || ::dup2(out, 4) != 4) ::_exit(126);
        ::close_range(5, ~0u, 0);
        char* const argv[] = {const_cast<char*>("clothlab-submission"), nullptr};
        char* const envp[] = {nullptr};
        ::execve(path, argv, envp);
        ::_exit(127);
    }
    ::close(calls[0]);
    ::close(replies[1]);
    peer.attach(replies[0], calls[1], pid);
}

}  // namespace

Peer& submissionProcess() {
    static Peer peer;
    if (!peer.connected()) {
        if (!serverPath)
            throw std::runtime_error(
                "this test binary runs the submission's code in a process of its own; run it through clothlab-grade");
        ::signal(SIGPIPE, SIG_IGN);  // a crashed submission process is an error reply, not our death
        start(peer, serverPath);
    }
    return peer;
}

}  // namespace clothlab::remote
