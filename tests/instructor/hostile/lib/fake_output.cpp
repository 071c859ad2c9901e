// GoogleTest's console lines of one passing test (//@use fake_output), printf format with the test
// name twice. Not an attack by itself.
namespace {
const char* const kHostileFake =
    "[==========] Running 1 test from 1 test suite.\n"
    "[----------] Global test environment set-up.\n"
    "[ RUN      ] %s\n"
    "[       OK ] %s (0 ms)\n"
    "[==========] 1 test from 1 test suite ran. (0 ms total)\n"
    "[  PASSED  ] 1 test.\n";
}  // namespace
