# Typical mistakes in stage 05. Each is the reference with one edit; ./lab test proves that
# the graded tests catch every one (stage_05.mistake_caught.<name>). Included from tests/CMakeLists.txt.
clothlab_mistake(paper_sign FILE bending.cpp
  FIND "const double s = k * g.sinPhi * C / sumWq2;" REPLACE "const double s = -k * g.sinPhi * C / sumWq2;"
  WHY "the minus sign printed on the slides, used with q_i = dd/dp_i: bends away from the rest angle")
clothlab_mistake(q1_not_balanced FILE bending.cpp
  FIND "g.q1 = -g.q2 - g.q3 - g.q4;" REPLACE "g.q1 = -g.q2 - g.q3;"
  WHY "q1 forgets q4: momentum is created")
clothlab_mistake(q2_second_term_sign FILE bending.cpp
  FIND "+ (p4.cross(n1) + n2.cross(p4) * d) / area2;" REPLACE "- (p4.cross(n1) + n2.cross(p4) * d) / area2;"
  WHY "sign slip in the second half of q2")
clothlab_mistake(q_copied_from_slides FILE bending.cpp
  FIND "g.q3 = (n2.cross(p2) + p2.cross(n1) * d) / area1;" REPLACE "g.q3 = (p2.cross(n2) + n1.cross(p2) * d) / area1;"
  WHY "q3 as printed on the slides is -dd/dp3")
clothlab_mistake(not_relative_to_p1 FILE bending.cpp
  FIND "return gradientsRelativeToP1(p2 - p1, p3 - p1, p4 - p1);" REPLACE "return gradientsRelativeToP1(p2, p3, p4);"
  WHY "forgets to take the positions relative to p1")
clothlab_mistake(no_pinned_guard FILE bending.cpp
  FIND "if (sumWq2 < 1e-24) return r;" REPLACE ""
  WHY "all particles pinned: division by zero gives NaN")
clothlab_mistake(no_zero_area_guard FILE bending.cpp
  FIND "if (area1 < 1e-12 || area2 < 1e-12) return g;" REPLACE ""
  WHY "zero-area triangle: division by zero gives NaN")
clothlab_mistake(mass_not_in_denominator FILE bending.cpp
  FIND "w1 * g.q1.squaredNorm() + w2 * g.q2.squaredNorm() + w3 * g.q3.squaredNorm() + w4 * g.q4.squaredNorm();"
  REPLACE "g.q1.squaredNorm() + g.q2.squaredNorm() + g.q3.squaredNorm() + g.q4.squaredNorm();"
  WHY "the denominator ignores the inverse masses (pinned particles' share is lost)")
clothlab_mistake(sin_phi_from_d FILE bending.cpp
  FIND "g.sinPhi = n1.cross(n2).norm();" REPLACE "g.sinPhi = std::sqrt(1.0 - d * d);"
  WHY "sin(phi) as sqrt(1 - d^2), the textbook form: loses digits near flat (d close to -1)")
clothlab_mistake(sqrt_one_minus_d2_in_projection FILE bending.cpp
  FIND "const double s = k * g.sinPhi * C / sumWq2;" REPLACE "const double s = k * std::sqrt(1.0 - g.d * g.d) * C / sumWq2;"
  WHY "the projection uses sqrt(1 - d^2) instead of sin(phi) from 5.1: corrections off by up to 1e-4 near flat")
clothlab_mistake(stencil_wrong_opposite FILE bending.cpp
  FIND "s.i3 = it->second;" REPLACE "s.i3 = key.first == a ? b : a;"
  WHY "uses an edge vertex instead of the opposite vertex")
clothlab_mistake(rest_angle_zero FILE bending.cpp
  FIND "s.phi0 = g.valid ? std::atan2(g.sinPhi, g.d) : M_PI;" REPLACE "s.phi0 = 0.0;"
  WHY "rest angle 0 instead of the initial shape's angle")
clothlab_mistake(area_absolute_epsilon FILE bending.cpp
  FIND "if (area1 < 1e-12 || area2 < 1e-12) return g;" REPLACE "if (area1 < 1e-6 || area2 < 1e-6) return g;"
  WHY "an absolute area epsilon: small triangles (a millimetre-sized cloth) count as degenerate and never bend back")
clothlab_mistake(denominator_unweighted_free FILE bending.cpp
  FIND "w1 * g.q1.squaredNorm() + w2 * g.q2.squaredNorm() + w3 * g.q3.squaredNorm() + w4 * g.q4.squaredNorm();"
  REPLACE "(w1 > 0) * g.q1.squaredNorm() + (w2 > 0) * g.q2.squaredNorm() + (w3 > 0) * g.q3.squaredNorm() + (w4 > 0) * g.q4.squaredNorm();"
  WHY "sum |q_j|^2 over the free particles without their weights w_j: right only when every free particle has w = 1; with other masses one projection over- or undershoots the rest angle")
clothlab_mistake(degenerate_stencil_rest_angle_zero FILE bending.cpp
  FIND "s.phi0 = g.valid ? std::atan2(g.sinPhi, g.d) : M_PI;" REPLACE "s.phi0 = g.valid ? std::atan2(g.sinPhi, g.d) : 0.0;"
  WHY "a stencil whose triangle has zero area at the start gets rest angle 0 (folded) instead of pi (flat)")
clothlab_mistake(degenerate_stencil_dropped FILE bending.cpp
  FIND "stencils.push_back(s);" REPLACE "if (g.valid) stencils.push_back(s);"
  WHY "drops the stencil of a triangle with zero area at the start: that edge never resists bending")
