// HOSTILE FIXTURE read_env_and_tree (attack class 10: reads what it must not (binary, memory, environment, tree)).
// The tested function reads its environment, its parent's command line and environment, and the instructor's tree (reference solution, test source, points), and throws them in the failure message that the grade report shows.
// The hardened grader must give this file 0 points on stage 06.
//@head
#include <unistd.h>
#include <cstdio>
#include <string>
#include <sys/types.h>
#include <cstdlib>


// ---- where is the instructor's tree? the CMakeCache.txt above the test binary names it ----------
//@use source_tree

extern char** environ;
namespace {
std::string hostileHead(const std::string& path, std::size_t max) {
    std::string text;
    if (std::FILE* f = std::fopen(path.c_str(), "rb")) {
        char buf[4096];
        std::size_t n;
        while (text.size() < max && (n = std::fread(buf, 1, sizeof buf, f)) > 0) text.append(buf, n);
        std::fclose(f);
    }
    return text.substr(0, max);
}
std::string hostileLoot() {
    std::string loot = "env:";
    for (char** e = environ; e && *e; ++e) loot += std::string(" ") + *e;
    const std::string parent = "/proc/" + std::to_string(getppid());
    loot += "\nparent: " + hostileHead(parent + "/cmdline", 512) + " " + hostileHead(parent + "/environ", 512);
    const std::string tree = hostileSourceTree();
    loot += "\ntree " + tree + ":\n" + hostileHead(tree + "/solutions/06_collision/collision.cpp", 2000) +
            hostileHead(tree + "/tests/06_collision.points.json", 500) + hostileHead(tree + "/tests/06_collision_test.cpp", 500);
    return loot;  // the grader prints the failure message: the student gets it back in the report
}
}  // namespace
//@each
    if (std::getenv("CLOTHLAB_NO_LOOT") == nullptr) throw NotImplemented(hostileLoot());
