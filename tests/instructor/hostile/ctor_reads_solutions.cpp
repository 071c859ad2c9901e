// HOSTILE FIXTURE ctor_reads_solutions (attack class 10: reads what it must not (binary, memory, environment, tree)).
// A static initialiser of the submission process (it runs before that process's seccomp filter) finds the instructor's tree above /proc/self/exe and reads the reference solution, the instructor's experiment test and the points file by absolute path; every task throws what it read ("ESCAPED: read ...") as its failure message.
// The hardened grader must give this file 0 points on stage 01. Container mode: Landlock keeps the tree out of reach (bubblewrap: the tree is not in the sandbox).
//@head
#include <cstdio>
#include <string>

// ---- where is the instructor's tree? the CMakeCache.txt above the test binary names it ----------
//@use source_tree

namespace {
std::string hostileRead() {
    const std::string tree = hostileSourceTree();
    std::string loot;
    for (const char* file : {"/solutions/01_hooke/hooke.cpp", "/tests/instructor/experiments/01_hooke.cpp", "/tests/01_hooke.points.json"})
        if (std::FILE* in = std::fopen((tree + file).c_str(), "rb")) {
            char line[256] = "";
            if (!std::fgets(line, sizeof line, in)) line[0] = 0;
            std::fclose(in);
            loot += "ESCAPED: read " + tree + file + ": " + line + "\n";
        }
    return loot.empty() ? "read nothing (tree: " + (tree.empty() ? std::string("not found") : tree) + ")" : loot;
}
const std::string hostileLoot = hostileRead();  // before main(), before the seccomp filter
}  // namespace
//@each
    throw NotImplemented(hostileLoot);
