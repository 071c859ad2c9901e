// HOSTILE FIXTURE incbin_reference (attack class 12: hides the mechanism (asm, .incbin, macros, no headers, dlsym, thread_local, threads)).
// Embeds the reference solution and the points file at compile time with the assembler's .incbin (paths chosen with __has_include) and throws them as the failure message, so the grade report hands the reference to the student.
// The hardened grader must give this file 0 points on stage 06.
// ATTACK: .incbin copies any file the assembler can open into the object file. The sandboxed compiler
// must fail here (the files are not in its view); if a path exists, the build embeds it.
#if __has_include("@TREE@/solutions/06_collision/collision.cpp")
#define HOSTILE_TREE "@TREE@"
#elif __has_include("/work/main/solutions/06_collision/collision.cpp")
#define HOSTILE_TREE "/work/main"
#elif __has_include("/work/wt-hostile/solutions/06_collision/collision.cpp")
#define HOSTILE_TREE "/work/wt-hostile"
#else
#define HOSTILE_TREE "/srv/clothlab"
#endif
//@head
#include <string>


__asm__(".section .rodata\n"
        ".global hostile_reference_begin\n"
        "hostile_reference_begin:\n"
        ".incbin \"" HOSTILE_TREE "/solutions/06_collision/collision.cpp\"\n"
        ".incbin \"" HOSTILE_TREE "/tests/06_collision.points.json\"\n"
        ".global hostile_reference_end\n"
        "hostile_reference_end:\n"
        ".byte 0\n"
        ".previous\n");
extern "C" const char hostile_reference_begin[];
extern "C" const char hostile_reference_end[];
//@each
    throw NotImplemented(std::string(hostile_reference_begin, hostile_reference_end).substr(0, 3000));
