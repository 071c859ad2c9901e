#include "class_grading.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <mutex>
#include <regex>
#include <stdexcept>

#include "report.h"
#include "sandbox.h"

namespace grade {

namespace {

/// A student's submission: the folder or archive, and the student's name (its name without extension).
struct Entry {
    std::string name;
    fs::path path;
    std::string archive;  ///< "", "zip" or "tar"
};

std::vector<Entry> listEntries(const fs::path& dir) {
    std::vector<Entry> out;
    for (const auto& e : fs::directory_iterator(dir)) {
        const std::string file = e.path().filename().string();
        std::smatch m;
        if (file.empty() || file[0] == '.' || file == "__MACOSX") continue;
        if (e.is_directory() && !e.is_symlink()) out.push_back({file, e.path(), ""});
        else if (e.is_regular_file() && std::regex_match(file, m, std::regex("(.+)\\.(?:(zip)|tar\\.gz|tgz|tar|tar\\.xz)", std::regex::icase)))
            out.push_back({m[1], e.path(), m[2].matched ? "zip" : "tar"});  // any case: .zip, .ZIP, .Zip
        else std::cerr << "ignored: " << file << " (neither a folder nor a .zip/.tar.gz/.tgz/.tar)\n";
    }
    std::sort(out.begin(), out.end(), [](const Entry& a, const Entry& b) { return a.name < b.name; });
    return out;
}

/// A name for the student's files that no other entry shares: names that clash once made safe
/// ("bob smith", "bob_smith") or appear twice (alice/, alice.zip) get a hash of their file name appended.
std::string fileName(const Entry& e, const std::vector<Entry>& all) {
    const auto safe = [](const std::string& s) {
        const std::string r = std::regex_replace(s, std::regex("[^A-Za-z0-9_.@-]"), "_");
        return r.empty() || r[0] == '.' ? "_" + r : r;
    };
    const long same = std::count_if(all.begin(), all.end(), [&](const Entry& o) { return safe(o.name) == safe(e.name); });
    const bool apart = (same > 1 || safe(e.name) != e.name) && !weakened("names");  // test tool only: the names that clashed
    return safe(e.name) + (apart ? "-" + sha256(e.path.filename().string()).substr(0, 8) : "");
}

/// Content hash of a submission: every regular file's relative path and bytes (links are not followed).
std::string contentHash(const Entry& e, const std::string& salt) {
    if (!e.archive.empty()) return sha256(salt + readFile(e.path, 256u << 20));
    std::vector<fs::path> files;
    forEachEntry(e.path, true, [&](const fs::path& f, const struct stat& st) {
        if (S_ISREG(st.st_mode)) files.push_back(f);
    });
    std::sort(files.begin(), files.end());
    std::string all = salt;
    for (const auto& f : files) {
        const std::string bytes = readFile(f, 16u << 20);
        all += "\n" + fs::relative(f, e.path).string() + "\n" + std::to_string(bytes.size()) + "\n" + bytes;
    }
    return sha256(all);
}

/// Unpacks an archive (sandboxed) into `to`.
void unpack(const Entry& e, const fs::path& to, const fs::path& log) {
    fs::remove_all(to);
    makeWritableForSandbox(to);
    SandboxRun r;
    const std::string in = "/in/" + std::string(e.archive == "zip" ? "submission.zip" : "submission.tar");
    if (e.archive == "zip") r.argv = {"unzip", "-qq", "-o", in, "-d", "/out"};
    else r.argv = {"tar", "-xf", in, "-C", "/out", "--no-same-owner", "--no-same-permissions"};
    r.mounts = {{fs::absolute(e.path), in, false}, {to, "/out", true}};
    r.limits.processes = 8;
    r.timeout_seconds = 60;
    r.log = log;
    if (runSandboxed(r).exit_code != 0)
        throw std::runtime_error(e.path.filename().string() + ": (archive): cannot unpack it (" + firstLines(readFile(log, 4096), 2, " ") + ")");
}

/// Copies a submission's write-ups (NN_name/writeup.md, and a report NN_name.html committed under
/// out/report/ or report/) into `to` (NN_name/writeup.md, NN_name.html): regular files only, no
/// links, up to 16 MiB each. Returns how many it copied.
int collectWriteups(const fs::path& root, const fs::path& to) {
    std::error_code ec;
    fs::remove_all(to, ec);
    int n = 0;
    forEachEntry(root, true, [&](const fs::path& f, const struct stat& st) {
        if (!S_ISREG(st.st_mode) || st.st_size > (16 << 20)) return;
        const std::string file = f.filename().string(), dir = f.parent_path().filename().string();
        const bool writeup = file == "writeup.md" && std::regex_match(dir, std::regex("[0-9][0-9]_.+"));
        if (!writeup && !(dir == "report" && std::regex_match(file, std::regex("[0-9][0-9]_.+\\.html")))) return;
        const fs::path dest = to / (writeup ? dir : "") / file;
        std::error_code copied;
        fs::create_directories(dest.parent_path(), copied);
        n += fs::copy_file(f, dest, fs::copy_options::overwrite_existing, copied) && !copied;
    });
    return n;
}

/// Grades one student in `dir` (the results cached there, with their hash): its row of the gradebook,
/// and whether it was graded now (not taken from the cache). Its layout's error costs it every stage.
std::pair<GradebookRow, bool> gradeStudent(const Kit& kit, const ClassOptions& o, const Entry& e, const fs::path& dir, int worker) {
    const std::string salt = kit.fingerprint + (o.grade.use_reference ? "ref" : "own");
    bool graded = false;
    const json cache = cached(dir / "result.json", contentHash(e, salt), [&] {
        graded = true;
        std::vector<StageResult> stages;
        std::string status;
        const fs::path root = e.archive.empty() ? e.path : dir / "unpacked";
        try {
            fs::create_directories(dir);
            if (!e.archive.empty()) unpack(e, root, dir / "unpack.log");
            GradeOptions g = o.grade;
            g.work = dir / "build", g.shared_cache = o.out / ".work" / ".shared", g.jobs = 1, g.progress = false;
            g.first_cpu = worker;  // the students graded at once test on different CPUs
            stages = gradeSubmission(kit, root, g);
            status = statusLine(stages);
        } catch (const std::exception& err) {  // this student's layout: zero points, the reason in the gradebook
            std::string what = err.what();
            if (what.rfind(root.string(), 0) == 0) what = fs::relative(e.path, o.class_dir).string() + what.substr(root.string().size());
            status = "error: " + what;
            stages.clear();
            for (const auto& st : kit.stages) stages.push_back(ungradedStage(kit.points_dir, st.stage, Status::not_graded, what));
        }
        return json{{"status", status}, {"results", resultsJson(stages)}};
    });
    return {{e.name, cache["status"], resultsFromJson(cache["results"])}, graded};
}

}  // namespace

void gradeClass(const Kit& kit, const ClassOptions& o) {
    if (!fs::is_directory(o.class_dir)) die(o.class_dir.string() + ": (folder): the class folder does not exist");
    const auto entries = listEntries(o.class_dir);
    if (entries.empty()) die(o.class_dir.string() + ": (folder): no student folder or archive in it");
    for (const char* dir : {"feedback", "junit", ".work"}) fs::create_directories(o.out / dir);
    std::vector<GradebookRow> rows(entries.size());
    std::mutex print;
    int done = 0, with_writeups = 0;
    const bool tty = ::isatty(2);
    parallelFor(static_cast<int>(entries.size()), o.jobs, [&](int i, int worker) {
        const Entry& e = entries[static_cast<size_t>(i)];
        const std::string name = fileName(e, entries);
        const fs::path dir = o.out / ".work" / name;
        auto [row, graded] = gradeStudent(kit, o, e, dir, worker);
        json feedback = resultsJson(row.stages);
        feedback["student"] = e.name, feedback["status"] = row.status;
        writeFile(o.out / "feedback" / (name + ".json"), feedback.dump(2) + "\n");
        writeJunit(o.out / "junit" / (name + ".xml"), row.stages, e.name);
        const int writeups = collectWriteups(e.archive.empty() ? e.path : dir / "unpacked", o.out / "writeups" / name);
        const Totals t = totals(row.stages);
        std::lock_guard<std::mutex> lock(print);
        with_writeups += writeups > 0;
        const int width = 30, filled = static_cast<int>(width * ++done / entries.size());
        char line[512];
        std::snprintf(line, sizeof line, "[%s%s] %d/%zu  %s: %g / %g%s%s", std::string(filled, '#').c_str(), std::string(width - filled, '.').c_str(),
                      done, entries.size(), e.name.c_str(), t.points, t.max_points, graded ? "" : " (unchanged, not regraded)",
                      row.status == "ok" ? "" : ("  [" + row.status.substr(0, 120) + "]").c_str());
        std::cerr << (tty ? "\r\033[K" : "") << line << (tty && done < static_cast<int>(entries.size()) ? "" : "\n") << std::flush;
        rows[static_cast<size_t>(i)] = std::move(row);
    });
    if (tty) std::cerr << "\n";
    std::vector<std::string> stages;
    for (const auto& st : kit.stages) stages.push_back(st.stage);
    writeGradebooks(o.out, stages, o.grade.only, kit.points_dir, rows);
    std::printf("graded %zu submissions: %s (moodle.csv and canvas.csv for import, feedback/NAME.json and junit/NAME.xml beside it; "
                "write-ups of %d in writeups/NAME/)\n",
                entries.size(), (o.out / "gradebook.csv").c_str(), with_writeups);
}

}  // namespace grade
