// Writes the test side of every stage function from the stage's contract header, at build time:
//
//     clothlab-make-proxies OUT_DIR framework/include/clothlab/exercise/01_hooke.h ...
//
// For each header NN_name.h it writes OUT_DIR/proxies_NN.cpp: one definition per function the
// header declares in namespace clothlab, which sends the call to the submission process
// (remote/peer.h). It also writes OUT_DIR/stage_functions.h, the list X(id, name) of them all
// (id = 100 NN + the function's place in its header), which the submission process serves.
// So a stage function's signature lives in its header only; a declaration this tool cannot read
// stops the build with the header's name.
#include <cctype>
#include <fstream>
#include <iostream>
#include <sstream>
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

/// The text without comments and preprocessor lines, whitespace runs made one space.
std::string code(const std::string& text) {
    std::string out;
    bool lineStart = true;
    for (size_t i = 0; i < text.size(); ++i) {
        if (text.compare(i, 2, "//") == 0 || (lineStart && text[i] == '#')) {
            i = text.find('\n', i);
            if (i == std::string::npos) break;
        } else if (text.compare(i, 2, "/*") == 0) {
            i = text.find("*/", i);
            if (i == std::string::npos) break;
            i += 2;
            if (i >= text.size()) break;
        }
        const char c = text[i];
        lineStart = c == '\n' || (lineStart && (c == ' ' || c == '\t'));
        if (std::isspace(static_cast<unsigned char>(c))) {
            if (!out.empty() && out.back() != ' ') out += ' ';
        } else {
            out += c;
        }
    }
    return out;
}

/// Splits at the commas outside <>, () and {}.
std::vector<std::string> splitTopLevel(const std::string& s) {
    std::vector<std::string> parts(1);
    int depth = 0;
    for (char c : s) {
        if (c == '<' || c == '(' || c == '{') ++depth;
        if (c == '>' || c == ')' || c == '}') --depth;
        if (c == ',' && depth == 0) parts.emplace_back();
        else parts.back() += c;
    }
    return parts;
}

/// The trailing identifier of a declaration ("const Vec3& p0" -> "p0").
std::string lastIdentifier(const std::string& s) {
    size_t e = s.size();
    while (e > 0 && s[e - 1] == ' ') --e;
    size_t b = e;
    while (b > 0 && (std::isalnum(static_cast<unsigned char>(s[b - 1])) || s[b - 1] == '_')) --b;
    return s.substr(b, e - b);
}

/// The functions declared directly in namespace clothlab (struct bodies, enums, inline
/// definitions and aliases are skipped).
std::vector<Function> declarations(const std::string& header) {
    std::ifstream in(header);
    if (!in) throw std::runtime_error("cannot read");
    std::stringstream buf;
    buf << in.rdbuf();
    const std::string text = code(buf.str());
    std::vector<Function> out;
    std::string statement;
    int depth = 0;
    for (char c : text) {
        if (c == '{') {
            if (depth == 0 && trim(statement) != "namespace clothlab") throw std::runtime_error("code outside namespace clothlab");
            ++depth;
            statement.clear();
            continue;
        }
        if (c == '}') {
            --depth;
            statement.clear();
            continue;
        }
        if (depth > 1) continue;
        if (depth == 0 && c == ';') statement.clear();
        if (depth == 0 || c != ';') {
            statement += c;
            continue;
        }
        const std::string s = trim(statement);
        statement.clear();
        const size_t open = s.find('(');
        if (s.empty() || open == std::string::npos || s.rfind("using ", 0) == 0 || s.rfind("struct ", 0) == 0) continue;
        if (s.back() != ')') throw std::runtime_error("cannot read the declaration: " + s);
        Function f;
        f.name = lastIdentifier(s.substr(0, open));
        f.returns = trim(s.substr(0, open - f.name.size() - (s[open - 1] == ' ' ? 1 : 0)));
        if (f.name.empty() || f.returns.empty()) throw std::runtime_error("cannot read the declaration: " + s);
        const std::string params = trim(s.substr(open + 1, s.size() - open - 2));
        if (!params.empty())
            for (std::string p : splitTopLevel(params)) {
                p = trim(p.substr(0, p.find('=')));
                const std::string name = lastIdentifier(p);
                if (name.empty() || name == p) throw std::runtime_error(f.name + ": a parameter without a name: " + p);
                f.params += (f.params.empty() ? "" : ", ") + p;
                f.args.push_back(name);
            }
        out.push_back(f);
    }
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::cerr << "usage: clothlab-make-proxies OUT_DIR HEADER...\n";
        return 2;
    }
    const std::string outDir = argv[1];
    std::ofstream list(outDir + "/stage_functions.h");
    list << "// Generated by clothlab-make-proxies from the stage headers: X(id, name) per stage function.\n"
            "#pragma once\n#define CLOTHLAB_STAGE_FUNCTIONS(X) \\\n";
    for (int a = 2; a < argc; ++a) {
        const std::string header = argv[a];
        const std::string file = header.substr(header.find_last_of('/') + 1);
        const std::string nn = file.substr(0, 2);
        std::vector<Function> functions;
        try {
            functions = declarations(header);
            if (functions.empty()) throw std::runtime_error("no function declared");
        } catch (const std::exception& e) {
            std::cerr << "clothlab-make-proxies: " << header << ": " << e.what() << "\n";
            return 1;
        }
        std::ofstream out(outDir + "/proxies_" + nn + ".cpp");
        out << "// Generated by clothlab-make-proxies from clothlab/exercise/" << file << ": stage " << nn
            << "'s functions in the test process,\n// each sent to the submission process (remote/peer.h).\n"
            << "#include \"clothlab/exercise/" << file << "\"\n#include \"remote/functions.h\"\n#include \"remote/peer.h\"\n\n"
            << "namespace clothlab {\n";
        for (size_t i = 0; i < functions.size(); ++i) {
            const Function& f = functions[i];
            std::string args;
            for (const auto& x : f.args) args += ", " + x;
            out << "\n" << f.returns << " " << f.name << "(" << f.params << ") {\n    return remote::Invoke<decltype("
                << f.name << ")>::call(remote::submissionProcess(), remote::k_" << f.name << ", \"" << f.name << "\"" << args
                << ");\n}\n";
            list << "    X(" << std::stoi(nn) * 100 + static_cast<int>(i) + 1 << ", " << f.name << ") \\\n";
        }
        out << "\n}  // namespace clothlab\n";
    }
    list << "\n";
    return 0;
}
