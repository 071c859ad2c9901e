// clothlab-leak-check: does the student copy give away a reference solution?
//
//   clothlab-leak-check SOURCE_ROOT COPY [--window N]
//
// Reads every function body in SOURCE_ROOT/solutions/**/*.cpp (the top-level functions, inside
// the namespace) and reports a leak wherever N consecutive tokens of a body occur in a .cpp, .h or
// .md file of COPY. Tokens are C++ tokens without comments and whitespace, so reformatting or
// renaming the file hides nothing. Windows that also occur in a stub in SOURCE_ROOT/exercises/
// (signatures, the "not implemented" boilerplate) are not leaks. Exit 0: no leak; 1: leaks (one
// line each: the copy's file and line, the function and its reference file); 2: bad input.
// C++17 and the standard library only, so it builds wherever the tests build.
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct Token {
    std::string text;
    int line;
};

bool identChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Operators of two characters are one token (`+=` as in `x += dt * v`), everything else one character.
bool twoCharOperator(char a, char b) {
    static const std::set<std::string> ops = {"::", "->", "+=", "-=", "*=", "/=", "==", "!=", "<=", ">=",
                                              "&&", "||", "++", "--", "<<"};
    return ops.count(std::string{a, b}) > 0;
}

/// C++ tokens of `text` without comments, whitespace and preprocessor lines. Also used on Markdown,
/// so a quote that does not close on its line is punctuation ("don't"), not the start of a literal.
std::vector<Token> tokenize(const std::string& text) {
    std::vector<Token> out;
    const size_t n = text.size();
    int line = 1;
    bool line_start = true;  // only whitespace so far on this line
    size_t i = 0;
    while (i < n) {
        const char c = text[i];
        if (c == '\n') { ++line, ++i, line_start = true; continue; }
        if (std::isspace(static_cast<unsigned char>(c))) { ++i; continue; }
        if (c == '#' && line_start) {  // preprocessor line (and Markdown heading), with continuations
            while (i < n && text[i] != '\n') i += (text[i] == '\\' && i + 1 < n) ? 2 : 1;
            continue;
        }
        line_start = false;
        if (c == '/' && i + 1 < n && text[i + 1] == '/') {
            while (i < n && text[i] != '\n') ++i;
            continue;
        }
        if (c == '/' && i + 1 < n && text[i + 1] == '*') {
            const size_t end = text.find("*/", i + 2);
            const size_t stop = end == std::string::npos ? n : end + 2;
            line += static_cast<int>(std::count(text.begin() + static_cast<long>(i), text.begin() + static_cast<long>(stop), '\n'));
            i = stop;
            continue;
        }
        if (c == '"' || c == '\'') {  // a literal is one token, if it closes on this line
            size_t j = i + 1;
            while (j < n && text[j] != c && text[j] != '\n') j += (text[j] == '\\' && j + 1 < n) ? 2 : 1;
            if (j < n && text[j] == c) {
                out.push_back({text.substr(i, j + 1 - i), line});
                i = j + 1;
                continue;
            }
        }
        if (identChar(c) || (c == '.' && i + 1 < n && std::isdigit(static_cast<unsigned char>(text[i + 1])))) {
            // identifier or number (1e-12 is one number: a sign right after an exponent belongs to it)
            size_t j = i + 1;
            const bool number = std::isdigit(static_cast<unsigned char>(c)) || c == '.';
            while (j < n && (identChar(text[j]) || (number && text[j] == '.') ||
                             (number && (text[j] == '+' || text[j] == '-') && (text[j - 1] == 'e' || text[j - 1] == 'E'))))
                ++j;
            out.push_back({text.substr(i, j - i), line});
            i = j;
            continue;
        }
        const size_t len = (i + 1 < n && twoCharOperator(c, text[i + 1])) ? 2 : 1;
        out.push_back({text.substr(i, len), line});
        i += len;
    }
    return out;
}

std::string readFile(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

struct Body {
    std::string function;  // its name
    std::string file;      // solutions/NN_name/file.cpp
    std::vector<Token> tokens;
};

/// Index of the `}` that closes the `{` at `open`, or tokens.size().
size_t matchingBrace(const std::vector<Token>& t, size_t open) {
    int depth = 0;
    for (size_t k = open; k < t.size(); ++k) {
        if (t[k].text == "{") ++depth;
        if (t[k].text == "}" && --depth == 0) return k;
    }
    return t.size();
}

/// The bodies of the functions at namespace level: a `{` after a declaration with a parameter list.
/// Namespace bodies are entered; class, enum and initializer braces are skipped.
std::vector<Body> functionBodies(const std::vector<Token>& t, const std::string& file) {
    std::vector<Body> bodies;
    size_t decl = 0;  // first token of the current declaration
    for (size_t k = 0; k < t.size(); ++k) {
        const std::string& s = t[k].text;
        if (s == ";" || s == "}") { decl = k + 1; continue; }
        if (s != "{") continue;
        const auto first = t.begin() + static_cast<long>(decl), here = t.begin() + static_cast<long>(k);
        // The parameter list is the last "(" outside parentheses (after any __attribute__((...))).
        auto paren = here;
        int depth = 0;
        for (auto p = first; p != here; ++p) {
            if (p->text == "(" && depth++ == 0) paren = p;
            if (p->text == ")") --depth;
        }
        const bool is_namespace = std::any_of(first, here, [](const Token& x) { return x.text == "namespace"; }) ||
                                  (first != here && first->text == "extern");
        const bool is_type = first != here && (first->text == "struct" || first->text == "class" ||
                                               first->text == "enum" || first->text == "union");
        if (is_namespace) { decl = k + 1; continue; }
        const size_t close = matchingBrace(t, k);
        if (paren != here && paren != first && !is_type) {
            Body b{(paren - 1)->text, file, {}};
            b.tokens.assign(t.begin() + static_cast<long>(k) + 1, t.begin() + static_cast<long>(close));
            bodies.push_back(std::move(b));
        }
        k = close;
        decl = k + 1;
    }
    return bodies;
}

// A window is evidence only if it names at least three things: identifiers of two or more characters
// that are not keywords. Loop headers (`for ( int i = 0 ; i < n ; ++ i )`) and zero initialisers
// are in every numerical code and prove nothing.
bool namesEnough(const std::vector<Token>& t, size_t at, size_t n) {
    static const std::set<std::string> keywords = {"auto", "bool", "break", "const", "continue", "double", "else",
                                                   "float", "for", "if", "int", "return", "size_t", "static_cast",
                                                   "std", "void", "while", "true", "false", "nullptr"};
    std::set<std::string> names;
    for (size_t k = at; k < at + n; ++k) {
        const std::string& s = t[k].text;
        if (s.size() >= 2 && (std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_') && !keywords.count(s)) names.insert(s);
    }
    return names.size() >= 3;
}

std::string windowKey(const std::vector<Token>& t, size_t at, size_t n) {
    std::string key;
    for (size_t k = at; k < at + n; ++k) key += t[k].text + '\x1f';
    return key;
}

std::vector<fs::path> filesUnder(const fs::path& dir, const std::set<std::string>& extensions) {
    std::vector<fs::path> files;
    if (!fs::is_directory(dir)) return files;
    for (auto it = fs::recursive_directory_iterator(dir); it != fs::recursive_directory_iterator(); ++it) {
        if (it->is_directory() && it->path().filename() == ".git") { it.disable_recursion_pending(); continue; }
        if (it->is_regular_file() && extensions.count(it->path().extension().string())) files.push_back(it->path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

[[noreturn]] void usage(const std::string& why) {
    std::cerr << "error: command line: " << why << "\nusage: clothlab-leak-check SOURCE_ROOT COPY [--window N]\n";
    std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    size_t window = 16;  // tokens: long enough that boilerplate shared with the framework is no hit (see namesEnough)
    std::vector<std::string> paths;
    for (size_t a = 0; a < args.size(); ++a) {
        if (args[a] == "--window") {
            if (a + 1 >= args.size()) usage("--window: expects a number of tokens");
            char* end = nullptr;
            const long v = std::strtol(args[++a].c_str(), &end, 10);
            if (*end != '\0' || v < 2) usage("--window: expects a number of tokens >= 2, got '" + args[a] + "'");
            window = static_cast<size_t>(v);
        } else {
            paths.push_back(args[a]);
        }
    }
    if (paths.size() != 2) usage("expects SOURCE_ROOT and COPY");
    const fs::path root = paths[0], copy = paths[1];
    if (!fs::is_directory(root / "solutions")) usage(root.string() + "/solutions: (folder): does not exist");
    if (!fs::is_directory(copy)) usage(copy.string() + ": (folder): does not exist");

    // Windows the stubs share with the reference (signatures, boilerplate) are no leak.
    std::unordered_set<std::string> stub_windows;
    for (const auto& f : filesUnder(root / "exercises", {".cpp", ".h"})) {
        const auto t = tokenize(readFile(f));
        for (size_t k = 0; k + window <= t.size(); ++k) stub_windows.insert(windowKey(t, k, window));
    }
    // Every other window of a reference body, and which function it comes from.
    std::unordered_map<std::string, const Body*> reference;
    std::vector<Body> bodies;
    const auto solution_files = filesUnder(root / "solutions", {".cpp"});
    for (const auto& f : solution_files)
        for (auto& b : functionBodies(tokenize(readFile(f)), fs::relative(f, root).string())) bodies.push_back(std::move(b));
    for (const auto& b : bodies)
        for (size_t k = 0; k + window <= b.tokens.size(); ++k) {
            std::string key = windowKey(b.tokens, k, window);
            if (!stub_windows.count(key) && namesEnough(b.tokens, k, window)) reference.emplace(std::move(key), &b);
        }
    if (reference.empty()) usage(root.string() + "/solutions: no function body of " + std::to_string(window) + " tokens or more");

    // Scan the copy: one line per (file, function), at the first place it shows.
    int leaks = 0;
    for (const auto& f : filesUnder(copy, {".cpp", ".h", ".md"})) {
        const auto t = tokenize(readFile(f));
        struct Hit { int line, windows; size_t at; };  // the first place, how many windows
        std::map<const Body*, Hit> found;
        for (size_t k = 0; k + window <= t.size(); ++k) {
            const auto hit = reference.find(windowKey(t, k, window));
            if (hit == reference.end()) continue;
            ++found.emplace(hit->second, Hit{t[k].line, 0, k}).first->second.windows;
        }
        for (const auto& [body, where] : found) {
            ++leaks;
            std::string text;  // the first shared window, as tokens
            for (size_t k = where.at; k < where.at + window; ++k) text += (text.empty() ? "" : " ") + t[k].text;
            std::cout << "leak: " << fs::relative(f, copy).string() << ":" << where.line << ": " << where.windows
                      << " windows of " << window << " tokens from the reference " << body->function << "() in "
                      << body->file << ", e.g. `" << text << "`\n";
        }
    }
    std::cout << (leaks ? "FAIL" : "ok") << ": " << bodies.size() << " reference function bodies (" << solution_files.size()
              << " files) checked against " << copy.string() << ", window " << window << " tokens: " << leaks
              << (leaks == 1 ? " leak" : " leaks") << "\n";
    return leaks ? 1 : 0;
}
