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


//@use forger

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
