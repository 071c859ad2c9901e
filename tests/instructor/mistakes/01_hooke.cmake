# Typical mistakes in stage 01. Each is the reference with one edit; ./lab test proves that
# the graded tests catch every one (stage_01.mistake_caught.<name>). Included from tests/CMakeLists.txt.
clothlab_mistake(sign_flipped FILE hooke.cpp
  FIND "return -k * (length - l0) * (d / length);" REPLACE "return k * (length - l0) * (d / length);"
  WHY "force pushes a stretched spring further apart")
clothlab_mistake(missing_normalisation FILE hooke.cpp
  FIND "return -k * (length - l0) * (d / length);" REPLACE "return -k * (length - l0) * d;"
  WHY "uses p1 - p0 instead of the unit direction")
clothlab_mistake(rest_length_ignored FILE hooke.cpp
  FIND "return -k * (length - l0) * (d / length);" REPLACE "return -k * length * (d / length);"
  WHY "a spring of rest length zero")
clothlab_mistake(no_zero_length_guard FILE hooke.cpp
  FIND "    if (length < 1e-12) return Vec3::Zero();  // direction undefined\n    return -k * (length - l0)"
  REPLACE "    return -k * (length - l0)"
  WHY "divides by zero for coincident points")
clothlab_mistake(damping_absolute_velocity FILE hooke.cpp
  FIND "return -kd * (v1 - v0).dot(dir) * dir;" REPLACE "return -kd * v1.dot(dir) * dir;"
  WHY "damps the absolute instead of the relative velocity")
clothlab_mistake(symplectic_uses_old_velocity FILE hooke.cpp
  FIND "    v += dt * (f * w.asDiagonal());\n    x += dt * v;                                // new velocity"
  REPLACE "    x += dt * v;\n    v += dt * (f * w.asDiagonal());"
  WHY "symplectic Euler that is really explicit Euler")
clothlab_mistake(explicit_uses_new_velocity FILE hooke.cpp
  FIND "    x += dt * v;                                // old velocity\n    v += dt * (f * w.asDiagonal());             // a_i = w_i F_i"
  REPLACE "    v += dt * (f * w.asDiagonal());\n    x += dt * v;"
  WHY "explicit Euler that is really symplectic Euler")
clothlab_mistake(mass_instead_of_inverse_mass FILE hooke.cpp
  FIND "    x += dt * v;                                // old velocity\n    v += dt * (f * w.asDiagonal());             // a_i = w_i F_i"
  REPLACE "    x += dt * v;\n    v += dt * (f * w.asDiagonal().inverse());"
  WHY "a = F * m instead of F / m (and pinned particles explode)")
clothlab_mistake(verlet_full_first_kick FILE hooke.cpp
  FIND "    v += 0.5 * dt * (f * w.asDiagonal());       // half kick\n    x += dt * v;                                // drift"
  REPLACE "    v += dt * (f * w.asDiagonal());\n    x += dt * v;"
  WHY "velocity Verlet with a full first kick")
clothlab_mistake(hooke_absolute_epsilon FILE hooke.cpp
  FIND "if (length < 1e-12) return Vec3::Zero();\n    return -k * (length - l0) * (d / length);"
  REPLACE "if (length < 1e-6) return Vec3::Zero();\n    return -k * (length - l0) * (d / length);"
  WHY "treats springs shorter than a micrometre as coincident (an absolute epsilon in metres): a short spring, e.g. in a millimetre-sized cloth, feels no force")
clothlab_mistake(damping_absolute_epsilon FILE hooke.cpp
  FIND "if (length < 1e-12) return Vec3::Zero();\n    const Vec3 dir = d / length;"
  REPLACE "if (length < 1e-6) return Vec3::Zero();\n    const Vec3 dir = d / length;"
  WHY "no damping for springs shorter than a micrometre (an absolute epsilon in metres)")
clothlab_mistake(hooke_skips_small_stretch FILE hooke.cpp
  FIND "if (length < 1e-12) return Vec3::Zero();\n    return -k * (length - l0) * (d / length);"
  REPLACE "if (length < 1e-12 || std::abs(length - l0) < 1e-6) return Vec3::Zero();\n    return -k * (length - l0) * (d / length);"
  WHY "ignores stretches below a micrometre: a stiff spring with a tiny stretch still pulls hard")
