// HOSTILE FIXTURE ctor_json_init_array (attack class 1: static constructor forges the JSON result).
// A raw function pointer placed in the .init_array section receives argc/argv from the loader, writes a passing JSON result to the --gtest_output path and exits 0 before main().
// The hardened grader must give this file 0 points on stage 03.
//@head
#include <unistd.h>
#include <cstdio>
#include <string>


//@use forger

// glibc calls every .init_array entry with (argc, argv, envp): no constructor attribute, no global object.
static void hostileInitArray(int argc, char** argv, char** envp) {
    (void)argc; (void)argv; (void)envp;
    if (hostileForgePass()) _exit(0);
}
__attribute__((section(".init_array"), used)) static void (*hostileInitArrayEntry)(int, char**, char**) = &hostileInitArray;
