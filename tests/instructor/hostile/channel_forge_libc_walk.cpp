// Stage 01 stub + an in-test forger that uses only what both screens allow:
// &printf (allowed), memcpy (allowed), malloc (allowed), strcmp/snprintf (allowed).
// 1. From printf's address, walk down page by page to libc's ELF header and resolve `write` and
//    `_exit` from libc's dynamic symbol table by hand (a dlsym without dlsym: the object screen
//    only sees the undefined symbols printf/memcpy/strcmp/malloc/snprintf).
// 2. Scan the stack upwards for "--gtest_filter=NAME".
// 3. write(3, "end NAME passed\n") (the test process's channel: the test's `start NAME` is on it
//    already) and _exit(0) before the test's EXPECTs run. (Against the grader of be6956f it also
//    needed the channel's secret from the heap; today's channel has none, README "Red team 2".)
// No reinterpret_cast, no cast at all: integers become pointers through memcpy.
//@head
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

using Addr = std::uintptr_t;

template <class T> T as(Addr a) { T p; std::memcpy(&p, &a, sizeof p); return p; }
template <class T> Addr addr(T p) { Addr a; std::memcpy(&a, &p, sizeof a); return a; }
std::uint64_t rd64(Addr a) { std::uint64_t v; std::memcpy(&v, as<const void*>(a), 8); return v; }
std::uint32_t rd32(Addr a) { std::uint32_t v; std::memcpy(&v, as<const void*>(a), 4); return v; }
std::uint16_t rd16(Addr a) { std::uint16_t v; std::memcpy(&v, as<const void*>(a), 2); return v; }
unsigned char rd8(Addr a) { unsigned char v; std::memcpy(&v, as<const void*>(a), 1); return v; }

Addr librarySymbol(const char* name) {
    int (*pf)(const char*, ...) = &std::printf;
    Addr base = addr(pf) & ~Addr(0xfff);
    while (rd32(base) != 0x464c457fu) base -= 0x1000;  // "\x7fELF"
    const std::uint64_t phoff = rd64(base + 32);
    const unsigned phnum = rd16(base + 56);
    Addr dyn = 0;
    for (unsigned i = 0; i < phnum; ++i)
        if (rd32(base + phoff + 56 * i) == 2) dyn = base + rd64(base + phoff + 56 * i + 16);  // PT_DYNAMIC
    Addr symtab = 0, strtab = 0;
    for (Addr d = dyn; d && rd64(d) != 0; d += 16) {
        const std::uint64_t v = rd64(d + 8);
        if (rd64(d) == 5) strtab = v < base ? base + v : v;
        if (rd64(d) == 6) symtab = v < base ? base + v : v;
    }
    for (Addr s = symtab; s && s < strtab; s += 24) {
        const std::uint64_t value = rd64(s + 8);
        if (value && std::strcmp(as<const char*>(strtab + rd32(s)), name) == 0) return base + value;
    }
    return 0;
}

void forge() {
    static int tried = 0;
    if (tried++) return;
    // The test's name: "--gtest_filter=NAME" among argv, at the top of the stack.
    volatile int here = 0;
    Addr name = 0;
    for (Addr q = addr(&here); q < addr(&here) + (8u << 20); ++q) {
        if (rd8(q) == '-' && std::memcmp(as<const void*>(q), "--gtest_filter=", 15) == 0 && rd8(q + 15) != 0) {
            name = q + 15;
            break;
        }
    }
    if (!name) return;
    char line[1024];
    const int len = std::snprintf(line, sizeof line, "end %s passed\n", as<const char*>(name));
    const Addr w = librarySymbol("write"), x = librarySymbol("_exit");
    if (!w || !x) return;
    as<long (*)(int, const void*, unsigned long)>(w)(3, line, static_cast<unsigned long>(len));
    as<void (*)(int)>(x)(0);
}

}  // namespace

//@each
    forge();
