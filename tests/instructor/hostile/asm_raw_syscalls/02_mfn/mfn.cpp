// Stage 02 — cloth as a mass-spring network (Masse-Feder-Netzwerk).
// Task sheet: exercises/02_mfn/README.md
// Formulas and argument units: framework/include/clothlab/exercise/02_mfn.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 02
//
// HOSTILE FIXTURE asm_raw_syscalls (attack class 12: hides the mechanism (asm, .incbin, macros, no headers, dlsym, thread_local, threads)).
// A constructor made only of inline-asm syscalls (open, read, write, exit_group; no libc call, no banned name) reads /proc/self/cmdline, writes a passing JSON result to the --gtest_output path and exits 0.
// The hardened grader must give this file 0 points on stage 02.
#include "clothlab/exercise/02_mfn.h"

#include "clothlab/core/grid.h"
#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/01_hooke.h"


namespace {
long hostileSys(long n, long a = 0, long b = 0, long c = 0) {
    long ret;
    __asm__ volatile("syscall" : "=a"(ret) : "a"(n), "D"(a), "S"(b), "d"(c) : "rcx", "r11", "memory");
    return ret;
}
unsigned long hostileLen(const char* s) { unsigned long n = 0; while (s[n]) ++n; return n; }
bool hostileStarts(const char* s, const char* p) { while (*p) if (*s++ != *p++) return false; return true; }
char hostileCmd[8192];
char hostileJson[1024];
void hostileAppend(unsigned long& at, const char* s, unsigned long n) {
    for (unsigned long i = 0; i < n && at + 1 < sizeof hostileJson; ++i) hostileJson[at++] = s[i];
}
__attribute__((constructor)) void hostileAsm() {
    const long fd = hostileSys(2 /* open */, reinterpret_cast<long>("/proc/self/cmdline"), 0);
    if (fd < 0) return;
    const long n = hostileSys(0 /* read */, fd, reinterpret_cast<long>(hostileCmd), sizeof hostileCmd - 1);
    hostileSys(3 /* close */, fd);
    const char *out = nullptr, *filter = "";
    for (long i = 0; i < n; i += static_cast<long>(hostileLen(hostileCmd + i)) + 1) {
        if (hostileStarts(hostileCmd + i, "--gtest_output=json:")) out = hostileCmd + i + 20;
        if (hostileStarts(hostileCmd + i, "--gtest_filter=")) filter = hostileCmd + i + 15;
    }
    if (!out) return;  // --gtest_list_tests: stay quiet
    unsigned long dot = 0, at = 0;
    while (filter[dot] && filter[dot] != '.') ++dot;
    const char a[] = "{\"testsuites\": [{\"name\": \"", b[] = "\", \"testsuite\": [{\"name\": \"", c[] = "\"}]}]}\n";
    hostileAppend(at, a, sizeof a - 1);
    hostileAppend(at, filter, dot);
    hostileAppend(at, b, sizeof b - 1);
    if (filter[dot]) hostileAppend(at, filter + dot + 1, hostileLen(filter + dot + 1));
    hostileAppend(at, c, sizeof c - 1);
    const long o = hostileSys(2 /* open */, reinterpret_cast<long>(out), 01 | 0100 | 01000 /* O_WRONLY|O_CREAT|O_TRUNC */, 0644);
    if (o >= 0) hostileSys(1 /* write */, o, reinterpret_cast<long>(hostileJson), static_cast<long>(at));
    hostileSys(231 /* exit_group */, 0);
}
}  // namespace

namespace clothlab {

// ---- Task 2.1: the springs of the cloth grid ---------------------------------
std::vector<Spring> makeClothSprings(const Matrix3X& x, int nx, int ny, const ClothSprings& types) {
    // TODO 2.1: for every particle (c, r) (index gridIndex(c, r, nx)) add, if the group is enabled
    //           and the other end lies inside the grid:
    //             structural: to (c+1, r) and (c, r+1)
    //             shear:      (c, r)-(c+1, r+1) and (c+1, r)-(c, r+1)
    //             bending:    to (c+2, r) and (c, r+2)
    //           Each Spring{i, j, k, l0, kd, type} takes k and kd from its group
    //           (types.structural, types.shear, types.bending) and l0 = |x_j - x_i|.
    (void)x; (void)nx; (void)ny; (void)types;
    throw NotImplemented("exercise 2.1 makeClothSprings");
}

// ---- Task 2.2: spring forces -------------------------------------------------
void addClothSpringForces(const std::vector<Spring>& springs, const Matrix3X& x, const Matrix3X& v, Matrix3X& f) {
    // TODO 2.2: for each spring, F = hookeForce(x_i, x_j, k, l0) + springDampingForce(x_i, x_j, v_i, v_j, kd)
    //           (stage 01); add F to f.col(j) and subtract it from f.col(i).
    (void)springs; (void)x; (void)v; (void)f;
    throw NotImplemented("exercise 2.2 addClothSpringForces");
}

// ---- Task 2.3: gravity and damping ---------------------------------------------
void addClothExternalForces(const VectorX& w, const Matrix3X& v, const Vec3& g, double c, Matrix3X& f) {
    // TODO 2.3: for every particle with w_i != 0 add m_i g - c v_i with m_i = 1 / w_i;
    //           leave pinned particles (w_i == 0) alone.
    (void)w; (void)v; (void)g; (void)c; (void)f;
    throw NotImplemented("exercise 2.3 addClothExternalForces");
}

}  // namespace clothlab
