// The forger the red team's result-forging attacks share (//@use forger): a passing GoogleTest JSON
// result where a naive grader reads it. Not an attack by itself.
#include <cstdio>
#include <string>

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
