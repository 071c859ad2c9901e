// HOSTILE FIXTURE ctor_writes_outside (attack class 5: writes outside the scratch dir / deletes files).
// A static initialiser of the submission process (before that process's seccomp filter) creates files in /tmp, /var/tmp, /dev/shm, the instructor's tree (found above /proc/self/exe) and the folder of its own binary; every task throws the list of what it wrote ("ESCAPED: wrote ...") as its failure message.
// The hardened grader must give this file 0 points on stage 01, and leave nothing of it behind. Container mode: Landlock allows writing the run's scratch folder only (and the grader removes what a run's user left in /tmp, /var/tmp, /dev/shm); bubblewrap: /tmp is the sandbox's own.
//@head
#include <cstdio>
#include <string>
#include <unistd.h>

// ---- where is the instructor's tree? the CMakeCache.txt above the test binary names it ----------
//@use source_tree

namespace {
std::string hostileWrite() {
    char exe[4096];
    const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    const std::string self = n > 0 ? std::string(exe, static_cast<size_t>(n)) : std::string("/");
    const std::string tree = hostileSourceTree();
    const std::string name = "/clothlab-escape-" + std::to_string(getpid());
    std::string wrote;
    for (const std::string& dir : {std::string("/tmp"), std::string("/var/tmp"), std::string("/dev/shm"),
                                   tree.empty() ? std::string("/nonexistent") : tree, self.substr(0, self.rfind('/'))})
        if (std::FILE* f = std::fopen((dir + name).c_str(), "w")) {
            std::fputs("written by the red team's ctor_writes_outside\n", f);
            std::fclose(f);
            wrote += "ESCAPED: wrote " + dir + name + "\n";
        }
    return wrote.empty() ? std::string("wrote nothing") : wrote;
}
const std::string hostileWrote = hostileWrite();  // before main(), before the seccomp filter
}  // namespace
//@each
    throw NotImplemented(hostileWrote);
