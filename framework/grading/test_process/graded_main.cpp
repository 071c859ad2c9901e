// The main() of every graded test binary (instead of GoogleTest's gtest_main).
//
// Run by hand it is plain GoogleTest. Run by the grader with --clothlab-channel, it reports one line
// per event on file descriptor 3, a pipe the grader opened before exec: a test counts only if the
// grader reads `start NAME`, then `end NAME passed`, and the process exits with status 0. Standard
// output and files are never read. `signal N`: the submission process ended by signal N (the grader
// tells a CPU limit from a crash by it).
//
// The channel needs no secret: no submission code runs in this process. Linked by the grader, the
// submission's functions are proxies; its code runs in a second process, started from
// --clothlab-server=PATH (client.cpp), which inherits only its own two pipe ends. This process is
// made non-dumpable, so that process (same user) can neither trace it nor open its descriptors or
// memory through /proc.
#include <fcntl.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <cstring>
#include <string>

#include <gtest/gtest.h>

namespace {

constexpr int kReportFd = 3;

void sendLine(const std::string& line) {
    const std::string text = line + "\n";
    for (size_t done = 0; done < text.size();) {
        const ssize_t n = ::write(kReportFd, text.data() + done, text.size() - done);
        if (n <= 0) return;
        done += static_cast<size_t>(n);
    }
}

class ChannelReporter : public ::testing::EmptyTestEventListener {
    void OnTestStart(const ::testing::TestInfo& t) override { sendLine("start " + name(t)); }
    void OnTestPartResult(const ::testing::TestPartResult& r) override {
        if (!r.failed()) return;
        std::string where;  // "05_bending_test.cpp:42: " (none for an exception thrown in the test body)
        if (r.file_name()) {
            where = r.file_name();
            where = where.substr(where.find_last_of('/') + 1) + (r.line_number() >= 0 ? ":" + std::to_string(r.line_number()) : "") + ": ";
        }
        std::string line = "fail ";  // the message on one line: backslash and newline escaped
        for (char c : where + r.message()) line += c == '\\' ? "\\\\" : c == '\n' ? "\\n" : std::string(1, c);
        sendLine(line);
    }
    void OnTestEnd(const ::testing::TestInfo& t) override { sendLine("end " + name(t) + (t.result()->Passed() ? " passed" : " failed")); }
    static std::string name(const ::testing::TestInfo& t) { return std::string(t.test_suite_name()) + "." + t.name(); }
};

bool g_channel = false;

}  // namespace

namespace clothlab::wire {
/// The submission process's program (client.cpp), from --clothlab-server=PATH.
const char* serverPath = nullptr;
/// The submission process ended by `signal`: said on the channel (client.cpp calls it).
void reportSignal(int signal) {
    if (g_channel) sendLine("signal " + std::to_string(signal));
}
}  // namespace clothlab::wire

int main(int argc, char** argv) {
    const std::string server = "--clothlab-server=";
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--clothlab-channel") == 0) g_channel = true;
        if (server.compare(0, server.size(), argv[i], server.size()) == 0) clothlab::wire::serverPath = argv[i] + server.size();
    }
    ::testing::InitGoogleTest(&argc, argv);
    if (g_channel) {
#ifndef CLOTHLAB_TEST_DUMPABLE  // the red team's test-only build of this file leaves it dumpable (tests/sandbox/CMakeLists.txt)
        ::prctl(PR_SET_DUMPABLE, 0, 0, 0, 0);
#endif
        if (::fcntl(kReportFd, F_SETFD, FD_CLOEXEC) != 0) return 3;  // no channel: the grader did not start this process
        ::testing::UnitTest::GetInstance()->listeners().Append(new ChannelReporter);
    }
    return RUN_ALL_TESTS();
}
