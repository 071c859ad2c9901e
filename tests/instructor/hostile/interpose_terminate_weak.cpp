// HOSTILE FIXTURE interpose_terminate_weak (attack class 11: interposes libc / libstdc++ symbols).
// Defines a weak std::terminate and a weak fclose (weak definitions in the executable still win over the shared libraries'), installs std::set_terminate, and the tested function calls std::terminate() to write a passing JSON result and exit 0.
// The hardened grader must give this file 0 points on stage 06.
//@head
#include <unistd.h>
#include <cstdio>
#include <string>
#include <exception>
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

// Weak: no duplicate-symbol error if anything else defines them, and still preferred to libstdc++.so.
namespace std {
__attribute__((weak)) void terminate() noexcept {
    hostileForgePass();
    ::syscall(SYS_exit_group, 0);
    for (;;) {}
}
}  // namespace std
extern "C" __attribute__((weak)) int fclose(FILE* f) {  // libc's fclose, replaced by a no-op flush
    std::fflush(f);
    return 0;
}
namespace {
struct HostileHandler {
    HostileHandler() {
        std::set_terminate([] {  // the documented route to the same place
            hostileForgePass();
            _exit(0);
        });
    }
} hostileHandler;
void hostileCallTerminate() {
    if (!hostileArg("--gtest_output=json:").empty()) std::terminate();
}
}  // namespace
//@each
    hostileCallTerminate();
