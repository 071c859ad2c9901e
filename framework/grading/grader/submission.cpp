#include "submission.h"

#include <sys/stat.h>

#include <algorithm>
#include <iostream>
#include <mutex>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "lint.h"
#include "sandbox.h"

namespace grade {

namespace {

/// A file's identity for the cache: path, size, modification time.
std::string stamp(const fs::path& p) {
    struct stat st {};
    if (::stat(p.c_str(), &st) != 0) return p.string() + ":missing;";
    return p.string() + ":" + std::to_string(st.st_size) + ":" + std::to_string(st.st_mtim.tv_sec) + "." + std::to_string(st.st_mtim.tv_nsec) + ";";
}

void progress(bool on, const std::string& line) {
    static std::mutex print;
    std::lock_guard<std::mutex> lock(print);
    if (on) std::cerr << line << "\n";
}

}  // namespace

Kit loadKit(const fs::path& file) {
    const std::string text = readFile(file);
    json j = json::parse(text, nullptr, false);
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
        for (const auto& s : j.at("stages")) k.stages.push_back({s.at("stage"), s.at("dir"), s.at("tests"), s.at("reference"), s.at("stub"), s.at("proxy")});
    } catch (const std::exception& e) {
        die(file.string() + ": (grading kit): " + e.what() + "; rebuild (./lab build)");
    }
    std::string fp = text + stamp(fs::canonical("/proc/self/exe"));  // a new grader regrades
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
    const auto unreadable = [&] { return std::runtime_error(root.string() + ": (folder): cannot read it: " + ec.message()); };
    fs::recursive_directory_iterator it(root, fs::directory_options::none, ec), end;
    for (; it != end; it.increment(ec)) {
        if (ec) throw unreadable();
        const std::string name = it->path().filename().string();
        if (!it->is_directory(ec) || it->is_symlink(ec)) continue;
        if (name.empty() || name[0] == '.' || name == "__MACOSX" || it.depth() > 5) { it.disable_recursion_pending(); continue; }
        for (const auto& st : kit.stages)
            if (name == st.dir) found[st.stage].push_back(it->path()), it.disable_recursion_pending();
    }
    if (ec) throw unreadable();
    std::map<std::string, fs::path> out;
    std::string names;
    for (const auto& [stage, dirs] : found) {
        for (const auto& d : dirs) names += (names.empty() ? "" : ", ") + fs::relative(d, root).string();
        if (dirs.size() > 1)
            throw std::runtime_error(root.string() + ": (layout): " + std::to_string(dirs.size()) + " folders named " + dirs[0].filename().string() +
                                     " (" + names + "); keep one");
        out[stage] = dirs[0], names.clear();
    }
    for (const auto& st : kit.stages) names += (names.empty() ? "" : ", ") + st.dir;
    if (out.empty()) throw std::runtime_error(root.string() + ": (layout): no stage folder found (expected folders named " + names + ")");
    return out;
}

namespace {

/// A stage compiled: its status and problem, and the objects when it compiled.
struct Compiled {
    Status status = Status::graded;
    std::string problem;
    std::vector<fs::path> objects;
};

/// The stage's files copied into `to`: regular .cpp/.h/.hpp files, no links, at most 512 KiB each.
std::vector<fs::path> copySources(const fs::path& from, const fs::path& to, std::string* problem) {
    fs::remove_all(to);
    fs::create_directories(to);
    std::vector<fs::path> out;
    for (const auto& e : fs::directory_iterator(from)) {
        const std::string name = e.path().filename().string(), ext = e.path().extension().string();
        if (ext != ".cpp" && ext != ".h" && ext != ".hpp") continue;
        if (e.is_symlink() || !e.is_regular_file()) *problem += name + ": a link or special file, not read\n";
        else if (!std::regex_match(name, std::regex("[A-Za-z0-9_.-]+"))) *problem += name + ": file names may use letters, digits, _ . - only\n";
        else if (e.file_size() > (512u << 10)) *problem += name + ": larger than 512 KiB\n";
        else fs::copy_file(e.path(), to / name, fs::copy_options::overwrite_existing), out.push_back(to / name);
    }
    std::sort(out.begin(), out.end());
    return out;
}

/// Whether a file is compiled with the kit's precompiled header: not when it defines a macro before
/// its first #include (EIGEN_... settings, say), which the header, read first, would not see.
bool usePrecompiledHeader(const Kit& kit, const std::string& source) {
    static const std::regex directive("^[ \t]*#[ \t]*(include|define|undef)\\b");
    std::istringstream in(source);
    std::smatch m;
    for (std::string line; std::getline(in, line);)
        if (std::regex_search(line, m, directive)) return m[1] == "include" && !kit.precompiled_header.empty();
    return !kit.precompiled_header.empty();
}

/// A compile or link run's limits, and its CPU: with one job (each student of a class), the CPU its
/// tests run on, so that the students graded at once keep to their own CPUs (a compile beside a test
/// on one CPU slows every call between its two processes); with more jobs, anywhere.
SandboxRun buildRun(const GradeOptions& o, const fs::path& log) {
    SandboxRun r;
    r.limits.cpu_seconds = 120;
    r.limits.processes = 16;
    r.timeout_seconds = 180;
    r.cpu = o.jobs == 1 ? usableCpu(o.first_cpu) : -1;
    r.log = log;
    return r;
}

/// Lints and compiles one stage of the submission (sandboxed, each .cpp on its own) into work/obj/NN,
/// or the shared cache; reused while the kit and the stage's file names and bytes are the same.
Compiled compileStage(const Kit& kit, const KitStage& st, const fs::path& folder, const GradeOptions& o) {
    std::string copied;  // what copying left out
    const fs::path src = o.work / "src" / st.dir;
    const auto files = copySources(folder, src, &copied);
    std::string key = kit.fingerprint + "\n" + copied;
    for (const auto& f : files) key += f.filename().string() + "\n" + std::to_string(fs::file_size(f)) + "\n" + readFile(f) + "\n";
    const std::string hash = sha256(key);
    const fs::path obj = o.shared_cache.empty() ? o.work / "obj" / st.stage : o.shared_cache / (st.stage + "-" + hash.substr(0, 16));
    const json c = cached(obj / "result.json", hash, [&] {
        fs::remove_all(obj);
        makeWritableForSandbox(obj);
        std::string findings;
        std::vector<fs::path> units, objects;
        for (const auto& f : files) {
            if (f.extension() == ".cpp") units.push_back(f);
            for (const auto& fd : weakened("lint") ? std::vector<Finding>{} : lintSource(readFile(f), st.dir + "/" + f.filename().string()))
                findings += fd.where + ": " + fd.what + "\n";
        }
        if (units.empty()) findings += st.dir + ": no .cpp file\n";
        if (!findings.empty()) return json{{"status", Status::rejected}, {"problem", findings + copied}};
        for (const auto& u : units) {
            SandboxRun r = buildRun(o, o.work / ("compile_" + st.stage + ".log"));
            r.argv = {kit.compiler};
            r.argv.insert(r.argv.end(), kit.compile_flags.begin(), kit.compile_flags.end());
            r.argv.insert(r.argv.end(), {"-fdiagnostics-color=never", "-fmax-errors=10", "-I/kit/include"});
            if (usePrecompiledHeader(kit, readFile(u))) r.argv.insert(r.argv.end(), {"-include", "/kit/include/" + kit.precompiled_header});
            for (const auto& s : kit.system_includes) r.argv.insert(r.argv.end(), {"-isystem", s.string()});
            r.argv.insert(r.argv.end(), {"-I/submission/" + st.dir, "-c", "/submission/" + st.dir + "/" + u.filename().string(), "-o",
                                         "/out/" + u.stem().string() + ".o"});
            r.mounts = {{kit.include_dir, "/kit/include", false}, {src, "/submission/" + st.dir, false}, {obj, "/out", true}};
            if (weakened("compile")) {  // test tool only: the compiler sees the instructor's tree, as the tree's own build does
                const fs::path tree = kit.points_dir.parent_path(), build = kit.file.parent_path().parent_path();
                r.argv.insert(r.argv.end() - 5, {"-I" + (tree / "framework/include").string(), "-I" + (tree / "tests").string(),
                                                 "-I" + (build / "tests/generated").string()});
                r.mounts.insert(r.mounts.end(), {{tree, tree, false}, {build / "tests/generated", build / "tests/generated", false}});
            }
            const RunOutcome out = runSandboxed(r);
            if (out.exit_code != 0 || !fs::exists(obj / (u.stem().string() + ".o"))) {
                std::string log = std::regex_replace(readFile(r.log, 64u << 10), std::regex("/submission/"), "");
                if (out.timed_out) log += "the compiler ran longer than " + std::to_string(r.timeout_seconds) + " s\n";
                else if (out.exit_code > 128) log += "the compiler was ended by signal " + std::to_string(out.exit_code - 128) + "\n";
                return json{{"status", Status::does_not_compile}, {"problem", firstLines(log, 12, "") + "\n"}};
            }
            objects.push_back(obj / (u.stem().string() + ".o"));
        }
        return json{{"status", Status::graded}, {"problem", copied}, {"objects", objects}};
    });
    return {c["status"], c["problem"], c.value("objects", std::vector<fs::path>{})};
}

/// Links `inputs` (sandboxed) into a program called `name`, reused from the cache while the inputs,
/// the flags and the bytes of `contents` (the submission's objects) are the same. On failure: empty
/// path, *problem says why (the linker's first lines, object names as sources).
fs::path linkProgram(const Kit& kit, const std::vector<fs::path>& inputs, const std::vector<std::string>& flags,
                     const std::vector<fs::path>& contents, const std::string& name, const GradeOptions& o, std::string* problem) {
    std::string key = kit.fingerprint + name + ";";
    for (const auto& p : inputs) key += stamp(p);  // objects of the shared cache never change in place
    for (const auto& f : flags) key += f + ";";
    for (const auto& p : contents) key += readFile(p, 256u << 20);
    const std::string hash = sha256(key);
    const fs::path bin = o.shared_cache.empty() ? o.work / "bin" : o.shared_cache / ("bin-" + name + "-" + hash.substr(0, 16)), exe = bin / name;
    if (!fs::exists(exe)) fs::remove(bin / (name + ".json"));
    *problem = cached(bin / (name + ".json"), hash, [&] {
        fs::remove(exe);
        makeWritableForSandbox(bin);
        SandboxRun r = buildRun(o, o.work / ("link_" + name + ".log"));
        r.argv = {kit.compiler};
        for (const auto& p : inputs) {
            r.argv.push_back(p.string());
            if (std::none_of(r.mounts.begin(), r.mounts.end(), [&](const Mount& m) { return m.host == p; })) r.mounts.push_back({p, p, false});
        }
        r.argv.insert(r.argv.end(), flags.begin(), flags.end());
        r.argv.insert(r.argv.end(), {"-o", "/out/" + name});
        r.mounts.push_back({bin, "/out", true});
        r.limits.file_size = 512LL << 20;
        if (runSandboxed(r).exit_code == 0 && fs::exists(exe)) return json("");
        const std::string log = std::regex_replace(readFile(r.log, 64u << 10), std::regex("[^\n]*/obj/[0-9]+/([A-Za-z0-9_.-]+)\\.o"), "$1.cpp");
        return json(firstLines(log, 8, "") + "\n");
    }).get<std::string>();
    if (!problem->empty()) fs::remove(bin / (name + ".json"));  // a failed link is tried again
    return problem->empty() ? exe : fs::path();
}

}  // namespace

std::vector<StageResult> gradeSubmission(const Kit& kit, const fs::path& root, const GradeOptions& o) {
    const auto folders = locateStages(root, kit);
    fs::create_directories(o.work);
    const bool reference = o.use_reference && !weakened("reference");
    // 1. Lint and compile every stage the submission has (a stage graded alone still needs the
    //    others when they come from the submission).
    std::map<std::string, Compiled> compiled;
    std::mutex m;
    std::vector<const KitStage*> todo;
    for (const auto& st : kit.stages)
        if (folders.count(st.stage) && (o.only.empty() || o.only.count(st.stage) || !reference)) todo.push_back(&st);
    parallelFor(static_cast<int>(todo.size()), o.jobs, [&](int i) {
        const KitStage& st = *todo[static_cast<size_t>(i)];
        progress(o.progress, "compiling stage " + st.stage + " (" + st.dir + ")");
        Compiled c = compileStage(kit, st, folders.at(st.stage), o);
        std::lock_guard<std::mutex> lock(m);
        compiled[st.stage] = std::move(c);
    });
    // 2. Link each graded stage's two programs. The test process: the graded tests, the reference for
    //    the stages that come from it, proxies for those that come from the submission; the submission
    //    process: the submission's objects of those stages, the same choice for the others, its main().
    //    (Test tool only: `process` and `channel` link the submission's objects into the test process.)
    const bool in_process = weakened("process") || weakened("channel");
    std::vector<StageResult> results;
    std::vector<StageRun> runs;
    std::vector<size_t> ran_at;  // where each run's result goes in results
    for (const auto& st : kit.stages) {
        if (!o.only.empty() && !o.only.count(st.stage)) continue;
        const auto own = compiled.find(st.stage);
        if (!folders.count(st.stage) || own->second.status != Status::graded) {
            results.push_back(folders.count(st.stage) ? ungradedStage(kit.points_dir, st.stage, own->second.status, own->second.problem)
                                                      : ungradedStage(kit.points_dir, st.stage, Status::not_submitted,
                                                                      "no folder named " + st.dir + " in the submission"));
            continue;
        }
        std::vector<fs::path> client = kit.main_objects, server = kit.server_objects, submitted;
#ifdef CLOTHLAB_GRADER_TEST_SWITCHES  // test tool only: test-only objects in place of the kit's (tests/sandbox/CMakeLists.txt)
        if (weakened("dumpable")) client = {CLOTHLAB_TEST_DUMPABLE_MAIN};
        if (weakened("channel")) client = {};  // GoogleTest's own main (libs below)
        if (weakened("seccomp")) server.front() = CLOTHLAB_TEST_UNCONFINED_SERVER;
#endif
        client.insert(client.end(), st.tests.begin(), st.tests.end());
        for (const auto& other : kit.stages) {
            const auto theirs = compiled.find(other.stage);
            const bool submission = other.stage == st.stage || ((!reference || other.reference.empty()) && theirs != compiled.end() &&
                                                                 theirs->second.status == Status::graded);
            const auto& use = submission ? theirs->second.objects : reference && !other.reference.empty() ? other.reference : other.stub;
            const auto& local = submission && !in_process ? other.proxy : use;
            client.insert(client.end(), local.begin(), local.end());
            server.insert(server.end(), use.begin(), use.end());
            if (submission) submitted.insert(submitted.end(), use.begin(), use.end());
        }
#ifdef CLOTHLAB_GRADER_TEST_SWITCHES
        if (weakened("channel")) client.push_back(CLOTHLAB_TEST_GTEST_MAIN);  // after the objects: a main() of theirs wins
#endif
        if (!in_process) client.insert(client.end(), kit.client_objects.begin(), kit.client_objects.end());
        client.insert(client.end(), kit.libs.begin(), kit.libs.end());
        server.insert(server.end(), kit.libs.begin(), kit.libs.end());
        std::vector<std::string> server_flags = kit.link_flags;
        server_flags.insert(server_flags.end(), kit.server_link_flags.begin(), kit.server_link_flags.end());
        progress(o.progress, "linking stage " + st.stage);
        std::string problem;
        const fs::path exe = linkProgram(kit, client, kit.link_flags, in_process ? submitted : std::vector<fs::path>{}, "grade_" + st.stage, o, &problem);
        // Stages whose submission processes link the same objects share one program (--reference none:
        // all seven), so an edit relinks it once.
        std::string objects;
        for (const auto& p : server) objects += p.string() + ";";
        const fs::path serve = problem.empty() && !in_process
                                   ? linkProgram(kit, server, server_flags, submitted, "submission_" + sha256(objects).substr(0, 12), o, &problem)
                                   : fs::path();
        if (!problem.empty()) {
            results.push_back(ungradedStage(kit.points_dir, st.stage, Status::does_not_link, problem));
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
