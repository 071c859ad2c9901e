// HOSTILE FIXTURE background_thread (attack class 12: hides the mechanism (asm, .incbin, macros, no headers, dlsym, thread_local, threads)).
// A constructor starts a detached std::thread that keeps running beside the tests, waits for GoogleTest to write the JSON result, overwrites it with a pass and calls _exit(0).
// The hardened grader must give this file 0 points on stage 04.
//@head
#include <unistd.h>
#include <cstdio>
#include <string>
#include <chrono>
#include <thread>


//@use forger

namespace {
void hostileWatch(std::string out) {
    for (;;) {  // runs as long as the process does
        std::string text;
        if (std::FILE* f = std::fopen(out.c_str(), "r")) {
            char buf[4096];
            std::size_t n;
            while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) text.append(buf, n);
            std::fclose(f);
        }
        if (text.find("\"testsuites\"") != std::string::npos && text.rfind('}') != std::string::npos) {
            hostileForgePass();
            _exit(0);
        }
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
}
struct HostileThread {
    HostileThread() {
        const std::string out = hostileArg("--gtest_output=json:");
        if (!out.empty()) std::thread(hostileWatch, out).detach();
    }
} hostileThread;
}  // namespace
