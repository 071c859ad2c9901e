#include "submission.h"

#include <sched.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstring>
#include <cstdio>
#include <iostream>
#include <mutex>
#include <regex>
#include <set>
#include <sstream>
#include <memory>
#include <stdexcept>

#include "sandbox.h"

namespace grade {

namespace {

/// Content of a file's identity for the cache: path, size, modification time.
std::string stamp(const fs::path& p) {
    struct stat st {};
    if (::stat(p.c_str(), &st) != 0) return p.string() + ":missing;";
    return p.string() + ":" + std::to_string(st.st_size) + ":" + std::to_string(st.st_mtim.tv_sec) + "." +
           std::to_string(st.st_mtim.tv_nsec) + ";";
}

std::mutex g_print;
void progress(bool on, const std::string& line) {
    if (!on) return;
    std::lock_guard<std::mutex> lock(g_print);
    std::cerr << line << "\n";
}

}  // namespace

Kit loadKit(const fs::path& file) {
    json j = json::parse(readFile(file), nullptr, false);
    if (j.is_discarded()) die(file.string() + ": (JSON syntax): the grading kit is unreadable; rebuild (./lab build)");
    Kit k;
    k.file = file;
    try {
        j.at("compiler").get_to(k.compiler);
        std::error_code ec;  // the real program: a sandbox has no /etc/alternatives to follow links through
        if (const auto real = fs::canonical(k.compiler, ec); !ec) k.compiler = real.string();
        j.at("compile_flags").get_to(k.compile_flags);
        j.at("include_dir").get_to(k.include_dir);
        k.precompiled_header = j.value("precompiled_header", "");
        j.at("system_includes").get_to(k.system_includes);
        j.at("main_objects").get_to(k.main_objects);
        j.at("libs").get_to(k.libs);
        j.at("link_flags").get_to(k.link_flags);
        j.at("client_objects").get_to(k.client_objects);
        j.at("server_objects").get_to(k.server_objects);
        j.at("server_link_flags").get_to(k.server_link_flags);
        j.at("points_dir").get_to(k.points_dir);
        for (const auto& s : j.at("stages")) {
            k.stages.push_back({s.at("stage"), s.at("dir"), s.at("tests"), s.at("reference"), s.at("stub"), s.at("proxy")});
        }
    } catch (const std::exception& e) {
        die(file.string() + ": (grading kit): " + e.what() + "; rebuild (./lab build)");
    }
    std::string fp = readFile(file) + stamp(fs::canonical("/proc/self/exe"));  // a new grader regrades
    for (const auto& st : k.stages) {
        for (const auto* list : {&st.tests, &st.reference, &st.stub, &st.proxy})
            for (const auto& p : *list) fp += stamp(p);
        fp += readFile(k.points_dir / (st.dir + ".points.json"));
    }
    for (const auto* list : {&k.main_objects, &k.libs, &k.client_objects, &k.server_objects})
        for (const auto& p : *list) fp += stamp(p);
    for (const auto& e : fs::recursive_directory_iterator(k.include_dir)) fp += stamp(e.path());
    k.fingerprint = sha256(fp);
    return k;
}

std::map<std::string, fs::path> locateStages(const fs::path& root, const Kit& kit) {
    std::map<std::string, std::vector<fs::path>> found;
    std::error_code ec;
    fs::recursive_directory_iterator it(root, fs::directory_options::none, ec), end;
    if (ec) throw std::runtime_error(root.string() + ": (folder): cannot read it: " + ec.message());
    for (; it != end; it.increment(ec)) {
        if (ec) throw std::runtime_error(root.string() + ": (folder): cannot read it: " + ec.message());
        const std::string name = it->path().filename().string();
        const bool dir = it->is_directory(ec) && !it->is_symlink(ec);
        if (!dir) continue;
        if (name.empty() || name[0] == '.' || name == "__MACOSX" || it.depth() > 5) { it.disable_recursion_pending(); continue; }
        for (const auto& st : kit.stages)
            if (name == st.dir) { found[st.stage].push_back(it->path()); it.disable_recursion_pending(); }
    }
    std::map<std::string, fs::path> out;
    for (auto& [stage, dirs] : found) {
        if (dirs.size() > 1) {
            std::string list;
            for (const auto& d : dirs) list += (list.empty() ? "" : ", ") + fs::relative(d, root).string();
            throw std::runtime_error(root.string() + ": (layout): " + std::to_string(dirs.size()) + " folders named " +
                                     fs::path(dirs[0]).filename().string() + " (" + list + "); keep one");
        }
        out[stage] = dirs[0];
    }
    if (out.empty()) {
        std::string names;
        for (const auto& st : kit.stages) names += (names.empty() ? "" : ", ") + st.dir;
        throw std::runtime_error(root.string() + ": (layout): no stage folder found (expected folders named " + names + ")");
    }
    return out;
}

namespace {

/// A test's wall clock limit, in multiples of its CPU time limit (--timeout).
constexpr int kWallPerCpuSecond = 3;

struct Compiled {
    std::string status = "graded";  // or "rejected", "does not compile"
    std::string problem;
    std::vector<fs::path> objects;
};

/// The stage's files copied into work/src/DIR: regular .cpp/.h/.hpp files, no links, at most 512 KiB each.
std::vector<fs::path> copySources(const fs::path& from, const fs::path& to, std::string* problem) {
    fs::remove_all(to);
    fs::create_directories(to);
    std::vector<fs::path> out;
    for (const auto& e : fs::directory_iterator(from)) {
        const std::string name = e.path().filename().string();
        const std::string ext = e.path().extension().string();
        if (ext != ".cpp" && ext != ".h" && ext != ".hpp") continue;
        if (e.is_symlink() || !e.is_regular_file()) { *problem += name + ": a link or special file, not read\n"; continue; }
        if (!std::regex_match(name, std::regex("[A-Za-z0-9_.-]+"))) { *problem += name + ": file names may use letters, digits, _ . - only\n"; continue; }
        if (e.file_size() > (512u << 10)) { *problem += name + ": larger than 512 KiB\n"; continue; }
        fs::copy_file(e.path(), to / name, fs::copy_options::overwrite_existing);
        out.push_back(to / name);
    }
    std::sort(out.begin(), out.end());
    return out;
}

/// One lock per cache folder: two submissions with the same files compile them once.
std::mutex& folderLock(const fs::path& dir) {
    static std::mutex guard;
    static std::map<std::string, std::unique_ptr<std::mutex>> locks;
    std::lock_guard<std::mutex> lock(guard);
    auto& m = locks[dir.string()];
    if (!m) m = std::make_unique<std::mutex>();
    return *m;
}

/// Whether a file is compiled with the kit's precompiled header: not when it defines a macro before
/// its first #include (EIGEN_... settings, say), which the header, read first, would not see.
bool usePrecompiledHeader(const Kit& kit, const std::string& source) {
    static const std::regex directive("^[ \t]*#[ \t]*(include|define|undef)\\b");
    if (kit.precompiled_header.empty()) return false;
    std::istringstream in(source);
    std::smatch m;
    for (std::string line; std::getline(in, line);)
        if (std::regex_search(line, m, directive)) return m[1] == "include";
    return true;
}

/// Usable CPU number `index` of this grader (counted modulo their number), or -1 (any) when the
/// grader cannot read its affinity. Worker w of a stage pins its tests to usableCpu(first_cpu + w).
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

/// Where a submission's compiles and links run: with one job (each student of a class), on the CPU
/// its tests run on, so that the students graded at once keep to their own CPUs (a compile beside a
/// test on one CPU slows every call between its two processes); with more jobs, anywhere.
int buildCpu(const GradeOptions& o) { return o.jobs == 1 ? usableCpu(o.first_cpu) : -1; }

/// Screens and compiles one stage of the submission into work/obj/NN, or into the shared cache
/// (reused only when the stored files are byte for byte these files).
Compiled compileStage(const Kit& kit, const KitStage& st, const fs::path& folder, const fs::path& work,
                      const fs::path& shared, int cpu) {
    Compiled c;
    const fs::path src = work / "src" / st.dir;
    const auto files = copySources(folder, src, &c.problem);
    std::string key = kit.fingerprint + "\n" + c.problem;
    for (const auto& f : files) key += f.filename().string() + "\n" + std::to_string(fs::file_size(f)) + "\n" + readFile(f) + "\n";
    const std::string hash = sha256(key);
    const fs::path obj = shared.empty() ? work / "obj" / st.stage : shared / (st.stage + "-" + hash.substr(0, 16));
    std::lock_guard<std::mutex> lock(folderLock(obj));
    const fs::path cache = obj / "result.json";
    if (fs::exists(cache)) {
        const json j = json::parse(readFile(cache), nullptr, false);
        if (!j.is_discarded() && j.value("hash", "") == hash) {
            c.status = j["status"];
            c.problem = j["problem"];
            for (const auto& o : j["objects"]) c.objects.push_back(o.get<std::string>());
            return c;
        }
    }
    fs::remove_all(obj);
    makeWritableForSandbox(obj);
    std::vector<fs::path> units;
    for (const auto& f : files)
        if (f.extension() == ".cpp") units.push_back(f);
    std::string findings;
    for (const auto& f : files)
        for (const auto& fd : screenSource(readFile(f), st.dir + "/" + f.filename().string()))
            findings += fd.where + ": " + fd.what + "\n";
    if (units.empty()) findings += st.dir + ": no .cpp file\n";
    if (!findings.empty()) {
        c.status = "rejected";
        c.problem = findings + c.problem;
    } else {
        for (const auto& u : units) {
            const fs::path o = obj / (u.stem().string() + ".o");
            SandboxRun r;
            r.argv = {kit.compiler};
            r.argv.insert(r.argv.end(), kit.compile_flags.begin(), kit.compile_flags.end());
            r.argv.insert(r.argv.end(), {"-fdiagnostics-color=never", "-fmax-errors=10", "-I/kit/include"});
            if (usePrecompiledHeader(kit, readFile(u))) r.argv.insert(r.argv.end(), {"-include", "/kit/include/" + kit.precompiled_header});
            for (const auto& s : kit.system_includes) r.argv.insert(r.argv.end(), {"-isystem", s.string()});
            r.argv.insert(r.argv.end(), {"-I/submission/" + st.dir, "-c", "/submission/" + st.dir + "/" + u.filename().string(),
                                         "-o", "/out/" + o.filename().string()});
            r.mounts = {{kit.include_dir, "/kit/include", false}, {src, "/submission/" + st.dir, false}, {obj, "/out", true}};
            r.limits.cpu_seconds = 120;
            r.limits.processes = 16;
            r.timeout_seconds = 180;
            r.cpu = cpu;
            r.log = work / ("compile_" + st.stage + ".log");
            const RunOutcome out = runSandboxed(r);
            if (out.exit_code != 0 || !fs::exists(o)) {
                std::string log = std::regex_replace(readFile(r.log, 64u << 10), std::regex("/submission/"), "");
                if (out.timed_out) log += "the compiler ran longer than " + std::to_string(r.timeout_seconds) + " s\n";
                c.status = "does not compile";
                c.problem = firstLines(log, 12, "") + "\n";
                break;
            }
            c.objects.push_back(o);
        }
    }
    json j = {{"hash", hash}, {"status", c.status}, {"problem", c.problem}, {"objects", json::array()}};
    for (const auto& o : c.objects) j["objects"].push_back(o.string());
    writeFile(cache, j.dump(1));
    return c;
}

std::string unescape(const std::string& s) {
    std::string r;
    for (size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '\\' && i + 1 < s.size()) { r += s[i + 1] == 'n' ? '\n' : s[i + 1]; ++i; }
        else r += s[i];
    }
    return r;
}

/// One test in its own sandboxed process; the verdict comes from the channel (see graded_main.cpp).
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
    std::string failures;
    std::istringstream in(out.report);
    std::string line;
    while (std::getline(in, line)) {
        if (line == "start " + name) started = true;
        else if (line.rfind("fail ", 0) == 0) failures += unescape(line.substr(5)) + "\n";
        else if (line == "end " + name + " passed") ended_passed = true;
    }
    // The CPU limit: the kernel ends a process there with SIGXCPU, or a second later with SIGKILL
    // when it ignores SIGXCPU (nothing else in the sandbox may send SIGKILL: seccomp), the test's
    // process (its exit status) or the submission's (the test's failure names the signal).
    const auto by = [&](int sig) {
        return out.exit_code == 128 + sig || failures.find("signal " + std::to_string(sig) + ", " + ::strsignal(sig)) != std::string::npos;
    };
    const bool cpu_limit = by(SIGXCPU) || by(SIGKILL);
    if (out.timed_out) {
        r.message = "timed out: still running after " + std::to_string(run.timeout_seconds) + " s (waiting forever?)";
    } else if (cpu_limit) {
        r.message = "timed out: used more than " + std::to_string(timeout_s) + " s of CPU time (an endless loop?)";
    } else if (!failures.empty()) {
        r.message = failures;
    } else if (!started || !ended_passed || out.exit_code != 0) {
        std::string tail = readFile(log, 1u << 20);  // the last lines it printed
        if (tail.size() > 600) tail = tail.substr(tail.size() - 600);
        const int code = out.exit_code;
        r.message = (!started ? "the test did not start (the program ended with status " + std::to_string(code) + " before it ran)"
                              : "crashed or ended early (" + (code > 128 ? "signal " + std::to_string(code - 128) + ", " + ::strsignal(code - 128)
                                                                         : "exit status " + std::to_string(code)) + ")") +
                    (tail.empty() ? "" : ":\n" + tail);
    } else {
        r.passed = true;
    }
    fs::remove(log);  // a flood of output must not pile up: the message keeps its tail
    return r;
}

/// One graded stage, ready to run: its test program, the submission process's program ("" none:
/// the self-checks) and the folder with the answers its experiments read.
struct StageRun {
    std::string stage;
    fs::path exe, server, answers;
};

/// Runs the tests of every stage in one queue (the stages in order, each stage's tests in its points
/// file's order), `jobs` processes at a time, worker w pinned to usable CPU first_cpu + w: a worker
/// done with one stage goes on with the next, so no CPU idles while another runs a stage's longest
/// test. After two timeouts in a stage, its remaining tests are not run.
std::vector<StageResult> runStages(const fs::path& points_dir, const std::vector<StageRun>& stages, int timeout_s, int jobs,
                                   int first_cpu, const fs::path& logs) {
    struct Queued {
        size_t stage, index;  // the test's place in out
        TestResult graded;    // its name and points
    };
    std::vector<StageResult> out(stages.size());
    std::vector<std::string> shown(stages.size());  // the answers file as the student knows it
    std::vector<Queued> queue;
    for (size_t s = 0; s < stages.size(); ++s) {
        const json points = loadPoints(points_dir, stages[s].stage);
        out[s].stage = stages[s].stage;
        out[s].title = points["title"];
        const std::string file = fs::path(points["file"].get<std::string>()).filename().string();  // NN_name.points.json
        shown[s] = "exercises/" + file.substr(0, file.find('.')) + "/answers.json";
        for (const TestResult& t : pointsTests(points)) queue.push_back({s, out[s].tests.size(), t}), out[s].tests.emplace_back();
    }
    std::vector<std::atomic<int>> timeouts(stages.size());  // per stage
    fs::create_directories(logs);
    parallelFor(static_cast<int>(queue.size()), jobs, [&](int i, int worker) {
        const Queued& q = queue[static_cast<size_t>(i)];
        const StageRun& run = stages[q.stage];
        TestResult r;
        if (timeouts[q.stage] >= 2) {
            r.name = q.graded.name;
            r.message = "not run: two tests of this stage timed out already";
        } else {
            r = runTest(run.exe, run.server, run.answers, shown[q.stage], q.graded.name, timeout_s, usableCpu(first_cpu + worker),
                        logs / (run.stage + "_" + std::to_string(q.index) + ".log"));
            if (r.message.rfind("timed out", 0) == 0) ++timeouts[q.stage];
        }
        r.max_points = q.graded.max_points;
        r.bonus = q.graded.bonus;
        r.points = r.passed ? r.max_points : 0.0;
        out[q.stage].tests[q.index] = r;
    });
    return out;
}

/// A folder holding a copy of the answers file (the graded experiments' numbers), or an empty
/// folder when there is none: only a regular file of at most 64 KiB is copied, never a link.
fs::path answersFolder(const fs::path& file, const fs::path& folder) {
    fs::remove_all(folder);
    fs::create_directories(folder);
    std::error_code ec;
    if (!file.empty() && fs::is_regular_file(fs::symlink_status(file, ec)) && fs::file_size(file, ec) <= 65536)
        writeFile(folder / "answers.json", readFile(file, 65536));
    makeWritableForSandbox(folder);
    return folder;
}

/// Links `inputs` (sandboxed) into a program called `name`, reused from the cache when the key's
/// SHA-256 is the same; `contents` are objects whose bytes go into the key (the submission's).
/// On failure: empty path, *problem says why (the linker's first lines, object names as sources).
fs::path linkProgram(const Kit& kit, const std::vector<fs::path>& inputs, const std::vector<std::string>& flags,
                     const std::vector<fs::path>& contents, const std::string& name, const GradeOptions& o,
                     std::string* problem) {
    std::string key = kit.fingerprint + name + ";";
    for (const auto& p : inputs) key += stamp(p);  // objects of the shared cache never change in place
    for (const auto& f : flags) key += f + ";";
    for (const auto& p : contents) key += readFile(p, 256u << 20);
    const std::string hash = sha256(key);
    const fs::path bin = o.shared_cache.empty() ? o.work / "bin" : o.shared_cache / ("bin-" + name + "-" + hash.substr(0, 16));
    const fs::path exe = bin / name;
    const fs::path key_file = bin / (name + ".sha256");
    std::lock_guard<std::mutex> lock(folderLock(bin));
    if (fs::exists(exe) && readFile(key_file, 64) == hash) return exe;
    fs::remove(exe);
    makeWritableForSandbox(bin);
    SandboxRun r;
    r.argv = {kit.compiler};
    for (const auto& p : inputs) {
        r.argv.push_back(p.string());
        if (std::find_if(r.mounts.begin(), r.mounts.end(), [&](const Mount& mm) { return mm.host == p; }) == r.mounts.end())
            r.mounts.push_back({p, p, false});
    }
    r.argv.insert(r.argv.end(), flags.begin(), flags.end());
    r.argv.insert(r.argv.end(), {"-o", "/out/" + name});
    r.mounts.push_back({bin, "/out", true});
    r.limits.cpu_seconds = 120;
    r.limits.processes = 16;
    r.limits.file_size = 512LL << 20;
    r.timeout_seconds = 180;
    r.cpu = buildCpu(o);
    r.log = o.work / ("link_" + name + ".log");
    const RunOutcome out = runSandboxed(r);
    if (out.exit_code != 0 || !fs::exists(exe)) {
        std::string log = readFile(r.log, 64u << 10);
        log = std::regex_replace(log, std::regex("[^\n]*/obj/[0-9]+/([A-Za-z0-9_.-]+)\\.o"), "$1.cpp");
        *problem = firstLines(log, 8, "");
        return {};
    }
    writeFile(key_file, hash);
    return exe;
}

}  // namespace

StageResult gradeBinary(const fs::path& points_dir, const std::string& stage, const fs::path& exe, const fs::path& answers,
                        int timeout_seconds, int jobs, const fs::path& tmp) {
    // The suite's integrity: the binary's tests and the points file name the same tests.
    fs::create_directories(tmp);
    SandboxRun list;
    list.argv = {"/grade/test", "--gtest_list_tests"};
    list.mounts = {{fs::absolute(exe), "/grade/test", false}};
    list.log = tmp / ("list_" + stage + ".txt");
    if (runSandboxed(list).exit_code != 0) die(exe.string() + ": (binary): cannot list its tests");
    std::set<std::string> names;
    std::istringstream in(readFile(list.log));
    std::string line, suite;
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        const auto hash = line.find("  #");
        if (hash != std::string::npos) line = line.substr(0, hash);
        if (line[0] != ' ') suite = line;
        else names.insert(suite + line.substr(line.find_first_not_of(' ')));
    }
    const json points = loadPoints(points_dir, stage);
    std::set<std::string> listed;
    for (const auto& t : pointsTests(points)) {
        listed.insert(t.name);
        if (!names.count(t.name))
            die(points["file"].get<std::string>() + (t.bonus ? ": bonus." : ": tests.") + t.name + ": no such test in " + exe.string());
    }
    for (const auto& n : names)
        if (!listed.count(n)) die(points["file"].get<std::string>() + ": tests." + n + ": the graded test has no points");
    const fs::path folder = answersFolder(answers, tmp / ("answers_" + stage));
    return runStages(points_dir, {{stage, fs::absolute(exe), {}, folder}}, timeout_seconds, jobs, 0, tmp).front();
}

std::vector<StageResult> gradeSubmission(const Kit& kit, const fs::path& root, const GradeOptions& o) {
    const auto folders = locateStages(root, kit);
    fs::create_directories(o.work);
    // 1. Screen and compile every stage the submission has (a stage graded alone still needs the
    //    others when they come from the submission).
    std::map<std::string, Compiled> compiled;
    std::mutex m;
    std::vector<const KitStage*> todo;
    for (const auto& st : kit.stages) {
        const bool graded = o.only.empty() || o.only.count(st.stage);
        if (folders.count(st.stage) && (graded || !o.use_reference)) todo.push_back(&st);
    }
    parallelFor(static_cast<int>(todo.size()), o.jobs, [&](int i) {
        const KitStage& st = *todo[i];
        progress(o.progress, "compiling stage " + st.stage + " (" + st.dir + ")");
        Compiled c = compileStage(kit, st, folders.at(st.stage), o.work, o.shared_cache, buildCpu(o));
        std::lock_guard<std::mutex> lock(m);
        compiled[st.stage] = std::move(c);
    });
    // 2. Link each graded stage's two programs.
    std::vector<StageResult> results;
    std::vector<StageRun> runs;
    std::vector<size_t> ran_at;  // where each run's result goes in results
    for (const auto& st : kit.stages) {
        if (!o.only.empty() && !o.only.count(st.stage)) continue;
        if (!folders.count(st.stage)) {
            results.push_back(ungradedStage(kit.points_dir, st.stage, "not submitted", "no folder named " + st.dir + " in the submission"));
            continue;
        }
        const Compiled& c = compiled.at(st.stage);
        if (c.status != "graded") {
            results.push_back(ungradedStage(kit.points_dir, st.stage, c.status, c.problem));
            continue;
        }
        // The test process links the graded tests, our code for the stages that come from us, and
        // proxies for those that come from the submission; the submission process links those.
        std::vector<fs::path> client = kit.main_objects, server = kit.server_objects, submitted;
        client.insert(client.end(), st.tests.begin(), st.tests.end());
        for (const auto& other : kit.stages) {
            const std::vector<fs::path>* use = &other.stub;
            bool theirs = false;
            if (other.stage == st.stage) {
                use = &c.objects;
                theirs = true;
            } else if (o.use_reference && !other.reference.empty()) {
                use = &other.reference;
            } else if (const auto own = compiled.find(other.stage); own != compiled.end() && own->second.status == "graded") {
                use = &own->second.objects;
                theirs = true;
            }
            client.insert(client.end(), theirs ? other.proxy.begin() : use->begin(), theirs ? other.proxy.end() : use->end());
            server.insert(server.end(), use->begin(), use->end());
            if (theirs) submitted.insert(submitted.end(), use->begin(), use->end());
        }
        client.insert(client.end(), kit.client_objects.begin(), kit.client_objects.end());
        client.insert(client.end(), kit.libs.begin(), kit.libs.end());
        server.insert(server.end(), kit.libs.begin(), kit.libs.end());
        std::vector<std::string> server_flags = kit.link_flags;
        server_flags.insert(server_flags.end(), kit.server_link_flags.begin(), kit.server_link_flags.end());
        progress(o.progress, "linking stage " + st.stage);
        std::string problem;
        const fs::path exe = linkProgram(kit, client, kit.link_flags, {}, "grade_" + st.stage, o, &problem);
        // Stages whose submission processes link the same objects share one program (--reference none:
        // all six), so an edit relinks it once.
        std::string objects;
        for (const auto& p : server) objects += p.string() + ";";
        const std::string server_name = "submission_" + sha256(objects).substr(0, 12);
        const fs::path serve = problem.empty() ? linkProgram(kit, server, server_flags, submitted, server_name, o, &problem) : fs::path();
        if (!problem.empty()) {
            results.push_back(ungradedStage(kit.points_dir, st.stage, "does not link", problem));
            continue;
        }
        runs.push_back({st.stage, exe, serve, answersFolder(folders.at(st.stage) / "answers.json", o.work / "answers" / st.stage)});
        ran_at.push_back(results.size());
        results.emplace_back();
    }
    // 3. Run the tests of every linked stage.
    std::string names;
    for (const auto& r : runs) names += " " + r.stage;
    if (!runs.empty()) progress(o.progress, "grading stage" + std::string(runs.size() > 1 ? "s" : "") + names + " ...");
    std::vector<StageResult> ran = runStages(kit.points_dir, runs, o.timeout_seconds, o.jobs, o.first_cpu, o.work / "logs");
    for (size_t i = 0; i < ran.size(); ++i) results[ran_at[i]] = std::move(ran[i]);
    return results;
}

}  // namespace grade
