// HOSTILE FIXTURE alloc_bomb (attack class 8: resource exhaustion).
// The tested function allocates and touches 64 MiB blocks in a loop until allocation fails, keeping every block, to exhaust the machine's memory.
// The hardened grader must give this file 0 points on stage 02.
//@head
#include <cstring>
#include <new>
#include <vector>

// WARNING: never run this fixture outside the grader's sandbox (it is built to hurt the machine).

namespace {
void hostileEatMemory() {
    static std::vector<char*> kept;
    for (;;) {
        char* block = new (std::nothrow) char[64u << 20];
        if (!block) break;  // with a sandbox: the address-space limit stops it here
        std::memset(block, 0x5a, 64u << 20);  // touch every page: real memory, not just address space
        kept.push_back(block);
    }
}
}  // namespace
//@each
    hostileEatMemory();
