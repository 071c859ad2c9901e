// clothlab-leak-check: does what students get give away a reference solution or an answer?
//
//   clothlab-leak-check SOURCE_ROOT STUDENTS_DIR [--window N] [--keys FILE]...
//
// STUDENTS_DIR is what students get (a fresh student copy, the handout's text beside it). Every text
// file in it (any name; a file with a NUL byte in its first 8 KiB is binary and skipped) is searched for
//  1. windows of N consecutive tokens (default 16) of any function body in SOURCE_ROOT/solutions/**/*.cpp
//     (the top-level functions, inside the namespace): a body copied, reformatted or renamed;
//  2. every statement of those bodies (the tokens up to `;`, `{` or `}`) of at least 5 tokens that
//     names two or more things and computes (two arithmetic operators or vector or math functions):
//     the reference's key lines, also one at a time (a shell script that quotes
//     `1.0 - std::pow(1.0 - k, 1.0 / iterations)`);
//  3. the instructor's keys, FILE lines `SOURCE<TAB>SCOPE<TAB>KIND<TAB>TEXT` (SCOPE: a path prefix in
//     STUDENTS_DIR the key applies to, `*` for all; KIND `tokens`: TEXT's C++ tokens in a row, e.g. a
//     formula or a number; KIND `words`: any 6 consecutive words of TEXT with 3 or more that are not
//     small words, or all of a shorter TEXT, case and punctuation ignored: an answer in prose).
// Tokens are C++ tokens without comments and whitespace, so reformatting or renaming hides nothing.
// What also occurs in a stub in SOURCE_ROOT/exercises/ (signatures, the "not implemented" boilerplate)
// is no leak. Exit 0: no leak; 1: leaks (one line each: the file and line, what it gives away and
// where that comes from); 2: bad input.
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
/// With `literals` false every quote is punctuation and what it encloses is tokens too (for the
/// statements and keys: code quoted in a shell script or a message).
std::vector<Token> tokenize(const std::string& text, bool literals = true) {
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
        if (literals && (c == '"' || c == '\'')) {  // a literal is one token, if it closes on this line
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
bool namesEnough(const std::vector<Token>& t, size_t at, size_t n, size_t at_least = 3) {
    static const std::set<std::string> keywords = {"auto", "bool", "break", "const", "continue", "double", "else",
                                                   "float", "for", "if", "int", "return", "size_t", "static_cast",
                                                   "std", "void", "while", "true", "false", "nullptr"};
    std::set<std::string> names;
    for (size_t k = at; k < at + n; ++k) {
        const std::string& s = t[k].text;
        if (s.size() >= 2 && (std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_') && !keywords.count(s)) names.insert(s);
    }
    return names.size() >= at_least;
}

/// A statement is a key line of the answer if it computes something: two or more arithmetic operators
/// or calls of a vector or math function (declarations, loop headers, `push_back({`, `len = e.norm()`
/// and `return e / len` are in every numerical code).
bool computes(const std::vector<Token>& t, size_t at, size_t n) {
    static const std::set<std::string> ops = {"+", "-", "*", "/", "%", "+=", "-=", "*=", "/=", "^"};
    static const std::set<std::string> math = {"dot", "cross", "norm", "squaredNorm", "normalized", "sqrt", "pow", "atan2",
                                               "acos", "asin", "sin", "cos", "floor", "ceil", "clamp", "min", "max", "abs"};
    int operations = 0;
    for (size_t k = at; k < at + n; ++k)
        operations += ops.count(t[k].text) || (math.count(t[k].text) && k + 1 < at + n && t[k + 1].text == "(") ? 1 : 0;
    return operations >= 2;
}

std::string windowKey(const std::vector<Token>& t, size_t at, size_t n) {
    std::string key;
    for (size_t k = at; k < at + n; ++k) key += t[k].text + '\x1f';
    return key;
}

/// Every regular file under `dir` (not in .git), sorted; with `text_only` only the text files: no NUL
/// byte in the first 8 KiB.
std::vector<fs::path> filesUnder(const fs::path& dir, const std::set<std::string>& extensions, bool text_only = false) {
    std::vector<fs::path> files;
    if (!fs::is_directory(dir)) return files;
    for (auto it = fs::recursive_directory_iterator(dir); it != fs::recursive_directory_iterator(); ++it) {
        if (it->is_directory() && it->path().filename() == ".git") { it.disable_recursion_pending(); continue; }
        if (!it->is_regular_file()) continue;
        if (!extensions.empty() && !extensions.count(it->path().extension().string())) continue;
        if (text_only) {
            std::ifstream in(it->path(), std::ios::binary);
            char head[8192];
            in.read(head, sizeof head);
            if (std::find(head, head + in.gcount(), '\0') != head + in.gcount()) continue;
        }
        files.push_back(it->path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

[[noreturn]] void usage(const std::string& why) {
    std::cerr << "error: command line: " << why << "\nusage: clothlab-leak-check SOURCE_ROOT STUDENTS_DIR [--window N] [--keys FILE]...\n";
    std::exit(2);
}

/// A sequence to find in what students get: a reference statement or an instructor's key.
struct Needle {
    std::vector<std::string> items;  // tokens, or words
    std::string what;                // "statement of f() in solutions/..." or "key of SOURCE"
    std::string scope;               // a path prefix in STUDENTS_DIR, "" for all
    bool words = false;
};

/// Lower-case words of `text` (letters, digits and any non-ASCII byte; the rest separates), with the
/// line each starts on.
std::vector<Token> wordsOf(const std::string& text) {
    std::vector<Token> out;
    int line = 1;
    std::string w;
    int at = 1;
    for (size_t i = 0; i <= text.size(); ++i) {
        const unsigned char c = i < text.size() ? static_cast<unsigned char>(text[i]) : ' ';
        if (std::isalnum(c) || c >= 0x80) {
            if (w.empty()) at = line;
            w += static_cast<char>(std::tolower(c));
        } else if (!w.empty()) {
            out.push_back({w, at});
            w.clear();
        }
        if (c == '\n') ++line;
    }
    return out;
}

/// Small words: a window of an answer counts only with 3 or more other words (not "of the to a ...").
bool smallWord(const std::string& w) {
    static const std::set<std::string> small = {"a", "an", "and", "are", "as", "at", "be", "by", "de", "der", "die",
        "das", "den", "dem", "des", "ein", "eine", "einer", "for", "from", "has", "in", "is", "it", "its", "ist", "mit",
        "of", "on", "or", "so", "that", "the", "then", "this", "to", "und", "von", "was", "with", "zu", "im", "it's"};
    return w.size() < 2 || small.count(w) > 0;
}

constexpr size_t kAnswerWords = 6;  // words in a row of an answer that give it away

/// The instructor's keys of FILE (SOURCE<TAB>SCOPE<TAB>KIND<TAB>TEXT per line) as needles.
void readKeys(const fs::path& file, std::vector<Needle>& needles) {
    std::ifstream in(file);
    if (!in) usage(file.string() + ": (file): cannot read the keys");
    std::string line;
    int n = 0;
    while (std::getline(in, line)) {
        ++n;
        if (line.empty() || line[0] == '#') continue;
        std::vector<std::string> f;
        size_t at = 0;
        for (int k = 0; k < 3; ++k) {
            const size_t tab = line.find('\t', at);
            if (tab == std::string::npos) usage(file.string() + ":" + std::to_string(n) + ": expects SOURCE<TAB>SCOPE<TAB>KIND<TAB>TEXT");
            f.push_back(line.substr(at, tab - at));
            at = tab + 1;
        }
        const std::string text = line.substr(at), what = "key of " + f[0], scope = f[1] == "*" ? "" : f[1];
        if (f[2] == "tokens") {
            Needle k{{}, what + ": `" + text + "`", scope, false};
            for (const auto& t : tokenize(text, false)) k.items.push_back(t.text);
            if (!k.items.empty()) needles.push_back(std::move(k));
        } else if (f[2] == "words") {
            std::vector<std::string> w;
            for (const auto& t : wordsOf(text)) w.push_back(t.text);
            const auto content = [&](size_t a, size_t b) {
                return std::count_if(w.begin() + static_cast<long>(a), w.begin() + static_cast<long>(b),
                                     [](const std::string& x) { return !smallWord(x); });
            };
            if (w.size() <= kAnswerWords) {
                if (content(0, w.size()) >= 3) needles.push_back({w, what + ": \"" + text + "\"", scope, true});
            } else {
                for (size_t a = 0; a + kAnswerWords <= w.size(); ++a)
                    if (content(a, a + kAnswerWords) >= 3)
                        needles.push_back({{w.begin() + static_cast<long>(a), w.begin() + static_cast<long>(a + kAnswerWords)},
                                           what + ": \"" + text.substr(0, 120) + (text.size() > 120 ? "…" : "") + "\"", scope, true});
            }
        } else {
            usage(file.string() + ":" + std::to_string(n) + ": KIND must be tokens or words, not '" + f[2] + "'");
        }
    }
}

std::string joined(const std::vector<std::string>& items, const std::string& sep) {
    std::string r;
    for (const auto& x : items) r += (r.empty() ? "" : sep) + x;
    return r;
}

/// Where `needles` (all of one kind) occur in `seq`: one report line per needle and file, at its first place.
int findNeedles(const std::vector<Token>& seq, const std::vector<const Needle*>& needles, const std::string& rel) {
    std::unordered_map<std::string, std::vector<const Needle*>> by_first;
    for (const Needle* k : needles) by_first[k->items[0]].push_back(k);
    std::set<std::string> found;  // what was reported (the windows of one answer say it once)
    int leaks = 0;
    for (size_t at = 0; at < seq.size(); ++at) {
        const auto it = by_first.find(seq[at].text);
        if (it == by_first.end()) continue;
        for (const Needle* k : it->second) {
            if (found.count(k->what) || at + k->items.size() > seq.size()) continue;
            bool same = true;
            for (size_t j = 1; j < k->items.size() && same; ++j) same = seq[at + j].text == k->items[j];
            if (!same) continue;
            found.insert(k->what);
            ++leaks;
            std::cout << "leak: " << rel << ":" << seq[at].line << ": " << k->what << "\n";
        }
    }
    return leaks;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    size_t window = 16;  // tokens: long enough that boilerplate shared with the framework is no hit (see namesEnough)
    std::vector<std::string> paths;
    std::vector<fs::path> key_files;
    for (size_t a = 0; a < args.size(); ++a) {
        if (args[a] == "--window") {
            if (a + 1 >= args.size()) usage("--window: expects a number of tokens");
            char* end = nullptr;
            const long v = std::strtol(args[++a].c_str(), &end, 10);
            if (*end != '\0' || v < 2) usage("--window: expects a number of tokens >= 2, got '" + args[a] + "'");
            window = static_cast<size_t>(v);
        } else if (args[a] == "--keys") {
            if (a + 1 >= args.size()) usage("--keys: expects a file");
            key_files.push_back(args[++a]);
        } else {
            paths.push_back(args[a]);
        }
    }
    if (paths.size() != 2) usage("expects SOURCE_ROOT and STUDENTS_DIR");
    const fs::path root = paths[0], copy = paths[1];
    if (!fs::is_directory(root / "solutions")) usage(root.string() + "/solutions: (folder): does not exist");
    if (!fs::is_directory(copy)) usage(copy.string() + ": (folder): does not exist");

    // Windows and statements the stubs share with the reference (signatures, boilerplate) are no leak.
    std::unordered_set<std::string> stub_windows;
    std::string stub_text = "\x1f";  // every stub's tokens, joined: a statement found in it is no leak
    for (const auto& f : filesUnder(root / "exercises", {".cpp", ".h"})) {
        const auto t = tokenize(readFile(f));
        for (size_t k = 0; k + window <= t.size(); ++k) stub_windows.insert(windowKey(t, k, window));
        const auto plain = tokenize(readFile(f), false);
        stub_text += windowKey(plain, 0, plain.size());
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

    // The statements of the bodies (2.) and the instructor's keys (3.), as tokens with quotes as punctuation.
    std::vector<Body> plain_bodies;
    for (const auto& f : solution_files)
        for (auto& b : functionBodies(tokenize(readFile(f), false), fs::relative(f, root).string())) plain_bodies.push_back(std::move(b));
    std::vector<Needle> needles;
    std::set<std::string> seen;
    for (const auto& b : plain_bodies) {
        size_t from = 0;
        for (size_t k = 0; k <= b.tokens.size(); ++k) {
            const bool end = k == b.tokens.size() || b.tokens[k].text == ";" || b.tokens[k].text == "{" || b.tokens[k].text == "}";
            if (!end) continue;
            const size_t n = std::min(k + 1, b.tokens.size()) - from;  // with its `;`
            if (n >= 5 && namesEnough(b.tokens, from, n, 2) && computes(b.tokens, from, n) && stub_text.find("\x1f" + windowKey(b.tokens, from, n)) == std::string::npos &&
                seen.insert(windowKey(b.tokens, from, n)).second) {
                Needle st{{}, "", "", false};
                for (size_t j = from; j < from + n; ++j) st.items.push_back(b.tokens[j].text);
                st.what = "statement of the reference " + b.function + "() in " + b.file + ": `" + joined(st.items, " ") + "`";
                needles.push_back(std::move(st));
            }
            from = k + 1;
        }
    }
    const size_t statements = needles.size();
    for (const auto& f : key_files) readKeys(f, needles);

    // Scan what students get: one line per (file, function) for bodies, per (file, needle) for the rest.
    int leaks = 0;
    const auto files = filesUnder(copy, {}, true);
    for (const auto& f : files) {
        const std::string text = readFile(f), rel = fs::relative(f, copy).string();
        const auto t = tokenize(text);
        struct Hit { int line, windows; size_t at; };  // the first place, how many windows
        std::map<const Body*, Hit> found;
        for (size_t k = 0; k + window <= t.size(); ++k) {
            const auto hit = reference.find(windowKey(t, k, window));
            if (hit == reference.end()) continue;
            ++found.emplace(hit->second, Hit{t[k].line, 0, k}).first->second.windows;
        }
        for (const auto& [body, where] : found) {
            ++leaks;
            std::string shown;  // the first shared window, as tokens
            for (size_t k = where.at; k < where.at + window; ++k) shown += (shown.empty() ? "" : " ") + t[k].text;
            std::cout << "leak: " << rel << ":" << where.line << ": " << where.windows << " windows of " << window
                      << " tokens from the reference " << body->function << "() in " << body->file << ", e.g. `" << shown << "`\n";
        }
        std::vector<const Needle*> by_tokens, by_words;
        for (const auto& k : needles)
            if (k.scope.empty() || rel.rfind(k.scope, 0) == 0) (k.words ? by_words : by_tokens).push_back(&k);
        leaks += findNeedles(tokenize(text, false), by_tokens, rel);
        if (!by_words.empty()) leaks += findNeedles(wordsOf(text), by_words, rel);
    }
    std::cout << (leaks ? "FAIL" : "ok") << ": " << bodies.size() << " reference function bodies (" << solution_files.size()
              << " files, " << statements << " statements) and " << needles.size() - statements << " keys checked against "
              << files.size() << " text files in " << copy.string() << ", window " << window << " tokens: " << leaks
              << (leaks == 1 ? " leak" : " leaks") << "\n";
    return leaks ? 1 : 0;
}
