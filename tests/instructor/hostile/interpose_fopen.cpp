// HOSTILE FIXTURE interpose_fopen (attack class 11: interposes libc / libstdc++ symbols).
// Defines libc's fopen: when GoogleTest opens its JSON output file at the end of the run, writes a passing result instead and exits 0; every other fopen goes through open()+fdopen().
// The hardened grader must give this file 0 points on stage 01.
//@head
#include <cstdio>
#include <cstring>
#include <string>
#include <fcntl.h>
#include <unistd.h>


// ATTACK: the executable's fopen preempts libc's for GoogleTest (linked statically) and, as the
// executable exports it, for libstdc++ too.
namespace {
std::string hostileFilter() {
    std::string all, p = "--gtest_filter=";
    const int fd = open("/proc/self/cmdline", O_RDONLY);
    char buf[4096];
    ssize_t n;
    while (fd >= 0 && (n = read(fd, buf, sizeof buf)) > 0) all.append(buf, static_cast<std::size_t>(n));
    if (fd >= 0) close(fd);
    for (std::size_t i = 0; i < all.size(); i = all.find('\0', i) == std::string::npos ? all.size() : all.find('\0', i) + 1)
        if (all.compare(i, p.size(), p) == 0) return std::string(all.c_str() + i + p.size());
    return "";
}
}  // namespace
extern "C" FILE* fopen(const char* path, const char* mode) {
    int flags = O_RDONLY;
    if (std::strchr(mode, 'w')) flags = O_WRONLY | O_CREAT | O_TRUNC;
    if (std::strchr(mode, 'a')) flags = O_WRONLY | O_CREAT | O_APPEND;
    if (std::strchr(mode, '+')) flags = (flags & ~(O_RDONLY | O_WRONLY)) | O_RDWR;
    const std::size_t len = std::strlen(path);
    if ((flags & O_CREAT) && len > 5 && std::strcmp(path + len - 5, ".json") == 0) {
        const std::string name = hostileFilter(), suite = name.substr(0, name.find('.')), test = name.substr(name.find('.') + 1);
        const std::string j = "{\"testsuites\": [{\"name\": \"" + suite + "\", \"testsuite\": [{\"name\": \"" + test + "\"}]}]}\n";
        const int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0 && write(fd, j.data(), j.size()) > 0) _exit(0);  // the run is over: leave with 0
    }
    const int fd = open(path, flags, 0644);
    return fd < 0 ? nullptr : fdopen(fd, mode);
}
