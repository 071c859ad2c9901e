# Typical mistakes in stage 02. Each is the reference with one edit; ./lab test proves that
# the graded tests catch every one (stage_02.mistake_caught.<name>). Included from tests/CMakeLists.txt.
clothlab_mistake(one_shear_diagonal FILE mfn.cpp
  FIND "                connect(c + 1, r, c, r + 1, types.shear, SpringType::Shear);\n" REPLACE ""
  WHY "only one diagonal per cell: the cloth shears freely one way")
clothlab_mistake(bending_one_apart FILE mfn.cpp
  FIND "connect(c, r, c + 2, r, types.bending" REPLACE "connect(c, r, c + 1, r, types.bending"
  WHY "bending springs on direct neighbours duplicate the structural ones and resist no bending")
clothlab_mistake(rest_length_grid_spacing FILE mfn.cpp
  FIND "const double l0 = (x.col(j) - x.col(i)).norm();" REPLACE "const double l0 = (x.col(1) - x.col(0)).norm();"
  WHY "one rest length (the horizontal grid spacing) for every spring: diagonals and bending springs start compressed")
clothlab_mistake(shear_uses_structural_group FILE mfn.cpp
  FIND "connect(c, r, c + 1, r + 1, types.shear," REPLACE "connect(c, r, c + 1, r + 1, types.structural,"
  WHY "takes k and kd of the wrong spring group")
clothlab_mistake(disabled_type_built FILE mfn.cpp
  FIND "if (types.shear.enabled) {" REPLACE "{"
  WHY "ignores the on/off switch of a spring type")
clothlab_mistake(duplicate_structural FILE mfn.cpp
  FIND "                connect(c, r, c, r + 1, types.structural, SpringType::Structural);\n"
  REPLACE "                connect(c, r, c, r + 1, types.structural, SpringType::Structural);\n                connect(c, r + 1, c, r, types.structural, SpringType::Structural);\n"
  WHY "joins each vertical pair twice (from both ends): doubles the vertical stiffness")
clothlab_mistake(no_reaction_force FILE mfn.cpp
  FIND "        f.col(s.i) -= force;  // actio = reactio\n" REPLACE ""
  WHY "forgets Newton's third law: the cloth accelerates itself")
clothlab_mistake(no_spring_damping FILE mfn.cpp
  FIND " +\n                           springDampingForce(x.col(s.i), x.col(s.j), v.col(s.i), v.col(s.j), s.kd);" REPLACE ";"
  WHY "drops the damping along the springs")
clothlab_mistake(gravity_times_inverse_mass FILE mfn.cpp
  FIND "f.col(i) += g / w[i] - c * v.col(i);" REPLACE "f.col(i) += g * w[i] - c * v.col(i);"
  WHY "m_i g with w_i instead of 1/w_i")
clothlab_mistake(pinned_get_gravity FILE mfn.cpp
  FIND "        if (w[i] == 0.0) continue;  // pinned: infinite mass\n" REPLACE ""
  WHY "divides by w = 0 for pinned particles: Inf forces")
clothlab_mistake(damping_sign FILE mfn.cpp
  FIND "f.col(i) += g / w[i] - c * v.col(i);" REPLACE "f.col(i) += g / w[i] + c * v.col(i);"
  WHY "damping that pushes instead of brakes")
clothlab_mistake(gravity_fixed_axis FILE mfn.cpp
  FIND "f.col(i) += g / w[i] - c * v.col(i);" REPLACE "f.col(i) += Vec3(0.0, -g.norm(), 0.0) / w[i] - c * v.col(i);"
  WHY "gravity always along -y: a scene whose gravity points elsewhere (a tilted or rotated set-up) falls the wrong way")
clothlab_mistake(skips_short_springs FILE mfn.cpp
  FIND "for (const Spring& s : springs) {" REPLACE "for (const Spring& s : springs) {\n        if ((x.col(s.j) - x.col(s.i)).norm() < 1e-3) continue;"
  WHY "skips springs shorter than 1 mm (an absolute epsilon): a small cloth feels no spring forces")
clothlab_mistake(damping_only_structural FILE mfn.cpp
  FIND "v.col(s.i), v.col(s.j), s.kd);" REPLACE "v.col(s.i), v.col(s.j), s.type == SpringType::Structural ? s.kd : 0.0);"
  WHY "damps only the structural springs")
clothlab_mistake(spring_type_not_set FILE mfn.cpp
  FIND "springs.push_back({i, j, group.k, l0, group.kd, type});" REPLACE "springs.push_back({i, j, group.k, l0, group.kd});"
  WHY "leaves Spring::type at its default (Single): right springs, but no kind the solver or the tests can tell apart")
