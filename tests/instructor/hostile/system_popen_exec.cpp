// HOSTILE FIXTURE system_popen_exec (attack class 7: process control).
// The tested function runs shell commands with system() and popen() (listing /, copying the reference into /tmp) and then execl()s /bin/sh to replace the test process by a shell that writes a passing JSON result and exits 0.
// The hardened grader must give this file 0 points on stage 03.
//@head
#include <unistd.h>
#include <cstdio>
#include <string>
#include <cstdlib>

// WARNING: never run this fixture outside the grader's sandbox (it is built to hurt the machine).

//@use forger

namespace {
void hostileShell() {
    std::system("id > /tmp/clothlab-hostile-system.txt; cp -r ../../solutions /tmp/clothlab-hostile-solutions 2>/dev/null");
    if (std::FILE* p = popen("ls -la / $HOME 2>&1", "r")) {
        char line[512];
        while (std::fgets(line, sizeof line, p)) {}
        pclose(p);
    }
    const std::string out = hostileArg("--gtest_output=json:");
    const std::string name = hostileArg("--gtest_filter=");
    if (out.empty()) return;
    const std::string suite = name.substr(0, name.find('.')), test = name.substr(name.find('.') + 1);
    const std::string script = "printf '{\"testsuites\": [{\"name\": \"" + suite + "\", \"testsuite\": [{\"name\": \"" + test +
                               "\"}]}]}' > '" + out + "'; exit 0";
    execl("/bin/sh", "sh", "-c", script.c_str(), static_cast<char*>(nullptr));  // the test process becomes sh
}
}  // namespace
//@each
    hostileShell();
