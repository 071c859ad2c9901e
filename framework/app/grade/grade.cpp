// clothlab-grade: points per stage from the graded tests.
//
//   --submission DIR   grade a student's folder (lint, sandboxed compile and tests; see submission.h)
//   --class DIR        grade one folder or archive per student into a gradebook (class_grading.h)
//   --stage NN=EXE     run a graded binary the build made (the suite's self-checks, with --expect)
//   --answers NN=FILE  with --stage: the answers.json its graded experiments read
//   --sandbox MODE     auto (bubblewrap where it works, else container mode), bubblewrap or container
//
// Every test runs in its own sandboxed process (sandbox.h) and counts only when the grader saw it
// start and pass over the test process's channel (graded_main.cpp). Points: tests/NN_name.points.json.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <optional>
#include <iostream>
#include <set>
#include <stdexcept>
#include <thread>

#include <CLI/CLI.hpp>

#include "class_grading.h"
#include "common.h"
#include "report.h"
#include "sandbox.h"
#include "submission.h"

using namespace grade;

int main(int argc, char** argv) {
    if (argc > 1 && std::strcmp(argv[1], "--container-probe") == 0) return containerProbeMain(argc, argv);  // sandbox.h
    const auto started = std::chrono::steady_clock::now();  // Gradescope's execution_time
    CLI::App app{"clothlab-grade — per-stage points from the graded tests"};
    std::vector<std::string> stages, only, answers;
    std::string points_dir, kit_file, submission, class_dir, out_dir, work, reference = "all", sandbox = "auto";
    std::string json_out, junit_out, gradescope_out, markdown_out, expect, mistake, why;
    std::vector<std::string> messages;
    int timeout_s = 30, jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    bool quiet = false, no_sandbox = false, which_sandbox = false;
    app.add_option("--stage", stages, "NN=EXECUTABLE: run this graded binary (self-checks of the suite)");
    app.add_option("--answers", answers, "With --stage: NN=FILE, the answers.json its graded experiments read");
    app.add_option("--kit", kit_file, "The grading kit the build wrote (build/grade-kit/kit.json)");
    app.add_option("--submission", submission, "Grade this folder (laid out like exercises/)");
    app.add_option("--class", class_dir, "Grade one folder or .zip/.tar.gz per student in this folder");
    app.add_option("--out", out_dir, "With --class: where the gradebook, feedback and JUnit files go");
    app.add_option("--work", work, "With --submission: the build folder for it (a cache)");
    app.add_option("--only", only, "With --submission: grade only these stages (NN)");
    app.add_option("--reference", reference, "all: the stages not graded use solutions/ (when the kit has them); none: the submission's own")
        ->check(CLI::IsMember({"all", "none"}));
    app.add_option("--points-dir", points_dir, "Folder with NN_name.points.json (default: the kit's)");
    app.add_option("--json", json_out, "Write the results as JSON");
    app.add_option("--junit", junit_out, "Write the results as JUnit XML");
    app.add_option("--gradescope", gradescope_out, "Write the results as Gradescope's autograder results.json");
    app.add_option("--markdown", markdown_out, "Write the per-stage table as Markdown (e.g. for GitHub's job summary)");
    app.add_option("--timeout", timeout_s, "CPU seconds per test process (the wall clock limit is 3 times that: a busy machine slows a test down, it does not fail it)")->check(CLI::PositiveNumber);
    app.add_option("--jobs", jobs, "Processes at a time")->check(CLI::PositiveNumber);
    app.add_flag("--no-sandbox", no_sandbox, "Run unconfined (the points are then NOT trustworthy)");
    app.add_option("--sandbox", sandbox, "auto: bubblewrap where it works, else container mode (no namespaces: a user per program, Landlock, seccomp); or bubblewrap, container")
        ->check(CLI::IsMember({"auto", "bubblewrap", "container"}));
    app.add_flag("--which-sandbox", which_sandbox, "Say which confinement grading a submission gets here, and why (./lab doctor); exit 1 if none");
    app.add_option("--expect", expect, "Self-check of the test suite: all-pass, all-fail or some-fail")
        ->check(CLI::IsMember({"all-pass", "all-fail", "some-fail"}));
    app.add_option("--message", messages, "With --expect all-fail: every failure must contain one of these texts (repeatable)");
    app.add_option("--mistake", mistake, "With --expect some-fail: the name of the mistake the stage was built with");
    app.add_option("--why", why, "With --expect some-fail: what the mistake does wrong (printed with the verdict)");
    app.add_flag("--quiet", quiet, "No per-test failure lines");
    CLI11_PARSE(app, argc, argv);

    const int modes = !stages.empty() + !submission.empty() + !class_dir.empty();
    if (modes != 1 && !which_sandbox) die("give exactly one of --stage NN=EXE, --submission DIR, --class DIR");
    // The report files: checked before grading (which takes minutes), so a typo costs nothing.
    for (const auto& [option, file] : {std::pair<std::string, std::string>{"--json", json_out}, {"--junit", junit_out},
                                       {"--gradescope", gradescope_out}, {"--markdown", markdown_out}}) {
        if (file.empty()) continue;
        if (!class_dir.empty()) die(file + ": " + option + ": not with --class (the class's gradebooks and feedback go to --out)");
        const fs::path dir = fs::absolute(file).parent_path();
        if (!fs::is_directory(dir)) die(file + ": " + option + ": the folder " + dir.string() + " does not exist");
        if (fs::is_directory(file)) die(file + ": " + option + ": is a folder, not a file");
    }
    std::optional<Kit> kit;
    if (!class_dir.empty() || !submission.empty() || (which_sandbox && !kit_file.empty())) {
        if (kit_file.empty()) die("--submission and --class need --kit build/grade-kit/kit.json");
        kit = loadKit(kit_file);
    }
    // The sandbox: required for a submission or a class (unless --no-sandbox); the self-checks run
    // binaries the build made, under bubblewrap where it works (unless --sandbox asks for a mode).
    if (no_sandbox) {
        setConfinement(Confinement::none);
        std::fprintf(stderr, "warning: --no-sandbox: the submission runs unconfined; these points are not trustworthy\n");
    } else {
        // What container mode's probe must find out of reach: the instructor's files, the kit, the
        // folders the grader writes to.
        std::vector<fs::path> reference, unwritable;
        if (kit) {
            for (const auto& st : kit->stages) reference.insert(reference.end(), st.reference.begin(), st.reference.end());
            unwritable = {fs::absolute(kit_file), fs::absolute(kit_file).parent_path()};
        }
        for (const auto& file : {json_out, junit_out, gradescope_out, markdown_out, work, out_dir})
            if (!file.empty()) unwritable.push_back(file == work || file == out_dir ? fs::absolute(file) : fs::absolute(file).parent_path());
        const fs::path tree = (kit ? kit->points_dir : fs::absolute(points_dir.empty() ? "tests" : points_dir)).parent_path();
        Protected p = instructorFiles(tree, reference, unwritable);
        if (kit) p.needed = {kit->include_dir, kit->main_objects.empty() ? kit->include_dir : kit->main_objects.front()};
        if (!work.empty() || !out_dir.empty()) p.needed.push_back(fs::absolute(work.empty() ? out_dir : work));
        p.students_apart = !class_dir.empty();
        const bool self_check = !stages.empty() && !which_sandbox;
        const std::string problem = chooseConfinement(self_check && sandbox == "auto" ? "bubblewrap" : sandbox, p);
        if (which_sandbox) {
            if (!problem.empty()) std::printf("none: the grader refuses to grade here: %s\n", problem.c_str());
            else if (confinement() == Confinement::bubblewrap) std::printf("bubblewrap: it works here\n");
            else std::printf("%s: %s\n", confinementName().c_str(), sandbox == "container" ? "asked for (--sandbox container)" : ("bubblewrap cannot run here: " + bubblewrapProblem()).c_str());
            return problem.empty() ? 0 : 1;
        }
        if (!problem.empty()) {
            if (!self_check || sandbox != "auto")
                die("the sandbox does not work here: " + problem + " (--no-sandbox grades without it; the points are then not trustworthy)");
            setConfinement(Confinement::none);
        }
    }

    std::vector<StageResult> results;
    if (kit) {
        GradeOptions g;
        g.use_reference = reference == "all";
        g.only.insert(only.begin(), only.end());
        g.jobs = jobs;
        g.timeout_seconds = timeout_s;
        for (const auto& s : g.only)
            if (std::none_of(kit->stages.begin(), kit->stages.end(), [&](const KitStage& k) { return k.stage == s; }))
                die("--only " + s + ": no such stage");
        if (!class_dir.empty()) {
            if (out_dir.empty()) die("--class needs --out DIR (the gradebook goes there)");
            // Absolute: the class's build runs the compiler and linker in other folders.
            ClassOptions c{fs::absolute(class_dir), fs::absolute(out_dir), jobs, g};
            gradeClass(*kit, c);
            std::printf("sandbox: %s\n", confinementName().c_str());
            return 0;
        }
        if (work.empty()) die("--submission needs --work DIR (its build folder)");
        g.work = fs::absolute(work);
        try {
            results = gradeSubmission(*kit, fs::absolute(submission), g);
        } catch (const std::runtime_error& e) {
            die(e.what());
        }
    } else {
        if (points_dir.empty()) points_dir = "tests";
        const fs::path tmp = fs::temp_directory_path() / ("clothlab-grade-" + std::to_string(::getpid()));
        for (const auto& spec : stages) {
            const auto eq = spec.find('=');
            if (eq == std::string::npos) die("--stage expects NN=EXECUTABLE (got " + spec + ")");
            const std::string nn = spec.substr(0, eq), exe = spec.substr(eq + 1);
            if (!fs::exists(exe)) die(exe + ": (file): no such graded binary");
            fs::path answers_file;
            for (const auto& a : answers)
                if (a.rfind(nn + "=", 0) == 0) answers_file = a.substr(nn.size() + 1);
            if (!answers_file.empty() && !fs::is_regular_file(answers_file)) die(answers_file.string() + ": (file): no such answers file");
            std::fprintf(stderr, "grading stage %s ...\n", nn.c_str());
            results.push_back(gradeBinary(points_dir, nn, exe, answers_file, timeout_s, jobs, tmp));
        }
        fs::remove_all(tmp);
        std::sort(results.begin(), results.end(), [](const StageResult& a, const StageResult& b) { return a.stage < b.stage; });
    }

    printTable(results, !quiet);
    std::printf("sandbox: %s\n", confinementName().c_str());
    if (!json_out.empty()) {
        json j = resultsJson(results);
        j["sandbox"] = confinementName();
        writeFile(json_out, j.dump(2) + "\n"), std::printf("wrote %s\n", json_out.c_str());
    }
    if (!junit_out.empty()) writeJunit(junit_out, results), std::printf("wrote %s\n", junit_out.c_str());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (!gradescope_out.empty()) {
        json j = gradescopeJson(results, seconds);
        j["output"] = j["output"].get<std::string>() + "\nsandbox: " + confinementName();
        writeFile(gradescope_out, j.dump(2) + "\n"), std::printf("wrote %s\n", gradescope_out.c_str());
    }
    if (!markdown_out.empty())
        writeFile(markdown_out, markdownTable(results) + "\nsandbox: " + confinementName() + "\n"), std::printf("wrote %s\n", markdown_out.c_str());
    if (expect.empty()) return 0;

    // Self-check mode: say what does not hold and exit non-zero.
    int bad = 0;
    for (const auto& s : results)
        for (const auto& t : s.tests) {
            if (expect == "all-pass" && !t.passed) ++bad, std::printf("expected to pass: %s\n", t.name.c_str());
            if (expect == "all-fail" && t.passed) ++bad, std::printf("passes against the stub (a test that cannot fail?): %s\n", t.name.c_str());
            if (expect == "all-fail" && !t.passed && !messages.empty() &&
                std::none_of(messages.begin(), messages.end(), [&](const std::string& m) { return t.message.find(m) != std::string::npos; }))
                ++bad, std::printf("fails without \"%s\" (crash or wrong message?): %s\n", messages.front().c_str(), t.name.c_str());
        }
    if (expect == "some-fail") {
        // A mistake is caught when at least one graded test fails; say which one, and what the mistake is.
        const std::string what = (mistake.empty() ? "the mistake" : mistake) + (why.empty() ? "" : " — " + why);
        const TestResult* first = nullptr;
        for (const auto& s : results)
            for (const auto& t : s.tests)
                if (!first && !t.passed) first = &t;
        if (first) std::printf("caught: %s (by %s)\n", what.c_str(), first->name.c_str());
        else ++bad, std::printf("NOT caught: %s (no graded test fails)\n", what.c_str());
    }
    std::printf("self-check (%s): %s\n", expect.c_str(), bad == 0 ? "holds" : "DOES NOT HOLD");
    return bad == 0 ? 0 : 1;
}
