// clothlab-grade: points per stage from the graded tests (docs/grading.md; the options: --help).
// Every test runs in its own sandboxed process (sandbox.h) and counts only when the grader saw it
// start and pass over the test process's channel (test_process/graded_main.cpp).
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <iostream>
#include <optional>
#include <stdexcept>

#include <CLI/CLI.hpp>

#include "class_grading.h"
#include "report.h"
#include "sandbox.h"

using namespace grade;

namespace {

struct Options {
    std::vector<std::string> binaries, stages, answers, messages;
    std::string points_dir, kit, submission, class_dir, out, work, reference = "all", sandbox = "auto";
    std::string json, junit, gradescope, markdown, expect, mistake, why;
    int timeout = 30, jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    bool quiet = false, no_sandbox = false, which_sandbox = false;
};

/// Chooses the confinement: required for a submission or a class (unless --no-sandbox); the
/// self-checks run binaries the build made, under bubblewrap where it works. Container mode's probe
/// must find out of reach the instructor's files, the kit and the folders the grader writes to.
/// Returns the exit status of --which-sandbox, or -1 to go on grading.
int confine(const Options& o, const std::optional<Kit>& kit) {
    if (o.no_sandbox) {
        setConfinement(Confinement::none);
        std::fprintf(stderr, "warning: --no-sandbox: the submission runs unconfined; these points are not trustworthy\n");
        return -1;
    }
    std::vector<fs::path> reference, unwritable;
    if (kit) {
        for (const auto& st : kit->stages) reference.insert(reference.end(), st.reference.begin(), st.reference.end());
        unwritable = {fs::absolute(o.kit), fs::absolute(o.kit).parent_path()};
    }
    for (const auto& f : {o.json, o.junit, o.gradescope, o.markdown, o.work, o.out})
        if (!f.empty()) unwritable.push_back(f == o.work || f == o.out ? fs::absolute(f) : fs::absolute(f).parent_path());
    const fs::path tree = (kit ? kit->points_dir : fs::absolute(o.points_dir.empty() ? "tests" : o.points_dir)).parent_path();
    Protected p = instructorFiles(tree, reference, unwritable);
    if (kit) p.needed = {kit->include_dir, kit->main_objects.empty() ? kit->include_dir : kit->main_objects.front()};
    if (!o.work.empty() || !o.out.empty()) p.needed.push_back(fs::absolute(o.work.empty() ? o.out : o.work));
    p.students_apart = !o.class_dir.empty();
    const bool self_check = !o.binaries.empty() && !o.which_sandbox;
    const std::string problem = chooseConfinement(self_check && o.sandbox == "auto" ? "bubblewrap" : o.sandbox, p);
    if (o.which_sandbox) {
        if (!problem.empty()) std::printf("none: the grader refuses to grade here: %s\n", problem.c_str());
        else if (confinement() == Confinement::bubblewrap) std::printf("bubblewrap: it works here\n");
        else std::printf("%s: %s\n", confinementName().c_str(),
                         o.sandbox == "container" ? "asked for (--sandbox container)" : ("bubblewrap cannot run here: " + bubblewrapProblem()).c_str());
        return problem.empty() ? 0 : 1;
    }
    if (!problem.empty() && (!self_check || o.sandbox != "auto"))
        die("the sandbox does not work here: " + problem + " (--no-sandbox grades without it; the points are then not trustworthy)");
    if (!problem.empty()) setConfinement(Confinement::none);
    return -1;
}

/// The suite's self-checks (--binary NN=EXE): every graded binary's tests with their points.
std::vector<StageResult> gradeBinaries(const Options& o) {
    std::vector<StageResult> results;
    const fs::path tmp = fs::temp_directory_path() / ("clothlab-grade-" + std::to_string(::getpid()));
    for (const auto& spec : o.binaries) {
        const auto eq = spec.find('=');
        if (eq == std::string::npos) die("--binary expects NN=EXECUTABLE (got " + spec + ")");
        const std::string nn = spec.substr(0, eq), exe = spec.substr(eq + 1);
        if (!fs::exists(exe)) die(exe + ": (file): no such graded binary");
        fs::path answers;
        for (const auto& a : o.answers)
            if (a.rfind(nn + "=", 0) == 0) answers = a.substr(nn.size() + 1);
        if (!answers.empty() && !fs::is_regular_file(answers)) die(answers.string() + ": (file): no such answers file");
        std::fprintf(stderr, "grading stage %s ...\n", nn.c_str());
        results.push_back(gradeBinary(o.points_dir.empty() ? "tests" : o.points_dir, nn, exe, answers, o.timeout, o.jobs, tmp));
    }
    fs::remove_all(tmp);
    std::sort(results.begin(), results.end(), [](const StageResult& a, const StageResult& b) { return a.stage < b.stage; });
    return results;
}

/// The self-check's verdict (--expect): says what does not hold; the exit status.
int selfCheck(const Options& o, const std::vector<StageResult>& results) {
    int bad = 0;
    const TestResult* first_failed = nullptr;
    for (const auto& s : results)
        for (const auto& t : s.tests) {
            const bool message = o.messages.empty() ||
                                 std::any_of(o.messages.begin(), o.messages.end(), [&](const std::string& m) { return t.message.find(m) != std::string::npos; });
            if (!t.passed && !first_failed) first_failed = &t;
            if (o.expect == "all-pass" && !t.passed) ++bad, std::printf("expected to pass: %s\n", t.name.c_str());
            if (o.expect == "all-fail" && t.passed) ++bad, std::printf("passes against the stub (a test that cannot fail?): %s\n", t.name.c_str());
            if (o.expect == "all-fail" && !t.passed && !message)
                ++bad, std::printf("fails without \"%s\" (crash or wrong message?): %s\n", o.messages.front().c_str(), t.name.c_str());
        }
    if (o.expect == "some-fail") {  // a mistake is caught when at least one graded test fails: say which, and what the mistake is
        const std::string what = (o.mistake.empty() ? "the mistake" : o.mistake) + (o.why.empty() ? "" : " — " + o.why);
        if (first_failed) std::printf("caught: %s (by %s)\n", what.c_str(), first_failed->name.c_str());
        else ++bad, std::printf("NOT caught: %s (no graded test fails)\n", what.c_str());
    }
    std::printf("self-check (%s): %s\n", o.expect.c_str(), bad == 0 ? "holds" : "DOES NOT HOLD");
    return bad == 0 ? 0 : 1;
}

/// The table on standard output and the report files asked for, each ending with the confinement.
void report(const Options& o, const std::vector<StageResult>& results, double seconds) {
    printTable(results, !o.quiet);
    const std::string sandbox = "sandbox: " + confinementName();
    std::printf("%s\n", sandbox.c_str());
    const auto write = [](const std::string& file, const std::string& text) {
        if (!file.empty()) writeFile(file, text), std::printf("wrote %s\n", file.c_str());
    };
    json j = resultsJson(results), gs = gradescopeJson(results, seconds);
    j["sandbox"] = confinementName();
    gs["output"] = gs["output"].get<std::string>() + "\n" + sandbox;
    write(o.json, j.dump(2) + "\n");
    if (!o.junit.empty()) writeJunit(o.junit, results), std::printf("wrote %s\n", o.junit.c_str());
    write(o.gradescope, gs.dump(2) + "\n");
    write(o.markdown, markdownTable(results) + "\n" + sandbox + "\n");
}

}  // namespace

int main(int argc, char** argv) {
    if (argc > 1 && std::strcmp(argv[1], "--container-probe") == 0) return containerProbeMain(argc, argv);  // sandbox.h
    const auto started = std::chrono::steady_clock::now();  // Gradescope's execution_time
    CLI::App app{"clothlab-grade — per-stage points from the graded tests"};
    Options o;
    app.add_option("--kit", o.kit, "The grading kit the build wrote (build/grade-kit/kit.json)");
    app.add_option("--submission", o.submission, "Grade this folder (laid out like exercises/)");
    app.add_option("--class", o.class_dir, "Grade one folder or .zip/.tar.gz per student in this folder");
    app.add_option("--out", o.out, "With --class: where the gradebook, feedback and JUnit files go");
    app.add_option("--work", o.work, "With --submission: the build folder for it (a cache)");
    app.add_option("--stage", o.stages, "With --submission or --class: grade only these stages (NN)");
    app.add_option("--reference", o.reference, "all: the stages not graded use solutions/ (when the kit has them); none: the submission's own")
        ->check(CLI::IsMember({"all", "none"}));
    app.add_option("--binary", o.binaries, "NN=EXECUTABLE: run this graded binary (self-checks of the suite)");
    app.add_option("--answers", o.answers, "With --binary: NN=FILE, the answers.json its graded experiments read");
    app.add_option("--points-dir", o.points_dir, "With --binary: the folder with NN_name.points.json (default: tests)");
    app.add_option("--json", o.json, "Write the results as JSON");
    app.add_option("--junit", o.junit, "Write the results as JUnit XML");
    app.add_option("--gradescope", o.gradescope, "Write the results as Gradescope's autograder results.json");
    app.add_option("--markdown", o.markdown, "Write the per-stage table as Markdown (e.g. for GitHub's job summary)");
    app.add_option("--timeout", o.timeout, "CPU seconds per test process (the wall clock limit is 3 times that: a busy machine slows a test down, it does not fail it)")
        ->check(CLI::PositiveNumber);
    app.add_option("--jobs", o.jobs, "Processes at a time")->check(CLI::PositiveNumber);
    app.add_flag("--no-sandbox", o.no_sandbox, "Run unconfined (the points are then NOT trustworthy)");
    app.add_option("--sandbox", o.sandbox, "auto: bubblewrap where it works, else container mode (no namespaces: a user per program, Landlock, seccomp); or bubblewrap, container")
        ->check(CLI::IsMember({"auto", "bubblewrap", "container"}));
    app.add_flag("--which-sandbox", o.which_sandbox, "Say which confinement grading a submission gets here, and why (./lab doctor); exit 1 if none");
    app.add_option("--expect", o.expect, "Self-check of the test suite: all-pass, all-fail or some-fail")->check(CLI::IsMember({"all-pass", "all-fail", "some-fail"}));
    app.add_option("--message", o.messages, "With --expect all-fail: every failure must contain one of these texts (repeatable)");
    app.add_option("--mistake", o.mistake, "With --expect some-fail: the name of the mistake the stage was built with");
    app.add_option("--why", o.why, "With --expect some-fail: what the mistake does wrong (printed with the verdict)");
    app.add_flag("--quiet", o.quiet, "No per-test failure lines");
    CLI11_PARSE(app, argc, argv);

    if (!o.binaries.empty() + !o.submission.empty() + !o.class_dir.empty() != 1 && !o.which_sandbox)
        die("give exactly one of --binary NN=EXE, --submission DIR, --class DIR");
    // The report files: checked before grading (which takes minutes), so a typo costs nothing.
    for (const auto& [option, file] : {std::pair<std::string, std::string>{"--json", o.json}, {"--junit", o.junit}, {"--gradescope", o.gradescope},
                                       {"--markdown", o.markdown}}) {
        if (file.empty()) continue;
        if (!o.class_dir.empty()) die(file + ": " + option + ": not with --class (the class's gradebooks and feedback go to --out)");
        if (!fs::is_directory(fs::absolute(file).parent_path())) die(file + ": " + option + ": the folder " + fs::absolute(file).parent_path().string() + " does not exist");
        if (fs::is_directory(file)) die(file + ": " + option + ": is a folder, not a file");
    }
    std::optional<Kit> kit;
    if (!o.class_dir.empty() || !o.submission.empty() || (o.which_sandbox && !o.kit.empty())) {
        if (o.kit.empty()) die("--submission and --class need --kit build/grade-kit/kit.json");
        kit = loadKit(o.kit);
    }
    if (const int which = confine(o, kit); which >= 0) return which;
    if (!kit) {
        const auto results = gradeBinaries(o);
        report(o, results, std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
        return o.expect.empty() ? 0 : selfCheck(o, results);
    }
    GradeOptions g;
    g.use_reference = o.reference == "all";
    g.only.insert(o.stages.begin(), o.stages.end());
    g.jobs = o.jobs;
    g.timeout_seconds = o.timeout;
    for (const auto& s : g.only)
        if (std::none_of(kit->stages.begin(), kit->stages.end(), [&](const KitStage& k) { return k.stage == s; })) die("--stage " + s + ": no such stage");
    if (!o.class_dir.empty()) {
        if (o.out.empty()) die("--class needs --out DIR (the gradebook goes there)");
        gradeClass(*kit, {fs::absolute(o.class_dir), fs::absolute(o.out), o.jobs, g});  // absolute: the class's build runs elsewhere
        std::printf("sandbox: %s\n", confinementName().c_str());
        return 0;
    }
    if (o.work.empty()) die("--submission needs --work DIR (its build folder)");
    g.work = fs::absolute(o.work);
    try {
        const auto results = gradeSubmission(*kit, fs::absolute(o.submission), g);
        report(o, results, std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
        return o.expect.empty() ? 0 : selfCheck(o, results);
    } catch (const std::runtime_error& e) {
        die(e.what());
    }
}
