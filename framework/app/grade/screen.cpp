#include "screen.h"

#include <cxxabi.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <regex>
#include <sstream>

#include "common.h"

namespace grade {

namespace {

// ---- Source screen ------------------------------------------------------------------------------

const std::set<std::string> kStdHeaders = {
    "algorithm", "array", "cassert", "cfloat", "climits", "cmath", "cstddef", "cstdint", "cstdio", "cstdlib",
    "cstring", "deque", "functional", "initializer_list", "iomanip", "iostream", "iterator", "limits", "list",
    "map", "memory", "numeric", "optional", "queue", "set", "sstream", "stack", "stdexcept", "string",
    "string_view", "tuple", "type_traits", "unordered_map", "unordered_set", "utility", "variant", "vector",
    "bitset", "complex", "random", "chrono", "ostream", "assert.h", "math.h", "stdio.h", "string.h",
    "stdint.h", "float.h", "limits.h", "stdlib.h"};

/// Names a submission has no use for, with the reason shown to the student.
const std::map<std::string, std::string>& bannedNames() {
    static const std::map<std::string, std::string> m = [] {
        std::map<std::string, std::string> b;
        auto add = [&](std::initializer_list<const char*> names, const std::string& why) {
            for (const char* n : names) b[n] = why;
        };
        add({"main"}, "a submission has no main(): the graded tests bring their own");
        add({"testing", "gtest"}, "a submission does not use GoogleTest: the graded tests do");
        add({"asm", "__asm", "__asm__", "_Pragma", "__attribute__", "__attribute", "__declspec"},
            "inline assembly, pragmas and compiler attributes are not allowed in a submission");
        // Only names no one uses for a variable of their own: common words (read, write, open, close,
        // exit, kill, connect, ...) are left to the object screen, which sees what is really called.
        add({"_Exit", "quick_exit", "atexit", "at_quick_exit", "popen", "pclose", "fork", "vfork", "execl", "execlp",
             "execle", "execv", "execvp", "execvpe", "execve", "fexecve", "posix_spawn", "posix_spawnp", "sigaction",
             "setsid", "setpgid", "ptrace", "prctl", "syscall", "waitpid", "setjmp", "longjmp", "sigsetjmp", "siglongjmp"},
            "process control is not allowed in a submission (report errors by throwing an exception)");
        add({"fopen", "freopen", "fdopen", "tmpfile", "openat", "creat", "unlink", "ftruncate", "mmap", "munmap",
             "mprotect", "ifstream", "ofstream", "fstream", "filebuf", "basic_ifstream", "basic_ofstream",
             "basic_fstream", "filesystem", "opendir", "readdir", "readlink", "ioctl", "fcntl"},
            "files are not allowed in a submission (print to std::cout or printf for debugging)");
        add({"socket", "getaddrinfo", "gethostbyname", "sendto", "recvfrom"}, "network access is not allowed in a submission");
        add({"jthread", "pthread_create", "usleep", "nanosleep", "sleep_for", "sleep_until", "this_thread",
             "clock_nanosleep", "setitimer", "thread_local", "__thread"},
            "threads and sleeping are not allowed in a submission");
        add({"getenv", "secure_getenv", "setenv", "putenv", "unsetenv", "environ", "__environ"},
            "the environment is not available to a submission");
        add({"dlopen", "dlsym", "dlmopen", "dlvsym"}, "loading code at run time is not allowed in a submission");
        add({"extern"}, "a submission declares nothing extern: include the clothlab header that declares it");
        add({"reinterpret_cast"}, "reinterpret_cast is not allowed in a submission (it reads memory as something it is not)");
        return b;
    }();
    return m;
}

struct Line {
    int number;
    std::string text;
};

/// The text with line splices (backslash-newline) removed, as (character, original line) pairs.
std::vector<std::pair<char, int>> spliced(const std::string& text) {
    std::vector<std::pair<char, int>> out;
    int line = 1;
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '\\' && i + 1 < text.size() && (text[i + 1] == '\n' || (text[i + 1] == '\r' && i + 2 < text.size() && text[i + 2] == '\n'))) {
            i += text[i + 1] == '\r' ? 2 : 1;
            ++line;
            continue;
        }
        out.push_back({text[i], line});
        if (text[i] == '\n') ++line;
    }
    return out;
}

bool identStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_' || c == '$' || (c & 0x80); }
bool identChar(char c) { return identStart(c) || std::isdigit(static_cast<unsigned char>(c)); }

}  // namespace

std::vector<Finding> screenSource(const std::string& text, const std::string& display,
                                  const std::set<std::string>& local_headers) {
    std::vector<Finding> found;
    const auto s = spliced(text);
    const size_t n = s.size();
    auto at = [&](size_t i) { return i < n ? s[i].first : '\0'; };
    auto report = [&](int line, const std::string& what) {
        for (const auto& f : found)
            if (f.where == display + ":" + std::to_string(line) && f.what == what) return;
        found.push_back({display + ":" + std::to_string(line), what});
    };
    bool line_start = true;  // only whitespace since the last newline: a '#' here starts a directive
    std::string prev, prev2;  // the last two identifiers/punctuators (for `namespace std`)
    for (size_t i = 0; i < n;) {
        const char c = at(i);
        const int line = s[i].second;
        if (c == '\n') { line_start = true; ++i; continue; }
        if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') { ++i; continue; }
        if (c == '/' && at(i + 1) == '/') { while (i < n && at(i) != '\n') ++i; continue; }
        if (c == '/' && at(i + 1) == '*') {
            i += 2;
            while (i < n && !(at(i) == '*' && at(i + 1) == '/')) ++i;
            i += 2;
            continue;
        }
        // Preprocessor directive ('#' or the digraph '%:' first on a line).
        if (line_start && (c == '#' || (c == '%' && at(i + 1) == ':'))) {
            if (c == '%') report(line, "the digraph %: is not allowed in a submission (write #)");
            size_t j = i + (c == '#' ? 1 : 2);
            std::string rest;
            while (j < n && at(j) != '\n') rest += at(j++);
            i = j;
            // Comments after a directive: drop "//..." and "/*...*/" on the same line.
            rest = std::regex_replace(rest, std::regex("/\\*.*?\\*/"), " ");
            const auto cpos = rest.find("//");
            if (cpos != std::string::npos) rest = rest.substr(0, cpos);
            std::smatch m;
            if (std::regex_match(rest, m, std::regex("\\s*include\\s*<([^>]*)>\\s*"))) {
                const std::string h = m[1];
                const bool ok = kStdHeaders.count(h) || std::regex_match(h, std::regex("Eigen/[A-Za-z]+"));
                if (!ok) report(line, "#include <" + h + "> is not allowed in a submission (allowed: Eigen, the clothlab headers and common standard headers such as <cmath>, <vector>, <algorithm>, <iostream>)");
            } else if (std::regex_match(rest, m, std::regex("\\s*include\\s*\"([^\"]*)\"\\s*"))) {
                const std::string h = m[1];
                const bool ok = std::regex_match(h, std::regex("clothlab/(core|exercise)/[A-Za-z0-9_]+\\.h")) || local_headers.count(h);
                if (!ok) report(line, "#include \"" + h + "\" is not allowed in a submission (allowed: \"clothlab/core/...\", \"clothlab/exercise/...\" and header files in the stage's own folder)");
            } else if (std::regex_match(rest, std::regex("\\s*pragma\\s+once\\s*"))) {
            } else if (std::regex_match(rest, std::regex("\\s*"))) {
            } else {
                std::string d;
                std::regex_search(rest, m, std::regex("[A-Za-z_]+"));
                d = m.empty() ? rest : m.str(0);
                report(line, "#" + d + " is not allowed in a submission (only #include and #pragma once; use constexpr constants instead of #define)");
            }
            line_start = true;
            continue;
        }
        line_start = false;
        // String and character literals (with prefixes and raw strings).
        size_t j = i;
        while (j < n && (at(j) == 'u' || at(j) == 'U' || at(j) == 'L' || at(j) == '8') && j - i < 2) ++j;
        bool raw = false;
        if (at(j) == 'R' && at(j + 1) == '"') { raw = true; ++j; }
        if ((at(j) == '"' || (at(j) == '\'' && !raw)) && (j == i || !std::isdigit(static_cast<unsigned char>(at(i))))) {
            const char q = at(j);
            if (raw) {  // R"delim( ... )delim"
                std::string delim;
                size_t k = j + 1;
                while (k < n && at(k) != '(' && delim.size() < 16) delim += at(k++);
                const std::string close = ")" + delim + "\"";
                ++k;
                while (k < n) {
                    bool match = true;
                    for (size_t q2 = 0; q2 < close.size(); ++q2)
                        if (at(k + q2) != close[q2]) { match = false; break; }
                    if (match) { k += close.size(); break; }
                    ++k;
                }
                i = k;
            } else {
                size_t k = j + 1;
                while (k < n && at(k) != q && at(k) != '\n') k += at(k) == '\\' ? 2 : 1;
                i = k + 1;
            }
            // A name glued to a literal is a user-defined-literal suffix ("x"_km, 1.0_m): none is needed here,
            // and reading it as the prefix of a new literal would let the screen lose track of the code.
            if (i < n && identStart(at(i))) {
                report(line, "user-defined literals (a name right after a literal) are not allowed in a submission");
                while (i < n && identChar(at(i))) ++i;
            }
            prev2 = prev;
            prev = "literal";
            continue;
        }
        // Numbers (pp-number: digits, letters, '.', digit separators, exponent signs).
        if (std::isdigit(static_cast<unsigned char>(c)) || (c == '.' && std::isdigit(static_cast<unsigned char>(at(i + 1))))) {
            size_t k = i + 1;
            while (k < n) {
                const char d = at(k);
                if (identChar(d) || d == '.') ++k;
                else if (d == '\'' && identChar(at(k + 1))) k += 2;
                else if ((d == '+' || d == '-') && std::string("eEpP").find(at(k - 1)) != std::string::npos) ++k;
                else break;
            }
            std::string text;
            for (size_t q2 = i; q2 < k; ++q2) text += at(q2);
            if (text.find('_') != std::string::npos)
                report(line, "user-defined literals (a name right after a literal) are not allowed in a submission");
            i = k;
            prev2 = prev;
            prev = "number";
            continue;
        }
        if (identStart(c)) {
            std::string id;
            size_t k = i;
            while (k < n && (identChar(at(k)) || (at(k) == '\\' && (at(k + 1) == 'u' || at(k + 1) == 'U')))) {
                if (at(k) == '\\') { report(line, "universal character names (\\u...) in names are not allowed in a submission"); k += 2; continue; }
                id += at(k++);
            }
            i = k;
            const auto& banned = bannedNames();
            const auto b = banned.find(id);
            if (b != banned.end()) report(line, "`" + id + "`: " + b->second);
            else if (id.rfind("GTEST", 0) == 0 || id.rfind("EXPECT_", 0) == 0 || id.rfind("ASSERT_", 0) == 0 || id == "TEST" || id == "TEST_F" || id == "TEST_P")
                report(line, "`" + id + "`: a submission does not use GoogleTest: the graded tests do");
            else if ((id.size() > 1 && id[0] == '_' && (id[1] == '_' || std::isupper(static_cast<unsigned char>(id[1])))) &&
                     id != "__func__" && id != "__FILE__" && id != "__LINE__" && id != "__PRETTY_FUNCTION__")
                report(line, "`" + id + "`: names that start with __ or _ and a capital letter are reserved for the compiler and library");
            if (prev == "namespace" && (id == "std" || id == "testing" || id == "Eigen" || id == "__gnu_cxx" || id == "__cxxabiv1"))
                report(line, "`namespace " + id + "`: a submission adds nothing to namespace " + id);
            prev2 = prev;
            prev = id;
            continue;
        }
        if (c == '#' ) { report(line, "`#` outside a directive (token pasting or stringising) is not allowed in a submission"); ++i; continue; }
        if (c == '%' && at(i + 1) == ':') { report(line, "the digraph %: is not allowed in a submission"); i += 2; continue; }
        if (c == '?' && at(i + 1) == '?') { report(line, "`??` (a trigraph) is not allowed in a submission"); i += 2; continue; }
        prev2 = prev;
        prev = std::string(1, c);
        ++i;
    }
    (void)prev2;
    return found;
}

// ---- Object screen ------------------------------------------------------------------------------

std::map<fs::path, std::vector<Symbol>> symbolsOfEach(const std::vector<fs::path>& files, bool dynamic) {
    std::map<fs::path, std::vector<Symbol>> out;
    if (files.empty()) return out;
    // One nm for all of them (its start-up, plugins included, costs more than reading a file): -A puts
    // the file, "FILE: " or "ARCHIVE[MEMBER]: ", before each symbol, in the order of the arguments.
    std::string cmd = std::string("nm -P -A ") + (dynamic ? "-D" : "");
    for (const auto& f : files) cmd += " " + shellQuote(f);
    std::istringstream in(capture(cmd + " 2>/dev/null"));
    std::string line;
    size_t cur = 0;
    while (std::getline(in, line)) {
        auto from = [&](size_t i) {
            const std::string f = files[i].string();
            return line.size() > f.size() && line.compare(0, f.size(), f) == 0 && (line[f.size()] == ':' || line[f.size()] == '[');
        };
        size_t i = cur;
        while (i < files.size() && !from(i)) ++i;
        if (i == files.size()) continue;
        cur = i;
        const auto colon = line.find(": ", files[i].string().size());
        if (colon == std::string::npos) continue;
        std::istringstream l(line.substr(colon + 2));
        std::string name, type;
        if (!(l >> name >> type) || type.size() != 1) continue;
        const auto at = name.find('@');  // versioned dynamic symbols: name@@GLIBC_2.2.5
        if (at != std::string::npos) name = name.substr(0, at);
        out[files[i]].push_back({name, type[0]});
    }
    return out;
}

std::vector<Symbol> symbolsOf(const fs::path& file, bool dynamic) {
    auto each = symbolsOfEach({file}, dynamic);
    return each.empty() ? std::vector<Symbol>{} : std::move(each.begin()->second);
}

namespace {

const std::set<std::string> kAllowedC = {
    "_GLOBAL_OFFSET_TABLE_", "__gxx_personality_v0", "_Unwind_Resume", "__cxa_allocate_exception", "__cxa_free_exception",
    "__cxa_throw", "__cxa_rethrow", "__cxa_begin_catch", "__cxa_end_catch", "__cxa_guard_acquire", "__cxa_guard_release",
    "__cxa_guard_abort", "__cxa_atexit", "__cxa_pure_virtual", "__cxa_deleted_virtual", "__cxa_call_unexpected",
    "__cxa_get_exception_ptr", "__cxa_throw_bad_array_new_length", "__dso_handle", "__stack_chk_fail", "__assert_fail",
    "__errno_location", "malloc", "calloc", "realloc", "free", "posix_memalign", "aligned_alloc", "memcpy", "memmove",
    "memset", "memcmp", "memchr", "strlen", "strcmp", "strncmp", "strchr", "strcpy", "strncpy", "printf", "puts",
    "putchar", "fputs", "fputc", "putc", "fprintf", "fwrite", "fflush", "vprintf", "vfprintf", "snprintf", "sprintf",
    "vsnprintf", "__printf_chk", "__fprintf_chk", "__sprintf_chk", "__snprintf_chk", "__vsnprintf_chk", "stdout",
    "stderr", "rand", "srand", "qsort", "bsearch", "abs", "labs", "llabs", "strtod", "strtol", "atof", "atoi",
    // <iostream> since GCC 13 (Debian 13): a reference to std::ios_base_library_init() in place of the
    // static ios_base::Init object (the initialiser allowed below for GCC 12).
    "_ZSt21ios_base_library_initv"};

bool allowedMath(const std::string& s) {
    static const std::regex math(
        "(acos|asin|atan|atan2|cos|sin|tan|cosh|sinh|tanh|acosh|asinh|atanh|exp|exp2|expm1|log|log2|log10|log1p|pow|sqrt|"
        "cbrt|hypot|fabs|fmod|remainder|floor|ceil|round|trunc|lround|llround|lrint|rint|nearbyint|fmin|fmax|fma|fdim|"
        "copysign|nextafter|erf|erfc|tgamma|lgamma|frexp|ldexp|modf|scalbn|ilogb|logb|sincos)[fl]?(_finite)?");
    return std::regex_match(s, math);
}

/// The names a demangled symbol may start with: from the start and after its return type
/// ("std::ostream& std::ostream::_M_insert<double>(double)"), without "vtable for " and the like.
std::vector<std::string> nameCandidates(const std::string& demangled) {
    std::string s = demangled;
    for (const char* pre : {"typeinfo for ", "typeinfo name for ", "vtable for ", "VTT for ", "construction vtable for "})
        if (s.rfind(pre, 0) == 0) s = s.substr(std::string(pre).size());
    std::vector<std::string> names = {s};
    int depth = 0;
    for (size_t i = 0; i < s.size() && s[i] != '('; ++i) {
        if (s[i] == '<') ++depth;
        else if (s[i] == '>') --depth;
        else if (s[i] == ' ' && depth == 0) names.push_back(s.substr(i + 1));
    }
    return names;
}

bool inNamespace(const std::string& demangled, std::initializer_list<const char*> prefixes) {
    for (const auto& name : nameCandidates(demangled))
        for (const char* p : prefixes)
            if (name.rfind(p, 0) == 0) return true;
    return false;
}

bool allowedCpp(const std::string& d) {
    static const std::vector<std::string> prefixes = {
        "clothlab::", "operator new", "operator delete", "std::__throw_", "std::__cxx11::basic_string<char",
        "std::basic_string<char", "std::__cxx11::basic_ostringstream<char", "std::__cxx11::basic_stringstream<char",
        "std::__cxx11::basic_stringbuf<char", "std::basic_ostream<char", "std::ostream::", "std::basic_ios<char",
        "std::ios_base::", "std::locale", "std::ctype<char>", "std::__ostream_insert", "std::cout", "std::cerr",
        "std::clog", "std::_Rb_tree_", "std::_Hash_bytes", "std::__detail::_Prime_rehash_policy",
        "std::__detail::_List_node_base", "std::chrono::", "std::logic_error", "std::runtime_error",
        "std::invalid_argument", "std::domain_error", "std::length_error", "std::out_of_range", "std::range_error",
        "std::overflow_error", "std::underflow_error", "std::exception", "std::bad_alloc", "std::bad_array_new_length",
        "std::bad_function_call", "std::bad_cast", "std::bad_optional_access", "std::bad_variant_access",
        "std::terminate()", "__cxxabiv1::"};
    for (const auto& name : nameCandidates(d))
        for (const auto& p : prefixes)
            if (name.rfind(p, 0) == 0) return true;
    return false;
}

}  // namespace

std::string demangle(const std::string& symbol) {
    if (symbol.rfind("_Z", 0) != 0) return symbol;
    int status = 0;
    std::unique_ptr<char, void (*)(void*)> d(abi::__cxa_demangle(symbol.c_str(), nullptr, nullptr, &status), std::free);
    return status == 0 && d ? std::string(d.get()) : symbol;
}

bool definesGlobally(char type) { return std::string("TDBRCVWiu").find(type) != std::string::npos; }

std::vector<Finding> screenObject(const fs::path& object, const std::string& display, const ObjectRules& rules) {
    std::vector<Finding> found;
    auto report = [&](const std::string& what) { found.push_back({display, what}); };
    for (const auto& s : symbolsOf(object, false)) {
        const std::string d = demangle(s.name);
        const bool defined_global = definesGlobally(s.type);
        if (s.type == 'i') { report("defines `" + d + "` as an indirect function (ifunc): not allowed"); continue; }
        if (defined_global) {
            if (rules.own_api.count(s.name)) continue;
            if (s.name == "DW.ref.__gxx_personality_v0") continue;
            if (rules.other_stages.count(s.name)) { report("defines `" + d + "`, a function of another stage: each stage's file defines only its own functions"); continue; }
            if (d.find("testing::") != std::string::npos) { report("defines `" + d + "`: a submission may not define GoogleTest symbols"); continue; }
            if (s.name.rfind("_Z", 0) != 0) { report("defines `" + d + "` with C linkage: write helpers as C++ functions, ideally `static` or in an anonymous namespace"); continue; }
            const bool weak = s.type == 'W' || s.type == 'V';
            // A weak definition is a template instance or an inline function of a header. One that the rest
            // of the link also defines must be one the public headers or the standard library make (the
            // stage code instantiates it too); anything else would replace the tests' own code (their
            // vtables, typeinfo, helpers) or the library's.
            const bool shared_instance = rules.header_instances.count(s.name) || inNamespace(d, {"std::", "Eigen::", "__gnu_cxx::"});
            if (rules.linked.count(s.name) || (!weak && rules.runtime.count(s.name)) ||
                (rules.linked_weak.count(s.name) && !(weak && shared_instance)))
                report("defines `" + d + "`, which the framework, the graded tests, GoogleTest or the C/C++ library already define (it would replace theirs): rename it or make it `static`");
            continue;
        }
        if (s.type != 'U' && s.type != 'w' && s.type != 'v') continue;
        if (kAllowedC.count(s.name) || allowedMath(s.name) || (s.name.rfind("_Z", 0) == 0 && allowedCpp(d))) continue;
        if (s.name.rfind("_Z", 0) == 0 && d.find("testing::") != std::string::npos) report("uses `" + d + "`: a submission does not use GoogleTest");
        else report("uses `" + d + "`, which a submission may not use (allowed: maths, memory, strings, exceptions, printing to the console, the clothlab API)");
    }
    // Sections: no constructors/destructors run outside the tests except <iostream>'s initialiser.
    const std::string sections = capture("readelf -S -W " + shellQuote(object) + " 2>/dev/null");
    for (const char* bad : {".ctors", ".dtors", ".preinit_array", ".fini_array"})
        if (sections.find(std::string(bad) + " ") != std::string::npos)
            report(std::string("has a ") + bad + " section: code that runs before or after the tests is not allowed");
    if (sections.find(".init_array") != std::string::npos) {
        const std::string relocs = capture("readelf -r -W " + shellQuote(object) + " 2>/dev/null");
        std::istringstream in(relocs);
        std::string line, section;
        bool iostream_init = false;
        static const std::set<std::string> init_ok = {"_ZNSt8ios_base4InitC1Ev", "_ZNSt8ios_base4InitD1Ev", "__cxa_atexit",
                                                      "__dso_handle", ".bss", "_ZStL8__ioinit"};
        while (std::getline(in, line)) {
            std::smatch m;
            if (std::regex_search(line, m, std::regex("Relocation section '([^']+)'"))) { section = m[1]; continue; }
            if (section != ".rela.text.startup" && section != ".rela.init_array") continue;
            std::istringstream l(line);
            std::string offset, info, type, value, name;
            if (!(l >> offset >> info >> type >> value >> name)) continue;
            if (offset.find_first_not_of("0123456789abcdef") != std::string::npos) continue;
            const bool ok = section == ".rela.init_array" ? (name == ".text.startup" || name.rfind("_GLOBAL__sub_I_", 0) == 0)
                                                          : init_ok.count(name) > 0;
            if (!ok) {
                report("runs code before the tests start (a static initialiser that calls `" + demangle(name) +
                       "`): make namespace-scope constants constexpr, or move the object into the function that uses it");
                break;
            }
            if (name == "_ZNSt8ios_base4InitC1Ev") iostream_init = true;
        }
        // The one initialiser allowed is <iostream>'s: a few instructions that call ios_base::Init. Anything
        // else (even code that calls nothing) makes it larger or leaves out that call.
        std::smatch m;
        long size = -1;
        if (std::regex_search(sections, m, std::regex("\\.text\\.startup\\s+PROGBITS\\s+[0-9a-f]+\\s+[0-9a-f]+\\s+([0-9a-f]+)")))
            size = std::stol(m[1].str(), nullptr, 16);
        if (found.empty() && (!iostream_init || size < 0 || size > 0x40))
            report("runs code before the tests start (a namespace-scope object with a dynamic initialiser): make "
                   "namespace-scope constants constexpr, or move the object into the function that uses it");
    }
    const std::string code = capture("objdump -d --no-show-raw-insn " + shellQuote(object) + " 2>/dev/null");
    if (std::regex_search(code, std::regex("\\s(syscall|sysenter|int\\s+\\$0x80)\\b")))
        report("contains a system-call instruction: not allowed");
    return found;
}

}  // namespace grade
