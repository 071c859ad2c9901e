// HOSTILE FIXTURE ctor_json_attribute (attack class 1: static constructor forges the JSON result).
// An __attribute__((constructor)) function writes a passing GoogleTest JSON result to the --gtest_output path and calls _exit(0) before main() runs.
// The hardened grader must give this file 0 points on stage 02.
//@head
#include <unistd.h>
#include <cstdio>
#include <string>


//@use forger

__attribute__((constructor(101))) static void hostileEarly() {
    if (hostileForgePass()) _exit(0);
}
