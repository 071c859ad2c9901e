// HOSTILE FIXTURE gtest_symbols (attack class 3: GoogleTest machinery (listener, own main, testing:: symbols)).
// Defines symbols in namespace testing (explicit specialisations of testing::internal::CmpHelperLT/LE/GT/GE/NE that always return AssertionSuccess) and makes iterationStiffness and pbdStep return without throwing (a no-op there earns nothing by itself), so the linker may take its always-true comparisons for the tests' EXPECT_LT etc.
// The hardened grader must give this file 0 points on stage 03.
//@head
#include <gtest/gtest.h>


// Explicit specialisations are strong symbols; the tests' implicit instantiations are weak (COMDAT),
// so the linker keeps these wherever the test did not inline its own copy.
namespace testing {
namespace internal {
#define HOSTILE_ALWAYS(op, T1, T2)                                                              \
    template <>                                                                                  \
    AssertionResult CmpHelper##op<T1, T2>(const char*, const char*, const T1&, const T2&) {      \
        return AssertionSuccess();                                                               \
    }
HOSTILE_ALWAYS(LT, double, double)
HOSTILE_ALWAYS(LE, double, double)
HOSTILE_ALWAYS(GT, double, double)
HOSTILE_ALWAYS(GE, double, double)
HOSTILE_ALWAYS(NE, double, double)
HOSTILE_ALWAYS(LT, int, int)
HOSTILE_ALWAYS(LE, int, int)
HOSTILE_ALWAYS(GT, int, int)
HOSTILE_ALWAYS(GE, int, int)
#undef HOSTILE_ALWAYS
}  // namespace internal
}  // namespace testing
//@task 3.2
    return {};  // no exception: the comparisons decide
//@task 3.3
    return;  // no exception: the comparisons decide
