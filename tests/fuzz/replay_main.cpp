// Runs the fuzz target (scene_fuzz.cpp) once on each file given, or on each file in each folder
// given, without libFuzzer: the build with g++ (sanitize.fuzz_replay in ./lab test) replays the
// seeds and the regressions this way. The target aborts on the first input that breaks the contract.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int main(int argc, char** argv) {
    namespace fs = std::filesystem;
    std::set<fs::path> files;  // sorted: the same order every run
    for (int i = 1; i < argc; ++i) {
        if (fs::is_directory(argv[i])) {
            for (const auto& e : fs::recursive_directory_iterator(argv[i]))
                if (e.is_regular_file() && e.path().extension() != ".expect") files.insert(e.path());
        } else {
            files.insert(argv[i]);
        }
    }
    for (const fs::path& f : files) {
        std::ifstream in(f, std::ios::binary);
        if (!in) {
            std::fprintf(stderr, "error: %s: (file): cannot open the file\n", f.c_str());
            return 1;
        }
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
    }
    std::printf("replayed %zu inputs: every one loads or gives one error line\n", files.size());
    return files.empty() ? 1 : 0;
}
