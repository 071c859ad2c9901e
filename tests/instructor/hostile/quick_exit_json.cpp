// HOSTILE FIXTURE quick_exit_json (attack class 2: exit-time hook forges the JSON result).
// The stage functions register an std::at_quick_exit handler that writes a passing JSON result, then call std::quick_exit(0) from inside the test.
// The hardened grader must give this file 0 points on stage 04.
//@head
#include <unistd.h>
#include <cstdio>
#include <string>
#include <cstdlib>


//@use forger

namespace {
void hostileQuickExit() { hostileForgePass(); }
[[noreturn]] void hostileLeave() {
    std::at_quick_exit(&hostileQuickExit);
    std::quick_exit(0);  // inside the test: no failure is ever recorded, the handler writes a pass
}
}  // namespace
//@each
    hostileLeave();
