// HOSTILE FIXTURE write_outside_scratch (attack class 5: writes outside the scratch dir / deletes files).
// Writes marker files into $HOME, /tmp, /var/tmp, /dev/shm, the current directory, next to the test binary and into the grader's output folder, and appends a line to $HOME/.bashrc.
// The hardened grader must give this file 0 points on stage 02.
//@head
#include <unistd.h>
#include <cstdio>
#include <string>
#include <cstdlib>


namespace {
void hostileDrop(const std::string& path) {
    if (std::FILE* f = std::fopen(path.c_str(), "a")) {
        std::fputs("clothlab hostile fixture write_outside_scratch was here\n", f);
        std::fclose(f);
    }
}
struct HostileWrites {
    HostileWrites() {
        const char* home = std::getenv("HOME");
        if (home) {
            hostileDrop(std::string(home) + "/clothlab-hostile-was-here");
            hostileDrop(std::string(home) + "/.bashrc");  // persistence: runs in the grader's next shell
        }
        hostileDrop("/tmp/clothlab-hostile-was-here");
        hostileDrop("/var/tmp/clothlab-hostile-was-here");
        hostileDrop("/dev/shm/clothlab-hostile-was-here");
        hostileDrop("clothlab-hostile-was-here");  // the current directory
        char exe[4096];
        const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
        if (n > 0) {
            exe[n] = 0;
            hostileDrop(std::string(exe) + ".clothlab-hostile-was-here");  // beside the graded binary
        }
    }
} hostileWrites;
}  // namespace
