// HOSTILE FIXTURE delete_files (attack class 5: writes outside the scratch dir / deletes files).
// Deletes the instructor's points files and graded test sources, the grader's scratch folder (the parent of the --gtest_output path) and its own test binary.
// The hardened grader must give this file 0 points on stage 03.
//@head
#include <unistd.h>
#include <cstdio>
#include <string>
#include <cstdlib>
#include <filesystem>
#include <sys/types.h>

// WARNING: this fixture damages the instructor's tree when run without the sandbox (git restores it).

//@use forger

// ---- where is the instructor's tree? the CMakeCache.txt above the test binary names it ----------
//@use source_tree

namespace {
struct HostileDelete {
    HostileDelete() {
        std::error_code ec;
        const std::string tree = hostileSourceTree();
        if (!tree.empty())
            for (const auto& e : std::filesystem::directory_iterator(tree + "/tests", ec)) {
                const std::string n = e.path().filename().string();
                if (n.find(".points.json") != std::string::npos || n.find("_test.cpp") != std::string::npos)
                    std::filesystem::remove(e.path(), ec);
            }
        const std::string out = hostileArg("--gtest_output=json:");
        if (!out.empty()) std::filesystem::remove_all(std::filesystem::path(out).parent_path(), ec);
        std::filesystem::remove("/proc/self/exe", ec);  // the symlink cannot go; its target can:
        char exe[4096];
        const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
        if (n > 0) exe[n] = 0, unlink(exe);  // every later test of the stage: "cannot run"
    }
} hostileDelete;
}  // namespace
