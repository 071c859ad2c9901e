#include "common.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

#include <openssl/evp.h>

namespace grade {

namespace {
/// The sum of f(t) over the tests.
template <class F> double sum(const std::vector<TestResult>& tests, F f) {
    double s = 0;
    for (const auto& t : tests) s += f(t);
    return s;
}
}  // namespace
double StageResult::points() const { return sum(tests, [](const TestResult& t) { return t.bonus ? 0.0 : t.points; }); }
double StageResult::max_points() const { return sum(tests, [](const TestResult& t) { return t.bonus ? 0.0 : t.max_points; }); }
double StageResult::bonus() const { return sum(tests, [](const TestResult& t) { return t.bonus ? t.points : 0.0; }); }
int StageResult::passed() const { return static_cast<int>(std::count_if(tests.begin(), tests.end(), [](const TestResult& t) { return t.passed; })); }

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

json loadPoints(const fs::path& points_dir, const std::string& stage) {
    fs::path file;
    if (!fs::is_directory(points_dir)) die(points_dir.string() + ": (folder): the points folder does not exist (--points-dir)");
    for (const auto& e : fs::directory_iterator(points_dir)) {
        const std::string name = e.path().filename().string();
        if (name.rfind(stage + "_", 0) == 0 && name.size() > 12 && name.substr(name.size() - 12) == ".points.json")
            file = e.path();
    }
    if (file.empty()) die(points_dir.string() + ": (folder): no " + stage + "_*.points.json");
    json j = json::parse(readFile(file), nullptr, false);
    const std::string f = file.string();
    if (j.is_discarded() || !j.is_object()) die(f + ": (JSON syntax): not a JSON object");
    if (!j.contains("title") || !j["title"].is_string()) die(f + ": title: missing or not a string");
    if (!j.contains("tests") || !j["tests"].is_object() || j["tests"].empty()) die(f + ": tests: missing, empty or not an object");
    for (auto it = j["tests"].begin(); it != j["tests"].end(); ++it)
        if (!it->is_number() || it->get<double>() <= 0) die(f + ": tests." + it.key() + ": points must be a number > 0");
    if (j.contains("bonus")) {
        if (!j["bonus"].is_object()) die(f + ": bonus: not an object");
        for (auto it = j["bonus"].begin(); it != j["bonus"].end(); ++it) {
            if (!it->is_number() || it->get<double>() <= 0) die(f + ": bonus." + it.key() + ": points must be a number > 0");
            if (j["tests"].contains(it.key())) die(f + ": bonus." + it.key() + ": also under tests");
        }
    }
    j["file"] = f;
    return j;
}

std::vector<TestResult> pointsTests(const json& points) {
    std::vector<TestResult> out;
    for (const char* part : {"tests", "bonus"})
        if (points.contains(part))
            for (auto it = points[part].begin(); it != points[part].end(); ++it) {
                TestResult t;
                t.name = it.key();
                t.max_points = it->get<double>();
                t.bonus = std::string(part) == "bonus";
                out.push_back(t);
            }
    return out;
}

StageResult ungradedStage(const fs::path& points_dir, const std::string& stage, const std::string& status,
                          const std::string& why) {
    const json points = loadPoints(points_dir, stage);
    StageResult s;
    s.stage = stage;
    s.title = points["title"];
    s.status = status;
    s.problem = why;
    s.tests = pointsTests(points);
    for (auto& t : s.tests) t.message = status + ": " + why;
    return s;
}

std::string firstLines(const std::string& text, int n, const std::string& indent) {
    std::istringstream in(text);
    std::string line, out;
    for (int i = 0; i < n && std::getline(in, line);) {
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        out += (i ? "\n" + indent : "") + line;
        ++i;
    }
    return out;
}

}  // namespace grade
