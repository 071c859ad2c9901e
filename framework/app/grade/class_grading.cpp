#include "class_grading.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <mutex>
#include <regex>
#include <stdexcept>

#include "report.h"
#include "sandbox.h"

namespace grade {

namespace {

struct Entry {
    std::string name;  ///< the student (folder or archive name without extension)
    fs::path path;
    std::string archive;  ///< "", "zip" or "tar"
};

std::string safeName(const std::string& s) {
    std::string r = std::regex_replace(s, std::regex("[^A-Za-z0-9_.@-]"), "_");
    return r.empty() || r[0] == '.' ? "_" + r : r;
}

std::vector<Entry> listEntries(const fs::path& dir) {
    std::vector<Entry> out;
    for (const auto& e : fs::directory_iterator(dir)) {
        const std::string file = e.path().filename().string();
        if (file.empty() || file[0] == '.' || file == "__MACOSX") continue;
        if (e.is_directory() && !e.is_symlink()) { out.push_back({file, e.path(), ""}); continue; }
        std::smatch m;
        if (e.is_regular_file() && std::regex_match(file, m, std::regex("(.+)\\.(zip|tar\\.gz|tgz|tar|tar\\.xz)", std::regex::icase)))
            out.push_back({m[1], e.path(), m[2].str() == "zip" || m[2].str() == "ZIP" ? "zip" : "tar"});
        else
            std::cerr << "ignored: " << file << " (neither a folder nor a .zip/.tar.gz/.tgz/.tar)\n";
    }
    std::sort(out.begin(), out.end(), [](const Entry& a, const Entry& b) { return a.name < b.name; });
    return out;
}

/// Content hash of a submission: every regular file's relative path and bytes (links are not followed).
std::string contentHash(const Entry& e, const std::string& salt) {
    if (!e.archive.empty()) return sha256(salt + readFile(e.path, 256u << 20));
    std::vector<fs::path> files;
    std::error_code ec;
    for (fs::recursive_directory_iterator it(e.path, ec), end; it != end; it.increment(ec)) {
        if (ec) break;
        if (it->is_regular_file(ec) && !it->is_symlink(ec)) files.push_back(it->path());
    }
    std::sort(files.begin(), files.end());
    std::string all = salt;
    for (const auto& f : files) {
        const std::string bytes = readFile(f, 16u << 20);
        all += "\n" + fs::relative(f, e.path).string() + "\n" + std::to_string(bytes.size()) + "\n" + bytes;
    }
    return sha256(all);
}

/// Unpacks an archive (sandboxed, as nobody) into `to`.
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
    const RunOutcome out = runSandboxed(r);
    if (out.exit_code != 0)
        throw std::runtime_error(e.path.filename().string() + ": (archive): cannot unpack it (" +
                                 firstLines(readFile(log, 4096), 2, " ") + ")");
}

/// Copies a submission's write-ups (NN_name/writeup.md, and a report NN_name.html committed under
/// out/report/ or report/) into `to` (NN_name/writeup.md, NN_name.html): regular files only, no
/// links, up to 16 MiB each. Returns how many it copied.
int collectWriteups(const fs::path& root, const fs::path& to) {
    std::error_code ec;
    fs::remove_all(to, ec);
    int n = 0;
    for (fs::recursive_directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec)) {
        if (it->is_symlink(ec) || !it->is_regular_file(ec) || it->file_size(ec) > (16u << 20)) continue;
        const std::string file = it->path().filename().string(), dir = it->path().parent_path().filename().string();
        const bool writeup = file == "writeup.md" && std::regex_match(dir, std::regex("[0-9][0-9]_.+"));
        if (!writeup && !(dir == "report" && std::regex_match(file, std::regex("[0-9][0-9]_.+\\.html")))) continue;
        const fs::path dest = to / (writeup ? dir : "") / file;
        std::error_code copied;
        fs::create_directories(dest.parent_path(), copied);
        n += fs::copy_file(it->path(), dest, fs::copy_options::overwrite_existing, copied) && !copied;
    }
    return n;
}

}  // namespace

std::vector<StageResult> resultsFromJson(const json& j) {
    std::vector<StageResult> out;
    for (const auto& s : j.at("stages")) {
        StageResult st;
        st.stage = s.at("stage");
        st.title = s.at("title");
        st.status = s.at("status");
        st.problem = s.at("problem");
        for (const auto& t : s.at("tests"))
            st.tests.push_back({t.at("name"), t.at("passed"), t.at("points"), t.at("max_points"), t.at("message"),
                                t.value("bonus", false)});
        out.push_back(st);
    }
    return out;
}

int gradeClass(const Kit& kit, const ClassOptions& o) {
    if (!fs::is_directory(o.class_dir)) die(o.class_dir.string() + ": (folder): the class folder does not exist");
    const auto entries = listEntries(o.class_dir);
    if (entries.empty()) die(o.class_dir.string() + ": (folder): no student folder or archive in it");
    fs::create_directories(o.out / "feedback");
    fs::create_directories(o.out / "junit");
    const fs::path work = o.out / ".work";
    fs::create_directories(work);

    struct Row {
        std::vector<StageResult> stages;
        std::string status;
        bool cached = false;
    };
    std::vector<Row> rows(entries.size());
    std::mutex print;
    int done = 0, with_writeups = 0;
    const bool tty = ::isatty(2);
    const std::string salt = kit.fingerprint + (o.grade.use_reference ? "ref" : "own");
    parallelFor(static_cast<int>(entries.size()), o.jobs, [&](int i, int worker) {
        const Entry& e = entries[i];
        // A name for files that no other entry shares: names that clash once made safe ("bob smith",
        // "bob_smith") or appear twice (alice/, alice.zip) get a hash of their file name appended.
        std::string name = safeName(e.name);
        int same = 0;
        for (const auto& other : entries) same += safeName(other.name) == name;
        if (same > 1 || name != e.name) name += "-" + sha256(e.path.filename().string()).substr(0, 8);
        const fs::path dir = work / name;
        Row row;
        std::string hash;
        try {
            hash = contentHash(e, salt);
            const fs::path cache = dir / "result.json";
            const json old = fs::exists(cache) ? json::parse(readFile(cache), nullptr, false) : json();
            if (old.is_object() && old.value("hash", "") == hash) {
                row.stages = resultsFromJson(old.at("results"));
                row.status = old.value("status", "ok");
                row.cached = true;
            } else {
                fs::create_directories(dir);
                fs::path root = e.path;
                if (!e.archive.empty()) {
                    root = dir / "unpacked";
                    unpack(e, root, dir / "unpack.log");
                }
                GradeOptions g = o.grade;
                g.work = dir / "build";
                g.shared_cache = work / ".shared";
                g.jobs = 1;
                g.first_cpu = worker;  // the students graded at once test on different CPUs
                g.progress = false;
                try {
                    row.stages = gradeSubmission(kit, root, g);
                    row.status = statusLine(row.stages);
                } catch (const std::runtime_error& err) {
                    std::string what = err.what();
                    if (what.rfind(root.string(), 0) == 0) what = what.substr(root.string().size());
                    throw std::runtime_error(fs::relative(e.path, o.class_dir).string() + what);
                }
            }
        } catch (const std::exception& err) {  // this student's layout: zero points, the reason in the gradebook
            row.status = std::string("error: ") + err.what();
            row.stages.clear();
            for (const auto& st : kit.stages) row.stages.push_back(ungradedStage(kit.points_dir, st.stage, "not graded", err.what()));
        }
        if (!row.cached && !hash.empty()) {  // the verdict, layout errors included, until the files change
            fs::create_directories(dir);
            writeFile(dir / "result.json", json{{"hash", hash}, {"status", row.status}, {"results", resultsJson(row.stages)}}.dump(1));
        }
        json fb = resultsJson(row.stages);
        fb["student"] = e.name;
        fb["status"] = row.status;
        writeFile(o.out / "feedback" / (name + ".json"), fb.dump(2) + "\n");
        writeJunit(o.out / "junit" / (name + ".xml"), row.stages, e.name);
        const int writeups = collectWriteups(e.archive.empty() ? e.path : dir / "unpacked", o.out / "writeups" / name);
        double pts = 0, max = 0;
        for (const auto& s : row.stages) pts += s.points(), max += s.max_points();
        std::lock_guard<std::mutex> lock(print);
        ++done;
        with_writeups += writeups > 0;
        const int width = 30, filled = static_cast<int>(width * done / entries.size());
        char line[512];
        std::snprintf(line, sizeof line, "[%s%s] %d/%zu  %s: %g / %g%s%s", std::string(filled, '#').c_str(),
                      std::string(width - filled, '.').c_str(), done, entries.size(), e.name.c_str(), pts, max,
                      row.cached ? " (unchanged, not regraded)" : "", row.status == "ok" ? "" : ("  [" + row.status.substr(0, 120) + "]").c_str());
        std::cerr << (tty ? "\r\033[K" : "") << line << (tty && done < static_cast<int>(entries.size()) ? "" : "\n") << std::flush;
        rows[i] = std::move(row);
    });
    if (tty) std::cerr << "\n";

    std::ofstream csv(o.out / "gradebook.csv");
    csv << "student";
    for (const auto& st : kit.stages) csv << "," << st.stage;
    csv << ",total,max,status,bonus\n";
    for (size_t i = 0; i < entries.size(); ++i) {
        double pts = 0, max = 0, bonus = 0;
        csv << csvField(entries[i].name);
        for (const auto& st : kit.stages) csv << "," << csvNumber(stagePoints(rows[i].stages, st.stage));
        for (const auto& s : rows[i].stages) pts += s.points(), max += s.max_points(), bonus += s.bonus();
        csv << "," << csvNumber(pts) << "," << csvNumber(max) << "," << csvField(rows[i].status) << "," << csvNumber(bonus) << "\n";
    }
    csv.close();
    // The same points in the import formats of Moodle and Canvas: one column per stage (grade item or
    // assignment), the student identified by the folder or archive name. With --only just those stages,
    // so that an import does not overwrite the other stages' grades with zeros.
    std::vector<GradeItem> items;
    for (const auto& st : kit.stages) {
        if (!o.grade.only.empty() && !o.grade.only.count(st.stage)) continue;
        const json points = loadPoints(kit.points_dir, st.stage);
        double max = 0;
        for (const auto& [test, p] : points["tests"].items()) max += p.get<double>();
        items.push_back({st.stage, "clothlab " + st.stage + " " + points["title"].get<std::string>(), max});
    }
    std::vector<GradebookRow> book;
    for (size_t i = 0; i < entries.size(); ++i) book.push_back({entries[i].name, rows[i].stages});
    writeFile(o.out / "moodle.csv", moodleCsv(items, book));
    writeFile(o.out / "canvas.csv", canvasCsv(items, book));
    std::printf("graded %zu submissions: %s (moodle.csv and canvas.csv for import, feedback/NAME.json and junit/NAME.xml beside it; "
                "write-ups of %d in writeups/NAME/)\n",
                entries.size(), (o.out / "gradebook.csv").c_str(), with_writeups);
    return static_cast<int>(entries.size());
}

}  // namespace grade
