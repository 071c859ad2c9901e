#include "common.h"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>

#include <openssl/evp.h>

namespace grade {

static const char* const kStatusNames[] = {"graded", "not submitted", "rejected", "does not compile", "does not link", "not graded"};

std::string statusName(Status s) { return kStatusNames[static_cast<int>(s)]; }

Status statusNamed(const std::string& name) {
    for (int s = 0; s < 6; ++s)
        if (name == kStatusNames[s]) return static_cast<Status>(s);
    throw std::runtime_error("no such stage status: " + name);
}

Totals totals(const std::vector<StageResult>& stages) {
    Totals t;
    for (const auto& s : stages)
        for (const auto& r : s.tests) {
            (r.bonus ? t.bonus : t.points) += r.points;
            (r.bonus ? t.max_bonus : t.max_points) += r.max_points;
            (r.bonus ? t.bonus_passed : t.passed) += r.passed;
            ++(r.bonus ? t.bonus_tests : t.tests);
        }
    return t;
}

void die(const std::string& msg) {
    std::cerr << "error: " << msg << "\n";
    std::exit(1);
}

std::string readFile(const fs::path& p, size_t max_bytes) {
    std::ifstream in(p, std::ios::binary);
    std::string s;
    char chunk[65536];
    while (s.size() < max_bytes) {
        in.read(chunk, static_cast<std::streamsize>(std::min(sizeof chunk, max_bytes - s.size())));
        if (in.gcount() <= 0) break;
        s.append(chunk, static_cast<size_t>(in.gcount()));
    }
    return s;
}

void writeFile(const fs::path& p, const std::string& text) {
    std::ofstream out(p, std::ios::binary);
    out << text;
    if (!out) die(p.string() + ": (file): cannot write");
}

std::string sha256(const std::string& data) {
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int size = 0;
    if (EVP_Digest(data.data(), data.size(), digest, &size, EVP_sha256(), nullptr) != 1) die("SHA-256: libcrypto failed");
    std::string out;
    char b[3];
    for (unsigned int i = 0; i < size; ++i) std::snprintf(b, sizeof b, "%02x", digest[i]), out += b;
    return out;
}

json cached(const fs::path& file, const std::string& hash, const std::function<json()>& make) {
    static std::mutex guard;
    static std::map<std::string, std::unique_ptr<std::mutex>> locks;
    std::unique_lock<std::mutex> hold(guard);
    auto& m = locks[file.string()];
    if (!m) m = std::make_unique<std::mutex>();
    hold.unlock();
    std::lock_guard<std::mutex> lock(*m);
    const json old = json::parse(readFile(file), nullptr, false);
    if (old.is_object() && old.value("hash", "") == hash) return old["result"];
    json result = make();
    fs::create_directories(file.parent_path());
    writeFile(file, json{{"hash", hash}, {"result", result}}.dump(1));
    return result;
}

json loadPoints(const fs::path& points_dir, const std::string& stage) {
    fs::path file;
    if (!fs::is_directory(points_dir)) die(points_dir.string() + ": (folder): the points folder does not exist (--points-dir)");
    for (const auto& e : fs::directory_iterator(points_dir)) {
        const std::string name = e.path().filename().string();
        if (name.rfind(stage + "_", 0) == 0 && name.size() > 12 && name.substr(name.size() - 12) == ".points.json") file = e.path();
    }
    if (file.empty()) die(points_dir.string() + ": (folder): no " + stage + "_*.points.json");
    json j = json::parse(readFile(file), nullptr, false);
    const std::string f = file.string();
    if (j.is_discarded() || !j.is_object()) die(f + ": (JSON syntax): not a JSON object");
    if (!j.contains("title") || !j["title"].is_string()) die(f + ": title: missing or not a string");
    if (!j.contains("tests") || !j["tests"].is_object() || j["tests"].empty()) die(f + ": tests: missing, empty or not an object");
    if (j.contains("bonus") && !j["bonus"].is_object()) die(f + ": bonus: not an object");
    for (const char* part : {"tests", "bonus"}) {
        const json list = j.value(part, json::object());
        for (const auto& [name, p] : list.items()) {
            if (!p.is_number() || p.get<double>() <= 0) die(f + ": " + part + "." + name + ": points must be a number > 0");
            if (part[0] == 'b' && j["tests"].contains(name)) die(f + ": bonus." + name + ": also under tests");
        }
    }
    j["file"] = f;
    return j;
}

StageResult pointsStage(const fs::path& points_dir, const std::string& stage) {
    const json points = loadPoints(points_dir, stage);
    StageResult s{stage, points["title"], Status::graded, "", {}};
    for (const char* part : {"tests", "bonus"}) {
        const json list = points.value(part, json::object());
        for (const auto& [name, p] : list.items()) s.tests.push_back({name, false, 0, p.get<double>(), "", part[0] == 'b'});
    }
    return s;
}

StageResult ungradedStage(const fs::path& points_dir, const std::string& stage, Status status, const std::string& why) {
    StageResult s = pointsStage(points_dir, stage);
    s.status = status;
    s.problem = why;
    for (auto& t : s.tests) t.message = statusName(status) + ": " + why;
    return s;
}

std::string firstLines(const std::string& text, int n, const std::string& indent) {
    std::istringstream in(text);
    std::string line, out;
    for (int i = 0; i < n && std::getline(in, line);)
        if (line.find_first_not_of(" \t\r") != std::string::npos) out += (i++ ? "\n" + indent : "") + line;
    return out;
}

#ifdef CLOTHLAB_GRADER_TEST_SWITCHES
bool weakened(const char* defence) {
    const char* w = std::getenv("CLOTHLAB_WEAKEN");
    if (!w || !*defence) return w && *w;
    const std::string list = "," + std::string(w) + ",";
    return list.find("," + std::string(defence) + ",") != std::string::npos;
}
#endif

}  // namespace grade
