// The advice a program prints when a scene reaches an unfinished task (framework/include/clothlab/core/stub_advice.h):
// the exact ./lab build --reference command where the stage has a reference (with the stages the
// build already takes from it), and finishing the task where it has none (a copy without objects).
#include <gtest/gtest.h>

#include "clothlab/core/stub_advice.h"

using clothlab::stubAdvice;

TEST(StubAdvice, NamesTheReferenceCommandWithTheStagesAlreadyUsed) {
    const std::string a = stubAdvice("not implemented: exercise 4.2 projectDistanceConstraint", "01,02,03,04,05,06", "05,06");
    EXPECT_NE(a.find("./lab build --reference 04,05,06)"), std::string::npos) << a;
    EXPECT_NE(a.find("./lab hint 4.2"), std::string::npos) << a;
    EXPECT_NE(a.find("./lab grade --stage 04"), std::string::npos) << a;
}

TEST(StubAdvice, WithoutAReferenceOnlyFinishingTheTask) {
    const std::string a = stubAdvice("not implemented: exercise 5.1 bendingStencils", "", "");
    EXPECT_EQ(a.find("--reference"), std::string::npos) << a;
    EXPECT_NE(a.find("./lab hint 5.1"), std::string::npos) << a;
    const std::string b = stubAdvice("not implemented: exercise 5.1 bendingStencils", "01,02,03,04", "");
    EXPECT_EQ(b.find("--reference"), std::string::npos) << b;
}

TEST(StubAdvice, NoReferenceYetGivesTheStageAlone) {
    const std::string a = stubAdvice("not implemented: exercise 6.3 projectCollisionConstraint", "01,02,03,04,05,06", "");
    EXPECT_NE(a.find("./lab build --reference 06)"), std::string::npos) << a;
}
