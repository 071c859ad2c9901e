# Typical mistakes in stage 04. Each is the reference with one edit; ./lab test proves that
# the graded tests catch every one (stage_04.mistake_caught.<name>). Included from tests/CMakeLists.txt.
clothlab_mistake(sign_flipped FILE distance.cpp
  FIND "return {-w1 * s, w2 * s};" REPLACE "return {w1 * s, -w2 * s};"
  WHY "pushes a stretched constraint further apart")
clothlab_mistake(weights_swapped FILE distance.cpp
  FIND "return {-w1 * s, w2 * s};" REPLACE "return {-w2 * s, w1 * s};"
  WHY "heavy particles move more than light ones: momentum is created")
clothlab_mistake(no_mass_weighting FILE distance.cpp
  FIND "const Vec3 s = (k * (len - d) / (wsum * len)) * e;" REPLACE "const Vec3 s = (k * (len - d) / (2.0 * len)) * e; (void)wsum;"
  WHY "divides by 2 instead of w1 + w2: light particles overshoot (the cloth explodes), heavy ones move too little")
clothlab_mistake(weighting_left_out FILE distance.cpp
  FIND "return {-w1 * s, w2 * s};" REPLACE "return {-0.5 * wsum * s, 0.5 * wsum * s};"
  WHY "splits every correction half-half, whatever the inverse masses: pinned particles move")
clothlab_mistake(missing_normalisation FILE distance.cpp
  FIND "const Vec3 s = (k * (len - d) / (wsum * len)) * e;" REPLACE "const Vec3 s = (k * (len - d) / wsum) * e;"
  WHY "uses p1 - p2 instead of the unit direction n")
clothlab_mistake(no_degenerate_guard FILE distance.cpp
  FIND "if (len < 1e-12 || wsum <= 0.0) return {Vec3::Zero(), Vec3::Zero()};" REPLACE ""
  WHY "divides by zero for coincident points or two pinned particles")
clothlab_mistake(stiffness_ignored FILE distance.cpp
  FIND "const Vec3 s = (k * (len - d) / (wsum * len)) * e;" REPLACE "const Vec3 s = ((len - d) / (wsum * len)) * e;"
  WHY "k is not applied")
clothlab_mistake(gradient_not_normalised FILE distance.cpp
  FIND "    return e / len;" REPLACE "    return e;"
  WHY "gradient p1 - p2 instead of the unit vector")
clothlab_mistake(rest_length_ignored FILE distance.cpp
  FIND "return (p1 - p2).norm() - d;" REPLACE "return (p1 - p2).norm();"
  WHY "C without the rest length")
clothlab_mistake(gradient_absolute_epsilon FILE distance.cpp
  FIND "if (len < 1e-12) return Vec3::Zero();" REPLACE "if (len < 1e-6) return Vec3::Zero();"
  WHY "an absolute epsilon of a micrometre: nearly coincident points get no gradient")
clothlab_mistake(projection_absolute_epsilon FILE distance.cpp
  FIND "if (len < 1e-12 || wsum <= 0.0)" REPLACE "if (len < 1e-6 || wsum <= 0.0)"
  WHY "an absolute epsilon of a micrometre: a nearly collapsed constraint is not pushed apart")
# Bonus 4.4 (long-range attachments)
clothlab_mistake(tether_pushes_out FILE distance.cpp
  FIND "if (len <= L) return Vec3::Zero();" REPLACE ""
  WHY "a two-sided tether: a slack one pushes its particle out to the length L")
clothlab_mistake(tether_to_any_particle FILE distance.cpp
  FIND "if (w[a] == 0.0 && dist < nearest) {" REPLACE "if (a != i && dist < nearest) {"
  WHY "anchors each particle to its nearest neighbour, pinned or not")
clothlab_mistake(tether_tie_highest_index FILE distance.cpp
  FIND "if (w[a] == 0.0 && dist < nearest) {" REPLACE "if (w[a] == 0.0 && dist <= nearest) {"
  WHY "of equally near pins takes the last one")
clothlab_mistake(tether_not_normalised FILE distance.cpp
  FIND "return -((len - L) / len) * e;" REPLACE "return -(len - L) * e;"
  WHY "moves along p - a instead of the unit direction: the wrong distance")
