// Running the graded tests: each in its own sandboxed process, the verdict read from its channel.
#include <sched.h>

#include <csignal>
#include <cstring>
#include <set>
#include <sstream>

#include "sandbox.h"
#include "submission.h"

namespace grade {

namespace {

/// A test's wall clock limit, in multiples of its CPU time limit (--timeout).
constexpr int kWallPerCpuSecond = 3;

/// The verdict GoogleTest itself reports, which the channel replaced (test tool only, `channel` off):
/// its JSON result names the test without a failure, or its output says `[       OK ] NAME`.
bool googleTestSaysPassed(const std::string& name, const fs::path& json_file, const fs::path& log) {
    const json j = json::parse(readFile(json_file), nullptr, false);
    for (const auto& suite : j.is_object() ? j.value("testsuites", json::array()) : json::array())
        for (const auto& t : suite.value("testsuite", json::array()))
            if (suite.value("name", "") + "." + t.value("name", "") == name && !t.contains("failures")) return true;
    return readFile(log).find("[       OK ] " + name) != std::string::npos;
}

/// One test in its own sandboxed process; the verdict comes from the channel (test_process/graded_main.cpp).
/// With a `server` (the submission process's program) the test process starts it for the
/// submission's code; test and submission process share one CPU (`cpu`, or any when < 0).
TestResult runTest(const fs::path& exe, const fs::path& server, const fs::path& answers, const std::string& shown,
                   const std::string& name, int timeout_s, int cpu, const fs::path& log) {
    TestResult r;
    r.name = name;
    SandboxRun run;
    run.argv = {"/grade/test", "--gtest_filter=" + name, "--clothlab-channel", "--gtest_color=no"};
    run.mounts = {{exe, "/grade/test", false}};
    if (!server.empty()) {
        run.argv.push_back("--clothlab-server=/grade/submission");
        run.mounts.push_back({server, "/grade/submission", false});
    }
    const fs::path gtest_out = log.parent_path() / (log.stem().string() + ".out");
    if (weakened("channel")) {  // test tool only: GoogleTest writes its JSON result where the grader reads it
        makeWritableForSandbox(gtest_out);
        run.argv.push_back("--gtest_output=json:/grade/out/result.json");
        run.mounts.push_back({gtest_out, "/grade/out", true});
    }
    // The graded experiments read the student's answers.json from here (tests/test_util.h answersPath).
    // One solver thread (OMP_NUM_THREADS, read by the solver's default team size, sim/team.h): the test
    // and the submission's process share one CPU, where a second thread can only wait for the first.
    // Its messages name the file as the student knows it (CLOTHLAB_ANSWERS_SHOWN_AS), not the sandbox's path.
    run.env = {{"CLOTHLAB_ANSWERS_DIR", "/grade/answers"}, {"CLOTHLAB_ANSWERS_SHOWN_AS", shown}, {"OMP_NUM_THREADS", "1"}};
    if (!answers.empty()) run.mounts.push_back({answers, "/grade/answers", false});
    // The limit is CPU time, per process (the test's and the submission's): a machine busy with other
    // work slows a test down, it does not fail it. The wall clock stops a program that waits forever.
    run.limits.cpu_seconds = timeout_s;
    run.limits.file_size = 16LL << 20;  // its log too
    run.timeout_seconds = kWallPerCpuSecond * timeout_s;
    run.log = log;
    run.channel = true;
    run.cpu = cpu;
    const RunOutcome out = runSandboxed(run);
    bool started = false, ended_passed = false;
    std::set<int> signals;  // what ended the submission process (graded_main.cpp's `signal N`)
    std::string failures, line;
    for (std::istringstream in(out.report); std::getline(in, line);) {
        if (line == "start " + name) started = true;
        else if (line == "end " + name + " passed") ended_passed = true;
        else if (line.rfind("signal ", 0) == 0) signals.insert(std::atoi(line.c_str() + 7));
        else if (line.rfind("fail ", 0) == 0) {  // one line, backslash and newline escaped
            for (size_t i = 5; i < line.size(); ++i) failures += line[i] != '\\' || i + 1 == line.size() ? line[i] : line[++i] == 'n' ? '\n' : line[i];
            failures += "\n";
        }
    }
    // The CPU limit: the kernel ends a process there with SIGXCPU, or a second later with SIGKILL when
    // it ignores SIGXCPU (nothing else in the sandbox may send SIGKILL: seccomp), the test's process or
    // the submission's.
    const auto by = [&](int sig) { return out.exit_code == 128 + sig || signals.count(sig); };
    const int code = out.exit_code;
    if (weakened("channel")) r.passed = googleTestSaysPassed(name, gtest_out / "result.json", log);
    else if (out.timed_out) r.message = "timed out: still running after " + std::to_string(run.timeout_seconds) + " s (waiting forever?)";
    else if (by(SIGXCPU) || by(SIGKILL)) r.message = "timed out: used more than " + std::to_string(timeout_s) + " s of CPU time (an endless loop?)";
    else if (!failures.empty()) r.message = failures;
    else if (!started || !ended_passed || code != 0) {
        std::string tail = readFile(log, 1u << 20);  // the last lines it printed
        if (tail.size() > 600) tail = tail.substr(tail.size() - 600);
        r.message = (!started ? "the test did not start (the program ended with status " + std::to_string(code) + " before it ran)"
                              : "crashed or ended early (" + (code > 128 ? "signal " + std::to_string(code - 128) + ", " + ::strsignal(code - 128)
                                                                         : "exit status " + std::to_string(code)) + ")") +
                    (tail.empty() ? "" : ":\n" + tail);
    } else r.passed = true;
    if (weakened("channel") && !r.passed) r.message = "GoogleTest did not report it passed";
    fs::remove(log);  // a flood of output must not pile up: the message keeps its tail
    return r;
}

}  // namespace

int usableCpu(int index) {
    static const std::vector<int> cpus = [] {
        std::vector<int> out;
        cpu_set_t set;
        if (::sched_getaffinity(0, sizeof set, &set) == 0)
            for (int c = 0; c < CPU_SETSIZE; ++c)
                if (CPU_ISSET(c, &set)) out.push_back(c);
        return out;
    }();
    return cpus.empty() ? -1 : cpus[static_cast<size_t>(index) % cpus.size()];
}

std::vector<StageResult> runStages(const fs::path& points_dir, const std::vector<StageRun>& stages, int timeout_s, int jobs,
                                   int first_cpu, const fs::path& logs) {
    std::vector<StageResult> out;
    std::vector<std::string> shown;  // the answers file as the student knows it
    std::vector<std::pair<size_t, size_t>> queue;  // (stage, test)
    for (size_t s = 0; s < stages.size(); ++s) {
        out.push_back(pointsStage(points_dir, stages[s].stage));
        const std::string file = fs::path(loadPoints(points_dir, stages[s].stage)["file"].get<std::string>()).filename().string();
        shown.push_back("exercises/" + file.substr(0, file.find('.')) + "/answers.json");  // NN_name.points.json
        for (size_t t = 0; t < out[s].tests.size(); ++t) queue.emplace_back(s, t);
    }
    std::vector<std::atomic<int>> timeouts(stages.size());  // per stage
    fs::create_directories(logs);
    parallelFor(static_cast<int>(queue.size()), jobs, [&](int i, int worker) {
        const auto [s, t] = queue[static_cast<size_t>(i)];
        TestResult& r = out[s].tests[t];
        TestResult ran{r.name, false, 0, 0, "not run: two tests of this stage timed out already", false};
        if (timeouts[s] < 2) {
            ran = runTest(stages[s].exe, stages[s].server, stages[s].answers, shown[s], r.name, timeout_s, usableCpu(first_cpu + worker),
                          logs / (stages[s].stage + "_" + std::to_string(t) + ".log"));
            if (ran.message.rfind("timed out", 0) == 0) ++timeouts[s];
        }
        r.passed = ran.passed, r.message = ran.message, r.points = ran.passed ? r.max_points : 0.0;
    });
    return out;
}

fs::path answersFolder(const fs::path& file, const fs::path& folder) {
    fs::remove_all(folder);
    fs::create_directories(folder);
    std::error_code ec;
    if (!file.empty() && fs::is_regular_file(fs::symlink_status(file, ec)) && fs::file_size(file, ec) <= 65536)
        writeFile(folder / "answers.json", readFile(file, 65536));
    makeWritableForSandbox(folder);
    return folder;
}

StageResult gradeBinary(const fs::path& points_dir, const std::string& stage, const fs::path& exe, const fs::path& answers,
                        int timeout_seconds, int jobs, const fs::path& tmp) {
    fs::create_directories(tmp);
    SandboxRun list;
    list.argv = {"/grade/test", "--gtest_list_tests"};
    list.mounts = {{fs::absolute(exe), "/grade/test", false}};
    list.log = tmp / ("list_" + stage + ".txt");
    if (runSandboxed(list).exit_code != 0) die(exe.string() + ": (binary): cannot list its tests");
    std::set<std::string> names, listed;
    std::istringstream in(readFile(list.log));
    for (std::string line, suite; std::getline(in, line);) {
        if (line.empty()) continue;
        line = line.substr(0, line.find("  #"));
        if (line[0] != ' ') suite = line;
        else names.insert(suite + line.substr(line.find_first_not_of(' ')));
    }
    const std::string file = loadPoints(points_dir, stage)["file"];
    for (const auto& t : pointsStage(points_dir, stage).tests) {
        listed.insert(t.name);
        if (!names.count(t.name)) die(file + (t.bonus ? ": bonus." : ": tests.") + t.name + ": no such test in " + exe.string());
    }
    for (const auto& n : names)
        if (!listed.count(n)) die(file + ": tests." + n + ": the graded test has no points");
    return runStages(points_dir, {{stage, fs::absolute(exe), {}, answersFolder(answers, tmp / ("answers_" + stage))}}, timeout_seconds, jobs, 0, tmp)
        .front();
}

}  // namespace grade
