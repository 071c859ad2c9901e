// Stage 01 — Hooke spring and time integration.
// Task sheet: exercises/01_hooke/README.md
// Formulas and argument units: framework/include/clothlab/exercise/01_hooke.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 01
//
// ATTACK: the whole submission is one #include. "../../solutions/..." does not exist next to the
// submission, but the compiler also tries it under every -I directory: framework/include/../../
// is the root of the instructor's tree, so this compiles the reference solution.
#include "../../solutions/01_hooke/hooke.cpp"
