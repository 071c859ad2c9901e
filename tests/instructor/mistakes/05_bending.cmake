# Typical mistakes in stage 05. Each is the reference with one edit; ./lab test proves that
# the graded tests catch every one (stage_05.mistake_caught.<name>). Included from tests/CMakeLists.txt.
clothlab_mistake(paper_sign FILE bending.cpp
  FIND "const double s = f * C;" REPLACE "const double s = -f * C;"
  WHY "the minus sign printed on the slides, used with q_i = dd/dp_i: bends away from the rest angle")
clothlab_mistake(q1_not_balanced FILE bending.cpp
  FIND "g.q1 = -g.q2 - g.q3 - g.q4;" REPLACE "g.q1 = -g.q2 - g.q3;"
  WHY "q1 forgets q4: momentum is created")
clothlab_mistake(q2_second_term_sign FILE bending.cpp
  FIND "g.q2 = b.cross(e1) + c.cross(e2);" REPLACE "g.q2 = b.cross(e1) - c.cross(e2);"
  WHY "sign slip in the second half of q2")
clothlab_mistake(q_copied_from_slides FILE bending.cpp
  FIND "g.q3 = e1.cross(a);" REPLACE "g.q3 = a.cross(e1);"
  WHY "q3 as printed on the slides is -dd/dp3")
clothlab_mistake(not_relative_to_p1 FILE bending.cpp
  FIND "const Vec3 a = p2 - p1, b = p3 - p1, c = p4 - p1;" REPLACE "const Vec3 a = p2, b = p3, c = p4;"
  WHY "forgets to take the positions relative to p1")
clothlab_mistake(no_pinned_guard FILE bending.cpp
  FIND "if (denom < 1e-24) return r;" REPLACE ""
  WHY "all particles pinned: division by zero gives NaN")
clothlab_mistake(no_zero_area_guard FILE bending.cpp
  FIND "if (L1 < 1e-24 || L2 < 1e-24) return g;" REPLACE ""
  WHY "zero-area triangle: division by zero gives NaN")
clothlab_mistake(mass_not_in_denominator FILE bending.cpp
  FIND "const double denom = w1 * g.q1.squaredNorm() + w2 * g.q2.squaredNorm() + w3 * g.q3.squaredNorm() +
                         w4 * g.q4.squaredNorm();"
  REPLACE "const double denom = g.q1.squaredNorm() + g.q2.squaredNorm() + g.q3.squaredNorm() + g.q4.squaredNorm();"
  WHY "the denominator ignores the inverse masses (pinned particles' share is lost)")
clothlab_mistake(stencil_wrong_opposite FILE bending.cpp
  FIND "s.i3 = it->second;" REPLACE "s.i3 = key.first == a ? b : a;"
  WHY "uses an edge vertex instead of the opposite vertex")
clothlab_mistake(rest_angle_zero FILE bending.cpp
  FIND "s.phi0 = g.valid ? std::acos(g.d) : M_PI;" REPLACE "s.phi0 = 0.0;"
  WHY "rest angle 0 instead of the initial shape's angle")
