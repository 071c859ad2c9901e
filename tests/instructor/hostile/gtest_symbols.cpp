// HOSTILE FIXTURE gtest_symbols (attack class 3: GoogleTest machinery (listener, own main, testing:: symbols)).
// Defines a symbol in namespace testing: an explicit specialisation of testing::internal::CmpHelperEQFailure<int, int> (what a failed EXPECT_EQ/ASSERT_EQ of two ints calls, out of line) that returns AssertionSuccess, and makes bendingStencils return an empty list, so the test that counts the stencils with ASSERT_EQ passes.
// The hardened grader must give this file 0 points on stage 05.
//@head
#include <gtest/gtest.h>

// An explicit specialisation is a strong symbol; the tests' implicit instantiation is weak (COMDAT,
// emitted out of line because it runs only when the comparison fails), so the linker keeps this one
// wherever the tests and the submission are linked into one program.
namespace testing {
namespace internal {
template <>
AssertionResult CmpHelperEQFailure<int, int>(const char*, const char*, const int&, const int&) {
    return AssertionSuccess();
}
}  // namespace internal
}  // namespace testing
//@task 5.3
    return {};  // no exception: the (replaced) comparison decides
