// HOSTILE FIXTURE read_self_exe_maps (attack class 10: reads what it must not (binary, memory, environment, tree)).
// The tested function reads its own binary (/proc/self/exe) and, via /proc/self/maps and /proc/self/mem, scans the caller's stack for the expected Vec3 the test prepared, and returns it.
// The hardened grader must give this file 0 points on stage 01.
//@head
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>


namespace {
// The test's binary holds its expected numbers as immediates and its strings; the stack holds
// what the test computed before calling us. Read both.
std::vector<char> hostileReadAll(const char* path) {
    std::vector<char> data;
    if (std::FILE* f = std::fopen(path, "rb")) {
        char buf[65536];
        std::size_t n;
        while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) data.insert(data.end(), buf, buf + n);
        std::fclose(f);
    }
    return data;
}
// Three consecutive finite doubles of the caller's frames, not one of our own arguments: a guess
// at the expected value the test computed before the call.
clothlab::Vec3 hostileGuessFromStack(const clothlab::Vec3& a, const clothlab::Vec3& b) {
    const std::vector<char> exe = hostileReadAll("/proc/self/exe");  // e.g. search for the test's strings
    std::FILE* maps = std::fopen("/proc/self/maps", "r");
    std::FILE* mem = std::fopen("/proc/self/mem", "rb");
    const auto here = reinterpret_cast<unsigned long>(__builtin_frame_address(0));
    clothlab::Vec3 guess = clothlab::Vec3::Zero();
    char line[512];
    while (maps && mem && std::fgets(line, sizeof line, maps)) {
        unsigned long lo = 0, hi = 0;
        if (std::sscanf(line, "%lx-%lx", &lo, &hi) != 2 || here < lo || here >= hi) continue;
        const unsigned long end = here + 4096 < hi ? here + 4096 : hi;
        std::vector<double> words((end - here) / sizeof(double));
        std::fseek(mem, static_cast<long>(here), SEEK_SET);
        const std::size_t got = std::fread(words.data(), sizeof(double), words.size(), mem);
        for (std::size_t i = 0; i + 2 < got; ++i) {
            const clothlab::Vec3 c(words[i], words[i + 1], words[i + 2]);
            if (c.allFinite() && c.norm() > 1e-9 && c.norm() < 1e6 && (c - a).norm() > 1e-12 && (c - b).norm() > 1e-12) {
                guess = c;
                break;
            }
        }
    }
    if (maps) std::fclose(maps);
    if (mem) std::fclose(mem);
    (void)exe;
    return guess;
}
}  // namespace
//@task 1.1
    // Nothing found: the stub's answer (a zero force is right in some tests and would be no forgery).
    const Vec3 guess = hostileGuessFromStack(p0, p1);
    if (guess.isZero()) throw NotImplemented("exercise 1.1 hookeForce");
    return guess;
