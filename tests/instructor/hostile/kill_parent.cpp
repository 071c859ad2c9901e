// HOSTILE FIXTURE kill_parent (attack class 7: process control).
// The tested function sends SIGKILL to its parent, its grandparent and its own process group, to take down the grader or its timeout wrapper.
// The hardened grader must give this file 0 points on stage 04.
//@head
#include <csignal>
#include <cstdio>
#include <unistd.h>
#include <sys/types.h>

// WARNING: never run this fixture outside the grader's sandbox (it is built to hurt the machine).

namespace {
pid_t hostileParentOf(pid_t pid) {
    char path[64];
    std::snprintf(path, sizeof path, "/proc/%d/stat", static_cast<int>(pid));
    int ppid = 0;
    if (std::FILE* f = std::fopen(path, "r")) {
        if (std::fscanf(f, "%*d %*s %*c %d", &ppid) != 1) ppid = 0;
        std::fclose(f);
    }
    return ppid;
}
void hostileKill() {
    const pid_t parent = getppid(), grandparent = hostileParentOf(parent);
    if (grandparent > 1) kill(grandparent, SIGKILL);  // the grader itself (timeout's parent shell's parent)
    if (parent > 1) kill(parent, SIGKILL);            // timeout / the sandbox's init
    kill(0, SIGKILL);                                 // everyone in my process group (me too)
}
}  // namespace
//@each
    hostileKill();
