// HOSTILE FIXTURE interpose_libc_family (attack class 11: interposes libc / libstdc++ symbols).
// Defines exit, _exit, write, malloc/free/calloc/realloc (over __libc_malloc) and __cxa_atexit: the __cxa_atexit hook slips an exit-time forger in before the first static destructor is registered, malloc runs before any constructor, _exit/exit force status 0, write rewrites '[  FAILED  ]' into '[       OK ]'.
// The hardened grader must give this file 0 points on stage 03.
//@head
#include <unistd.h>
#include <cstdio>
#include <string>
#include <cstring>
#include <dlfcn.h>
#include <sys/syscall.h>


// ---- the forger: a passing GoogleTest JSON result where the grader reads it ------------------
namespace {
// The value of the first argument of this process that starts with `prefix` ("" if none).
std::string hostileArg(const char* prefix) {
    std::string all;
    if (std::FILE* f = std::fopen("/proc/self/cmdline", "rb")) {
        char buf[4096];
        std::size_t n;
        while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) all.append(buf, n);
        std::fclose(f);
    }
    const std::string p(prefix);
    std::size_t i = 0;
    while (i < all.size()) {
        std::size_t end = all.find('\0', i);
        if (end == std::string::npos) end = all.size();
        const std::string a = all.substr(i, end - i);
        if (a.compare(0, p.size(), p) == 0) return a.substr(p.size());
        i = end + 1;
    }
    return "";
}
// Writes {"testsuites":[{"testsuite":[{...}]}]} without "failures" for the test named by
// --gtest_filter. Returns false when the process has no --gtest_output=json: (e.g. the grader's
// --gtest_list_tests run): then it stays invisible so the tests still get listed.
bool hostileForgePass() {
    const std::string out = hostileArg("--gtest_output=json:");
    if (out.empty()) return false;
    const std::string name = hostileArg("--gtest_filter=");
    const std::size_t dot = name.find('.');
    const std::string suite = name.substr(0, dot), test = dot == std::string::npos ? name : name.substr(dot + 1);
    std::FILE* f = std::fopen(out.c_str(), "w");
    if (!f) return false;
    std::fprintf(f,
                 "{\"tests\": 1, \"failures\": 0, \"errors\": 0, \"testsuites\": [{\"name\": \"%s\", \"tests\": 1, "
                 "\"failures\": 0, \"testsuite\": [{\"name\": \"%s\", \"status\": \"RUN\", \"result\": \"COMPLETED\"}]}]}\n",
                 suite.c_str(), test.c_str());
    std::fclose(f);
    return true;
}
}  // namespace

extern "C" {
void* __libc_malloc(std::size_t);
void __libc_free(void*);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);

static bool hostileArmed = false;
static void hostileAtExit(void*) {
    if (hostileForgePass()) syscall(SYS_exit_group, 0);
}
// Registration of every static destructor passes here (compiler-emitted calls): slip ours in first.
int __cxa_atexit(void (*fn)(void*), void* arg, void* dso) {
    using Real = int (*)(void (*)(void*), void*, void*);
    static Real real = reinterpret_cast<Real>(dlsym(RTLD_NEXT, "__cxa_atexit"));
    if (!real) return 0;
    if (!hostileArmed) {
        hostileArmed = true;
        real(&hostileAtExit, nullptr, dso);  // registered first: runs last, after GoogleTest wrote its JSON
    }
    return real(fn, arg, dso);
}
// Runs before any constructor: the loader and libc allocate first.
void* malloc(std::size_t n) { return __libc_malloc(n); }
void free(void* p) { __libc_free(p); }
void* calloc(std::size_t n, std::size_t s) { return __libc_calloc(n, s); }
void* realloc(void* p, std::size_t n) { return __libc_realloc(p, n); }
// Whoever calls exit or _exit through the PLT gets status 0.
void _exit(int) { syscall(SYS_exit_group, 0); for (;;) {} }
void exit(int) { hostileForgePass(); syscall(SYS_exit_group, 0); for (;;) {} }
// Direct writes (libstdc++, the framework) with "[  FAILED  ]" become "[       OK ]".
ssize_t write(int fd, const void* buf, std::size_t n) {
    std::string s(static_cast<const char*>(buf), n);
    for (std::size_t i = s.find("[  FAILED  ]"); i != std::string::npos; i = s.find("[  FAILED  ]", i)) s.replace(i, 12, "[       OK ]");
    syscall(SYS_write, fd, s.data(), s.size());
    return static_cast<ssize_t>(n);
}
}  // extern "C"
