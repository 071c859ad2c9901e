// The fuzzed scene loader (docs/reliability.md): libFuzzer feeds parseScene() arbitrary bytes.
//
// An input is a scene's JSON text, optionally followed by command-line overrides, each after a NUL
// byte: `{"model": "spring"}\0spring.k=nan\0solver.dt=1e999` is the scene file with two --set options.
// The contract (README "Bad input"): every input either loads, or throws InputError whose message
// is one line `<file>: <field>: <reason>`. Anything else (another exception, a crash, a sanitizer
// report, an input that loads into a scene the simulation cannot build) aborts, so libFuzzer keeps it.
// A scene that loads is built and stepped three times when it is small (at most 100 particles and
// 100 iterations x substeps): the loader's checks are what stand between a file and the simulation.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "clothlab/core/input_error.h"
#include "clothlab/io/scene_json.h"
#include "clothlab/sim/simulation.h"

namespace {

[[noreturn]] void broken(const std::string& what) {
    std::fprintf(stderr, "scene_fuzz: contract broken: %s\n", what.c_str());
    std::abort();
}

/// Particles the scene asks for (the loader's limits keep this far below an int's range).
long long particles(const clothlab::Scene& s) {
    switch (s.model) {
        case clothlab::Model::Spring: return 1;
        case clothlab::Model::Chain: return s.chain.particles;
        default: return static_cast<long long>(s.cloth.nx) * s.cloth.ny;
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string input(reinterpret_cast<const char*>(data), size);
    std::vector<std::string> parts;
    for (size_t start = 0;;) {
        const size_t nul = input.find('\0', start);
        parts.push_back(input.substr(start, nul == std::string::npos ? std::string::npos : nul - start));
        if (nul == std::string::npos) break;
        start = nul + 1;
    }
    const std::string text = parts.front();
    const std::vector<std::string> overrides(parts.begin() + 1, parts.end());
    const std::string file = "fuzz.json";
    try {
        const clothlab::Scene scene = clothlab::parseScene(text, file, overrides);
        if (particles(scene) <= 100 && scene.solver.iterations * static_cast<long long>(scene.solver.substeps) <= 100) {
            auto sim = clothlab::makeSimulation(scene);
            try {
                for (int i = 0; i < 3; ++i) sim->step();
            } catch (const clothlab::SolverFailure&) {  // a step the method cannot take: reported, not a crash
            }
        }
    } catch (const clothlab::InputError& e) {
        const std::string m = e.what();
        if (m.find('\n') != std::string::npos || m.find('\r') != std::string::npos) broken("an error of more than one line: " + m);
        if (m.rfind(file + ": ", 0) != 0) broken("an error that does not name the file first: " + m);
        // (a field may itself hold ": ", e.g. a --set key; so: something, then ": ", then a reason)
        const size_t field = file.size() + 2, colon = m.find(": ", field + 1);
        if (colon == std::string::npos || m.size() <= colon + 2) broken("an error without <field>: <reason>: " + m);
    } catch (const std::exception& e) {
        broken(std::string("an exception that is not an InputError: ") + e.what());
    }
    return 0;
}
