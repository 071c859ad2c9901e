// The instructor's tree as a naive grader's build would reveal it (//@use source_tree): the
// CMAKE_HOME_DIRECTORY of the CMakeCache.txt above this program, or above the grading kit that a
// grader process names on its command line (--kit PATH, in /proc when the program shares the
// grader's PID namespace: container mode). Not an attack by itself.
#include <dirent.h>
#include <unistd.h>
#include <cstdio>
#include <string>

namespace {
std::string hostileTreeAbove(std::string dir) {
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
std::string hostileSourceTree() {
    char exe[4096];
    const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n > 0) {
        exe[n] = 0;
        const std::string tree = hostileTreeAbove(exe);
        if (!tree.empty()) return tree;
    }
    DIR* proc = opendir("/proc");
    for (dirent* e; proc && (e = readdir(proc));) {
        if (e->d_name[0] < '1' || e->d_name[0] > '9') continue;
        std::string cmdline;
        if (std::FILE* f = std::fopen(("/proc/" + std::string(e->d_name) + "/cmdline").c_str(), "rb")) {
            char buf[4096];
            std::size_t got;
            while ((got = std::fread(buf, 1, sizeof buf, f)) > 0 && cmdline.size() < (1u << 16)) cmdline.append(buf, got);
            std::fclose(f);
        }
        const std::size_t kit = cmdline.find(std::string("--kit") + '\0');
        if (kit == std::string::npos) continue;
        const std::string tree = hostileTreeAbove(cmdline.c_str() + kit + 6);  // build/grade-kit/kit.json
        if (!tree.empty()) {
            closedir(proc);
            return tree;
        }
    }
    if (proc) closedir(proc);
    return "";
}
}  // namespace
