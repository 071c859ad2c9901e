// HOSTILE FIXTURE fork_bomb (attack class 7: process control).
// The tested function forks in an endless loop (every child forks too) to exhaust the process table; each child arms alarm(120) so an unsandboxed accident ends by itself.
// The hardened grader must give this file 0 points on stage 01.
//@head
#include <unistd.h>

// WARNING: never run this fixture outside the grader's sandbox (it is built to hurt the machine).
//@each
    for (;;) {
        if (fork() == 0) alarm(120);  // the child forks on as well; alarm: dies after 2 min without a sandbox
    }
