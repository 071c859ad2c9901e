// HOSTILE FIXTURE atexit_json (attack class 2: exit-time hook forges the JSON result).
// A static constructor registers an atexit handler that, after GoogleTest has written the real (failing) JSON, overwrites it with a passing one and turns the exit status into 0 with _exit(0).
// The hardened grader must give this file 0 points on stage 01.
//@head
#include <unistd.h>
#include <cstdio>
#include <string>
#include <cstdlib>


//@use forger

namespace {
void hostileAtExit() {
    if (hostileForgePass()) _exit(0);  // main() returned 1 (failures); the process now exits 0
}
struct HostileRegister {
    HostileRegister() { std::atexit(&hostileAtExit); }
} hostileRegister;
}  // namespace
