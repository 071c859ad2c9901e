// Stage 02 stub + a namespace-scope static whose initialiser dereferences a null pointer.
// The initialiser has no outside call and no relocation (at most `.bss`, its own variable), so the
// object screen's .init_array check (calls in .text.startup limited to ios_base::Init,
// __cxa_atexit, .bss) accepts it: code DOES run before main(). Here it only crashes every test
// (status 139 before `start`, 0 points); a relocation-free initialiser could equally find libc
// through the return addresses on its stack (see channel_forge_libc_walk) and read the channel
// secret from fd 3 before the graded main() does. If the grader ever lists tests of a submission's
// binary (gradeBinary's --gtest_list_tests + die()), this same file stops the whole run.
//@head


namespace {
int crashOnLoad() {
    volatile int* volatile nowhere = nullptr;
    *nowhere = 1;  // SIGSEGV before main()
    return 0;
}
int loaded = crashOnLoad();
}  // namespace
