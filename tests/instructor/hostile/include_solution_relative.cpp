// HOSTILE FIXTURE include_solution_relative (attack class 4: #include of the instructor's files).
// The whole submission is one #include. "../../solutions/..." does not exist next to the submission,
// but the compiler also tries it under every -I directory: framework/include/../../ is the root of the
// instructor's tree, so this compiles the reference solution. The hardened grader gives it 0 points.
//@no-stub
#include "../../solutions/01_hooke/hooke.cpp"
