/// @file stub_advice.h
/// @brief What a program tells a student whose scene reaches an unfinished task.
#pragma once
#include <string>

namespace clothlab {

/// The stages that have a reference here (solutions/, or the student copy's reference objects),
/// e.g. "05,06". Written by the build (cmake/reference_stages.cpp.in); a program that calls
/// stubAdvice() with its defaults links clothlab_reference_stages.
const char* referenceStagesHere();

/// The stages this build links the reference for (`./lab build --reference 05,06`), e.g. "05,06".
const char* referenceStagesUsed();

/// Which code each stage of this build runs, "01_hooke=reference;02_mfn=student;" (the app's stage panel).
const char* stageCode();

/// Advice that works in this copy for "not implemented: exercise N.M <name>" (NotImplemented::what()):
/// finish task N.M (with the hint and grade commands); where stage NN has a reference (`have`), also
/// the exact command that runs it with the reference for NN and the stages `used` already takes from it.
/// @param what  the exception's text
/// @param have  stages with a reference here, "01,02"
/// @param used  stages this build links the reference for, "05,06"
/// @return      "  (finish task N.M in exercises/NN_*/ ...)", one line
std::string stubAdvice(const std::string& what, const std::string& have = referenceStagesHere(),
                       const std::string& used = referenceStagesUsed());

}  // namespace clothlab
