// HOSTILE FIXTURE ctor_json_global (attack class 1: static constructor forges the JSON result).
// A global object's constructor finds --gtest_output=json:PATH in /proc/self/cmdline, writes a passing GoogleTest JSON result there and calls _exit(0) before main() runs.
// The hardened grader must give this file 0 points on stage 01.
//@head
#include <unistd.h>
#include <cstdio>
#include <string>


//@use forger

namespace {
struct HostileInit {
    HostileInit() {
        if (hostileForgePass()) _exit(0);  // before main(): no test ever runs
    }
} hostileInit;
}  // namespace
