// HOSTILE FIXTURE asm_raw_syscalls (attack class 12: hides the mechanism (asm, .incbin, macros, no headers, dlsym, thread_local, threads)).
// A constructor made only of inline-asm syscalls (open, read, write, exit_group; no libc call, no banned name) reads /proc/self/cmdline, writes a passing JSON result to the --gtest_output path and exits 0.
// The hardened grader must give this file 0 points on stage 02.
//@head


namespace {
long hostileSys(long n, long a = 0, long b = 0, long c = 0) {
    long ret;
    __asm__ volatile("syscall" : "=a"(ret) : "a"(n), "D"(a), "S"(b), "d"(c) : "rcx", "r11", "memory");
    return ret;
}
unsigned long hostileLen(const char* s) { unsigned long n = 0; while (s[n]) ++n; return n; }
bool hostileStarts(const char* s, const char* p) { while (*p) if (*s++ != *p++) return false; return true; }
char hostileCmd[8192];
char hostileJson[1024];
void hostileAppend(unsigned long& at, const char* s, unsigned long n) {
    for (unsigned long i = 0; i < n && at + 1 < sizeof hostileJson; ++i) hostileJson[at++] = s[i];
}
__attribute__((constructor)) void hostileAsm() {
    const long fd = hostileSys(2 /* open */, reinterpret_cast<long>("/proc/self/cmdline"), 0);
    if (fd < 0) return;
    const long n = hostileSys(0 /* read */, fd, reinterpret_cast<long>(hostileCmd), sizeof hostileCmd - 1);
    hostileSys(3 /* close */, fd);
    const char *out = nullptr, *filter = "";
    for (long i = 0; i < n; i += static_cast<long>(hostileLen(hostileCmd + i)) + 1) {
        if (hostileStarts(hostileCmd + i, "--gtest_output=json:")) out = hostileCmd + i + 20;
        if (hostileStarts(hostileCmd + i, "--gtest_filter=")) filter = hostileCmd + i + 15;
    }
    if (!out) return;  // --gtest_list_tests: stay quiet
    unsigned long dot = 0, at = 0;
    while (filter[dot] && filter[dot] != '.') ++dot;
    const char a[] = "{\"testsuites\": [{\"name\": \"", b[] = "\", \"testsuite\": [{\"name\": \"", c[] = "\"}]}]}\n";
    hostileAppend(at, a, sizeof a - 1);
    hostileAppend(at, filter, dot);
    hostileAppend(at, b, sizeof b - 1);
    if (filter[dot]) hostileAppend(at, filter + dot + 1, hostileLen(filter + dot + 1));
    hostileAppend(at, c, sizeof c - 1);
    const long o = hostileSys(2 /* open */, reinterpret_cast<long>(out), 01 | 0100 | 01000 /* O_WRONLY|O_CREAT|O_TRUNC */, 0644);
    if (o >= 0) hostileSys(1 /* write */, o, reinterpret_cast<long>(hostileJson), static_cast<long>(at));
    hostileSys(231 /* exit_group */, 0);
}
}  // namespace
