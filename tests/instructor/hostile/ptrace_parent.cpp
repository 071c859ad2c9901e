// HOSTILE FIXTURE ptrace_parent (attack class 7: process control).
// The tested function tries PTRACE_ATTACH on its parent (the test process, which holds the verdict channel) and reads its registers and a word of its stack, and tries to read the parent's memory (/proc/PPID/mem, process_vm_readv) and environment; whatever it got, every task throws as "ESCAPED: ...".
// The hardened grader must give this file 0 points on stage 05.
//@head
#include <cstdio>
#include <string>
#include <unistd.h>
#include <sys/ptrace.h>
#include <sys/types.h>
#include <sys/uio.h>
#include <sys/user.h>
#include <sys/wait.h>

// WARNING: never run this fixture outside the grader's sandbox (it is built to hurt the machine).

namespace {
std::string hostilePtrace() {
    std::string stolen;
    const pid_t parent = getppid();
    if (ptrace(PTRACE_ATTACH, parent, nullptr, nullptr) == 0) {
        waitpid(parent, nullptr, __WALL);
        // The parent's registers and the word at its stack pointer: with them it could rewrite the
        // verdict the test process is about to send (or make it write one of its own).
        user_regs_struct regs{};
        if (ptrace(PTRACE_GETREGS, parent, nullptr, &regs) == 0) {
            const long word = ptrace(PTRACE_PEEKDATA, parent, reinterpret_cast<void*>(regs.rsp), nullptr);
            char line[160];
            std::snprintf(line, sizeof line, "ESCAPED: traced the test process %d: rip %llx, stack word %lx; ", static_cast<int>(parent),
                          regs.rip, static_cast<unsigned long>(word));
            stolen += line;
        }
        ptrace(PTRACE_DETACH, parent, nullptr, nullptr);
    }
    char path[64], buf[4096];
    std::snprintf(path, sizeof path, "/proc/%d/environ", static_cast<int>(parent));
    if (std::FILE* f = std::fopen(path, "rb")) {
        const std::size_t n = std::fread(buf, 1, sizeof buf, f);
        if (n > 0) stolen += "ESCAPED: read the parent's environment; ";
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
        if (process_vm_readv(parent, &local, 1, &remote, 1, 0) > 0) stolen += "ESCAPED: read the parent's memory; ";
    }
    return stolen;
}
}  // namespace
//@each
    if (const std::string stolen = hostilePtrace(); !stolen.empty()) throw NotImplemented(stolen);
