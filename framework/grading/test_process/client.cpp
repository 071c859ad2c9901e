// The test process's side of the submission process: started on the first call of a submission's
// function (submission_process/serve_main.cpp), with the calls on its fd 3 and its replies on fd 4.
#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include "wire/peer.h"

namespace clothlab::wire {

/// The submission process's program and what to do when a signal ends it: graded_main.cpp.
extern const char* serverPath;
void reportSignal(int signal);

Peer& submissionProcess() {
    static Peer peer;
    if (peer.connected()) return peer;
    if (!serverPath) throw std::runtime_error("this test binary runs the submission's code in a process of its own; run it through clothlab-grade");
    ::signal(SIGPIPE, SIG_IGN);  // a crashed submission process is an error reply, not our death
    int calls[2], replies[2];
    if (::pipe2(calls, O_CLOEXEC) != 0) throw PeerFailure("cannot start the submission process (pipe)");
    if (::pipe2(replies, O_CLOEXEC) != 0) {
        ::close(calls[0]), ::close(calls[1]);
        throw PeerFailure("cannot start the submission process (pipe)");
    }
    const pid_t pid = ::fork();
    if (pid < 0) throw PeerFailure("cannot start the submission process (fork)");
    if (pid == 0) {  // only the two pipe ends cross into the new program (everything else is close-on-exec or closed)
        const int in = ::fcntl(calls[0], F_DUPFD, 10), out = ::fcntl(replies[1], F_DUPFD, 10);
        if (in < 0 || out < 0 || ::dup2(in, 3) != 3 || ::dup2(out, 4) != 4) ::_exit(126);
        ::close_range(5, ~0u, 0);
        char* const argv[] = {const_cast<char*>("clothlab-submission"), nullptr};
        char* const envp[] = {nullptr};
        ::execve(serverPath, argv, envp);
        ::_exit(127);
    }
    ::close(calls[0]), ::close(replies[1]);
    peer.attach(replies[0], calls[1], pid);
    peer.onSignal = &reportSignal;
    return peer;
}

}  // namespace clothlab::wire
