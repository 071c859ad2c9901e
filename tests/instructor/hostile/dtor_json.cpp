// HOSTILE FIXTURE dtor_json (attack class 2: exit-time hook forges the JSON result).
// A static object's destructor, which runs after main() returned and GoogleTest wrote the real result, overwrites the JSON with a passing one and exits 0.
// The hardened grader must give this file 0 points on stage 05.
//@head
#include <unistd.h>
#include <cstdio>
#include <string>


//@use forger

namespace {
struct HostileAtShutdown {
    ~HostileAtShutdown() {
        if (hostileForgePass()) _exit(0);
    }
} hostileAtShutdown;
}  // namespace
