// clothlab-make-proxies OUT_DIR SWEEPS_CPP HEADER...: the test process's side of every function
// whose code may come from the submission, written at build time from the code that declares it:
//
//  - for each stage header clothlab/exercise/NN_name.h, OUT_DIR/proxies_NN.cpp: one definition per
//    function the header declares in namespace clothlab, which sends the call to the submission
//    process (wire/peer.h);
//  - into the same file, each framework sweep that SWEEPS_CPP (sim/sweeps.cpp) defines after
//    CLOTHLAB_REPLACEABLE(NN): when stage NN is the submission's, the sweep crosses whole, once per
//    solver iteration, instead of once per constraint;
//  - OUT_DIR/functions.h: CLOTHLAB_REMOTE_FUNCTIONS(X), X(id, name) for all of them (stage function
//    i: id 100 NN + i; sweep k: 100 NN + 50 + k), which the submission process serves.
//
// So a signature lives where the function is declared, nowhere else; one this tool cannot read stops
// the build, naming the file.
#include <cctype>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

struct Function {
    std::string returns, name, params;  // params without default values
    std::vector<std::string> args;      // the parameter names
};

std::string trim(const std::string& s) {
    const size_t a = s.find_first_not_of(" \t\n");
    return a == std::string::npos ? "" : s.substr(a, s.find_last_not_of(" \t\n") - a + 1);
}

/// The file's text without comments and preprocessor lines, whitespace runs made one space.
std::string code(const std::string& file) {
    std::ifstream in(file);
    if (!in) throw std::runtime_error("cannot read");
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    std::string out;
    bool lineStart = true;
    for (size_t i = 0; i < text.size(); ++i) {
        if (text.compare(i, 2, "//") == 0 || (lineStart && text[i] == '#')) {
            if ((i = text.find('\n', i)) == std::string::npos) break;
        } else if (text.compare(i, 2, "/*") == 0) {
            if ((i = text.find("*/", i)) == std::string::npos || (i += 2) >= text.size()) break;
        }
        const char c = text[i];
        lineStart = c == '\n' || (lineStart && (c == ' ' || c == '\t'));
        if (!std::isspace(static_cast<unsigned char>(c))) out += c;
        else if (!out.empty() && out.back() != ' ') out += ' ';
    }
    return out;
}

/// The trailing identifier of a declaration ("const Vec3& p0" -> "p0").
std::string lastIdentifier(const std::string& s) {
    size_t e = s.find_last_not_of(' ') + 1, b = e;
    while (b > 0 && (std::isalnum(static_cast<unsigned char>(s[b - 1])) || s[b - 1] == '_')) --b;
    return s.substr(b, e - b);
}

/// "R name(P1 a, P2 b = x)" read into a Function (parameters split at the commas outside <>, (), {}).
Function signature(const std::string& s) {
    const size_t open = s.find('(');
    if (open == std::string::npos || s.back() != ')') throw std::runtime_error("cannot read the declaration: " + s);
    Function f;
    f.name = lastIdentifier(s.substr(0, open));
    f.returns = trim(s.substr(0, open - f.name.size() - (s[open - 1] == ' ' ? 1 : 0)));
    if (f.name.empty() || f.returns.empty()) throw std::runtime_error("cannot read the declaration: " + s);
    std::vector<std::string> parts(1);
    int depth = 0;
    for (char c : s.substr(open + 1, s.size() - open - 2)) {
        depth += (c == '<' || c == '(' || c == '{') - (c == '>' || c == ')' || c == '}');
        if (c == ',' && depth == 0) parts.emplace_back();
        else parts.back() += c;
    }
    for (std::string p : parts) {
        if ((p = trim(p.substr(0, p.find('=')))).empty()) continue;
        const std::string name = lastIdentifier(p);
        if (name.empty() || name == p) throw std::runtime_error(f.name + ": a parameter without a name: " + p);
        f.params += (f.params.empty() ? "" : ", ") + p;
        f.args.push_back(name);
    }
    return f;
}

/// The functions a stage header declares directly in namespace clothlab (struct bodies, inline
/// definitions and aliases are skipped).
std::vector<Function> declarations(const std::string& header) {
    std::vector<Function> out;
    std::string statement;
    int depth = 0;
    for (char c : code(header)) {
        if (c == '{' || c == '}') {
            if (c == '{' && depth == 0 && trim(statement) != "namespace clothlab") throw std::runtime_error("code outside namespace clothlab");
            depth += c == '{' ? 1 : -1;
            statement.clear();
        } else if (depth <= 1 && c == ';') {
            const std::string s = trim(statement);
            statement.clear();
            if (depth == 1 && s.find('(') != std::string::npos && s.rfind("using ", 0) != 0 && s.rfind("struct ", 0) != 0)
                out.push_back(signature(s));
        } else if (depth <= 1) {
            statement += c;
        }
    }
    return out;
}

/// The sweeps of sim/sweeps.cpp marked CLOTHLAB_REPLACEABLE(NN), by stage: their definitions' signatures.
std::map<std::string, std::vector<Function>> replaceable(const std::string& sweeps) {
    std::map<std::string, std::vector<Function>> out;
    const std::string text = code(sweeps), mark = "CLOTHLAB_REPLACEABLE(";
    for (size_t at = text.find(mark); at != std::string::npos; at = text.find(mark, at + 1)) {
        const size_t close = text.find(')', at), body = text.find('{', close);
        if (close == std::string::npos || body == std::string::npos) throw std::runtime_error("cannot read " + text.substr(at, 80));
        out[trim(text.substr(at + mark.size(), close - at - mark.size()))].push_back(signature(trim(text.substr(close + 1, body - close - 1))));
    }
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 4) {
        std::cerr << "usage: clothlab-make-proxies OUT_DIR SWEEPS_CPP HEADER...\n";
        return 2;
    }
    const std::string outDir = argv[1];
    std::string file = argv[2];
    try {
        auto sweeps = replaceable(file);
        std::ofstream list(outDir + "/functions.h");
        list << "// Generated by clothlab-make-proxies (wire/make_proxies.cpp): X(id, name) per function the\n"
                "// submission process serves.\n#pragma once\n#define CLOTHLAB_REMOTE_FUNCTIONS(X) \\\n";
        for (int a = 3; a < argc; ++a) {
            file = argv[a];
            const std::string base = file.substr(file.find_last_of('/') + 1), nn = base.substr(0, 2);
            const std::vector<Function> functions = declarations(file);
            if (functions.empty()) throw std::runtime_error("no function declared");
            std::ofstream out(outDir + "/proxies_" + nn + ".cpp");
            out << "// Generated by clothlab-make-proxies from clothlab/exercise/" << base << " and sim/sweeps.cpp: stage " << nn
                << "'s functions\n// in the test process, each sent to the submission process (wire/peer.h).\n"
                << "#include \"functions.h\"\n#include \"wire/peer.h\"\n\nnamespace clothlab {\n";
            const auto write = [&](const std::vector<Function>& fs, int first) {
                for (size_t i = 0; i < fs.size(); ++i) {
                    const Function& f = fs[i];
                    std::string args;
                    for (const auto& x : f.args) args += ", " + x;
                    out << "\n" << f.returns << " " << f.name << "(" << f.params << ") {\n    return wire::Invoke<decltype(" << f.name
                        << ")>::call(wire::submissionProcess(), " << first + static_cast<int>(i) << ", \"" << f.name << "\"" << args << ");\n}\n";
                    list << "    X(" << first + static_cast<int>(i) << ", " << f.name << ") \\\n";
                }
            };
            write(functions, std::stoi(nn) * 100 + 1);
            write(sweeps[nn], std::stoi(nn) * 100 + 51);
            sweeps.erase(nn);
            out << "\n}  // namespace clothlab\n";
        }
        if (!sweeps.empty()) throw std::runtime_error("CLOTHLAB_REPLACEABLE(" + sweeps.begin()->first + "): no such stage header");
        list << "\n";
    } catch (const std::exception& e) {
        std::cerr << "clothlab-make-proxies: " << file << ": " << e.what() << "\n";
        return 1;
    }
    return 0;
}
