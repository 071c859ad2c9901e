// The grading kit's precompiled header (cmake/grade_kit.cmake builds it into
// build/grade-kit/include/clothlab_precompiled.h.gch with the kit's compiler and flags).
// clothlab-grade compiles a submission file with -include of this header: Eigen is then read from
// the .gch instead of being parsed again for every stage (most of a stage's compile time).
// It holds exactly what the stage headers include (clothlab/core/types.h, which includes
// Eigen/Core and Eigen/Geometry; <vector>, <functional>), so a submission sees no name here that
// its stage header would not show it. A file that defines a macro before its first #include
// (EIGEN_... settings) is compiled without it (submission.cpp, usePrecompiledHeader).
// If the .gch does not match the compile (another compiler or other flags), GCC reads this
// header as text instead: slower, same result.
#ifndef CLOTHLAB_PRECOMPILED_H
#define CLOTHLAB_PRECOMPILED_H
#include <functional>
#include <vector>

#include "clothlab/core/types.h"
#endif
