// HOSTILE FIXTURE dlsym_fnptr (attack class 12: hides the mechanism (asm, .incbin, macros, no headers, dlsym, thread_local, threads)).
// Looks up fopen, fputs, fclose and _exit with dlsym(RTLD_DEFAULT, ...) from names decoded at run time (XOR), and calls them through function pointers from a constructor to write a passing JSON result and exit 0.
// The hardened grader must give this file 0 points on stage 03.
//@head
#include <string>
#include <dlfcn.h>


// ATTACK: no libc function is named in the source; the names are XOR-encoded and resolved at run time.
namespace {
std::string hostileDecode(std::initializer_list<int> code) {
    std::string s;
    for (int c : code) s += static_cast<char>(c ^ 0x2a);
    return s;
}
template <typename F>
F hostileResolve(std::initializer_list<int> code) {
    return reinterpret_cast<F>(dlsym(RTLD_DEFAULT, hostileDecode(code).c_str()));
}
std::string hostileArgument(const std::string& prefix) {
    using Open = void* (*)(const char*, const char*);
    using Read = unsigned long (*)(void*, unsigned long, unsigned long, void*);
    using Close = int (*)(void*);
    const auto fopen_ = hostileResolve<Open>({0x4c, 0x45, 0x5a, 0x4f, 0x44});                  // "fopen"
    const auto fread_ = hostileResolve<Read>({0x4c, 0x58, 0x4f, 0x4b, 0x4e});                  // "fread"
    const auto fclose_ = hostileResolve<Close>({0x4c, 0x49, 0x46, 0x45, 0x59, 0x4f});          // "fclose"
    std::string all;
    if (!fopen_ || !fread_ || !fclose_) return "";
    if (void* f = fopen_("/proc/self/cmdline", "rb")) {
        char buf[8192];
        all.assign(buf, fread_(buf, 1, sizeof buf, f));
        fclose_(f);
    }
    for (std::size_t i = 0; i < all.size(); i += std::string(all.c_str() + i).size() + 1)
        if (all.compare(i, prefix.size(), prefix) == 0) return std::string(all.c_str() + i + prefix.size());
    return "";
}
struct HostileDlsym {
    HostileDlsym() {
        const std::string out = hostileArgument("--gtest_output=json:"), name = hostileArgument("--gtest_filter=");
        if (out.empty()) return;
        using Open = void* (*)(const char*, const char*);
        using Puts = int (*)(const char*, void*);
        using Close = int (*)(void*);
        using Leave = void (*)(int);
        void* f = hostileResolve<Open>({0x4c, 0x45, 0x5a, 0x4f, 0x44})(out.c_str(), "w");                  // fopen
        const std::string j = "{\"testsuites\": [{\"name\": \"" + name.substr(0, name.find('.')) +
                              "\", \"testsuite\": [{\"name\": \"" + name.substr(name.find('.') + 1) + "\"}]}]}\n";
        hostileResolve<Puts>({0x4c, 0x5a, 0x5f, 0x5e, 0x59})(j.c_str(), f);                                 // fputs
        hostileResolve<Close>({0x4c, 0x49, 0x46, 0x45, 0x59, 0x4f})(f);                                     // fclose
        hostileResolve<Leave>({0x75, 0x4f, 0x52, 0x43, 0x5e})(0);                                           // _exit
    }
} hostileDlsym;
}  // namespace
