// The screen: what a submission may not contain, found before it runs.
//
// Source screen (before compiling): a tokenizer (comments, strings and digit separators handled)
// rejects preprocessor tricks (#define, #if, #pragma, token pasting, universal character names,
// digraphs that spell #), includes other than the public clothlab headers, Eigen, a list of
// standard headers and the stage's own files, and names a submission has no use for: its own
// main or GoogleTest, inline assembly and attributes, process control, files, sockets, threads,
// the environment, clocks to sleep on, reserved identifiers, namespaces std/testing/Eigen opened.
// Each finding names the file, the line and what to do instead.
//
// Object screen (after compiling, sees through anything the source screen missed): the object
// file may define only the stage's own functions and helpers that clash with nothing else in the
// link (no interposition of libc, libstdc++, GoogleTest, the framework or another stage); it may
// use only an allow-list of outside symbols (maths, memory, exceptions, strings, console output,
// clothlab's API); it may have no static initialiser other than <iostream>'s, no .ctors/.fini
// sections and no system-call instruction.
#pragma once
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace grade {

namespace fs = std::filesystem;

struct Finding {
    std::string where;  ///< "01_hooke/hooke.cpp:12" or "01_hooke/hooke.cpp"
    std::string what;   ///< one sentence: what is not allowed and what to do instead
};

/// Screens one source file. `display` is its name in messages; `local_headers`: headers the
/// student may include with "name.h" (the stage folder's own .h/.hpp files).
std::vector<Finding> screenSource(const std::string& text, const std::string& display,
                                  const std::set<std::string>& local_headers);

struct ObjectRules {
    std::set<std::string> own_api;        ///< mangled names the stage defines (from the stub's object)
    std::set<std::string> runtime;        ///< names the C/C++ runtime libraries define (libc, libm, libstdc++, libgcc_s)
    std::set<std::string> linked;         ///< names defined (not weakly) by the rest of the link: framework, GoogleTest, tests
    std::set<std::string> linked_weak;    ///< names the rest of the link defines weakly (templates, inline functions, vtables)
    std::set<std::string> header_instances;  ///< weak names the stage code (stubs, references) defines: public-header instances
    std::set<std::string> other_stages;   ///< mangled names of other stages' functions (better message)
};

/// Screens one object file compiled from the submission (runs nm, readelf and objdump).
std::vector<Finding> screenObject(const fs::path& object, const std::string& display, const ObjectRules& rules);

struct Symbol {
    std::string name;  ///< mangled, without a version suffix (@@GLIBC_2.2.5)
    char type;         ///< nm's letter: T, W, U, ...
};

/// Every symbol nm lists for an object, archive or (dynamic) shared library.
std::vector<Symbol> symbolsOf(const fs::path& file, bool dynamic = false);

/// symbolsOf for many files with one nm run (a file nm cannot read maps to no symbols).
std::map<fs::path, std::vector<Symbol>> symbolsOfEach(const std::vector<fs::path>& files, bool dynamic = false);

/// True for nm's letters of a global definition (text, data, bss, read-only, common, weak, ifunc, unique).
bool definesGlobally(char type);

/// "symbol" demangled (or itself when it is not a C++ name).
std::string demangle(const std::string& symbol);

}  // namespace grade
