// Small helpers shared by the graded tests (messages for students).
#pragma once
#include <sstream>
#include <string>

#include "clothlab/core/types.h"

namespace clothlab::testing_util {

/// "(x, y, z)" for failure messages.
inline std::string str(const Vec3& v) {
    std::ostringstream s;
    s << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
    return s.str();
}

}  // namespace clothlab::testing_util
