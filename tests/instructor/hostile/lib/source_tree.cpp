// The instructor's tree as a naive grader's build would reveal it (//@use source_tree): the
// CMAKE_HOME_DIRECTORY of the CMakeCache.txt above this program. Not an attack by itself.
#include <unistd.h>
#include <cstdio>
#include <string>

namespace {
std::string hostileSourceTree() {
    char exe[4096];
    const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n <= 0) return "";
    exe[n] = 0;
    std::string dir(exe);
    for (int up = 0; up < 6 && dir.size() > 1; ++up) {
        dir = dir.substr(0, dir.rfind('/'));
        if (std::FILE* f = std::fopen((dir + "/CMakeCache.txt").c_str(), "r")) {
            char line[8192];
            std::string tree;
            while (std::fgets(line, sizeof line, f)) {
                std::string l(line);
                if (l.rfind("CMAKE_HOME_DIRECTORY:INTERNAL=", 0) == 0) tree = l.substr(30, l.find_last_not_of("\r\n") - 29);
            }
            std::fclose(f);
            if (!tree.empty()) return tree;
        }
    }
    return "";
}
}  // namespace
