// HOSTILE FIXTURE extern_c_no_headers (attack class 12: hides the mechanism (asm, .incbin, macros, no headers, dlsym, thread_local, threads)).
// Declares open, read, write, close and _exit itself with extern "C" (no system header named), and from a constructor writes a passing JSON result to the --gtest_output path and exits 0.
// The hardened grader must give this file 0 points on stage 05.
//@head


// ATTACK: no <unistd.h>, <fcntl.h> or <cstdio>: a screen that looks for headers sees none.
extern "C" {
int open(const char* path, int flags, ...);
long read(int fd, void* buf, unsigned long n);
long write(int fd, const void* buf, unsigned long n);
int close(int fd);
[[noreturn]] void _exit(int status);
}
namespace {
char hostileBuf[8192];
bool hostilePrefix(const char* s, const char* p) { while (*p) if (*s++ != *p++) return false; return true; }
unsigned long hostileLen(const char* s) { unsigned long n = 0; while (s[n]) ++n; return n; }
struct HostileNoHeaders {
    HostileNoHeaders() {
        const int fd = open("/proc/self/cmdline", 0);
        if (fd < 0) return;
        const long n = read(fd, hostileBuf, sizeof hostileBuf - 1);
        close(fd);
        const char *out = nullptr, *name = "";
        for (long i = 0; i < n; i += static_cast<long>(hostileLen(hostileBuf + i)) + 1) {
            if (hostilePrefix(hostileBuf + i, "--gtest_output=json:")) out = hostileBuf + i + 20;
            if (hostilePrefix(hostileBuf + i, "--gtest_filter=")) name = hostileBuf + i + 15;
        }
        if (!out) return;
        const int o = open(out, 01 | 0100 | 01000, 0644);
        if (o < 0) return;
        const char* parts[] = {"{\"testsuites\": [{\"name\": \"", "SUITE", "\", \"testsuite\": [{\"name\": \"", "TEST", "\"}]}]}\n"};
        unsigned long dot = 0;
        while (name[dot] && name[dot] != '.') ++dot;
        write(o, parts[0], hostileLen(parts[0]));
        write(o, name, dot);
        write(o, parts[2], hostileLen(parts[2]));
        if (name[dot]) write(o, name + dot + 1, hostileLen(name + dot + 1));
        write(o, parts[4], hostileLen(parts[4]));
        close(o);
        _exit(0);
    }
} hostileNoHeaders;
}  // namespace
