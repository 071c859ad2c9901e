# Typical mistakes in stage 03. Each is the reference with one edit; ./lab test proves that
# the graded tests catch every one (stage_03.mistake_caught.<name>). Included from tests/CMakeLists.txt.
clothlab_mistake(damp_all_velocity FILE pbd_loop.cpp
  FIND "const Vec3 dv = vcm + omega.cross(x.col(i) - xcm) - v.col(i);" REPLACE "const Vec3 dv = -v.col(i);"
  WHY "plain damping v *= (1 - k): slows rigid motion too")
clothlab_mistake(damp_no_rotation FILE pbd_loop.cpp
  FIND "const Vec3 dv = vcm + omega.cross(x.col(i) - xcm) - v.col(i);" REPLACE "const Vec3 dv = vcm - v.col(i);"
  WHY "keeps only the centre-of-mass velocity: a spinning cloth is slowed")
clothlab_mistake(inertia_wrong FILE pbd_loop.cpp
  FIND "I += m * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());  // r~ r~^T"
  REPLACE "I += m * r.squaredNorm() * Eigen::Matrix3d::Identity();"
  WHY "a scalar moment of inertia instead of the tensor")
clothlab_mistake(stiffness_linear FILE pbd_loop.cpp
  FIND "return 1.0 - std::pow(1.0 - k, 1.0 / iterations);" REPLACE "return k / iterations;"
  WHY "k / n instead of 1 - (1 - k)^(1/n)")
clothlab_mistake(forces_without_inverse_mass FILE pbd_loop.cpp
  FIND "P.v += dt * (f * P.w.asDiagonal());" REPLACE "P.v += dt * f;"
  WHY "v += dt f: ignores the mass and moves pinned particles")
clothlab_mistake(predict_before_damping FILE pbd_loop.cpp
  FIND "    dampVelocities(P.x, P.v, P.w, kDamping);                              // (6)\n    P.p = P.x + dt * P.v;                                                 // (7)  p = x + dt v"
  REPLACE "    P.p = P.x + dt * P.v;\n    dampVelocities(P.x, P.v, P.w, kDamping);"
  WHY "predicts with the undamped velocity")
clothlab_mistake(iterations_off_by_one FILE pbd_loop.cpp
  FIND "for (int it = 0; it < iterations; ++it)" REPLACE "for (int it = 0; it <= iterations; ++it)"
  WHY "one sweep too many: zero iterations still projects")
clothlab_mistake(velocity_after_position FILE pbd_loop.cpp
  FIND "    P.v = (P.p - P.x) / dt;                                               // (13)\n    P.x = P.p;                                                            // (14)"
  REPLACE "    P.x = P.p;\n    P.v = (P.p - P.x) / dt;"
  WHY "sets x = p first, so v = (p - x)/dt is always zero")
clothlab_mistake(velocity_update_before_positions FILE pbd_loop.cpp
  FIND "    if (cb.velocityUpdate) cb.velocityUpdate(P.x, P.v);                   // (16)\n" REPLACE ""
  WHY "forgets velocityUpdate (line 16)")
clothlab_mistake(inertia_absolute_tolerance FILE pbd_loop.cpp
  FIND "const double tol = 1e-12 * std::max(1.0, eig.eigenvalues().cwiseAbs().maxCoeff());"
  REPLACE "const double tol = 1e-6;"
  WHY "an absolute threshold (1e-6 kg m^2) for a zero moment of inertia: a small or light cloth loses its spin")
clothlab_mistake(inertia_relative_tolerance_large FILE pbd_loop.cpp
  FIND "const double tol = 1e-12 * std::max(1.0, eig.eigenvalues().cwiseAbs().maxCoeff());"
  REPLACE "const double tol = 1e-3 * eig.eigenvalues().cwiseAbs().maxCoeff();"
  WHY "a nearly straight (but not straight) cloth is treated as a line: its spin about the line is damped")
clothlab_mistake(damping_before_forces FILE pbd_loop.cpp
  FIND "    P.v += dt * (f * P.w.asDiagonal());                                   // (5)  v += dt w f_ext\n    dampVelocities(P.x, P.v, P.w, kDamping);                              // (6)"
  REPLACE "    dampVelocities(P.x, P.v, P.w, kDamping);\n    P.v += dt * (f * P.w.asDiagonal());"
  WHY "damps before the external forces act (lines 5 and 6 swapped): this step's gravity is not damped")
clothlab_mistake(velocity_update_before_commit FILE pbd_loop.cpp
  FIND "    P.x = P.p;                                                            // (14)\n    if (cb.velocityUpdate) cb.velocityUpdate(P.x, P.v);                   // (16)"
  REPLACE "    if (cb.velocityUpdate) cb.velocityUpdate(P.x, P.v);\n    P.x = P.p;"
  WHY "calls velocityUpdate (16) before x = p (14): it sees the positions of the step's start")
clothlab_mistake(collisions_from_old_positions FILE pbd_loop.cpp
  FIND "if (cb.generateCollisionConstraints) cb.generateCollisionConstraints(P.x, P.p);"
  REPLACE "if (cb.generateCollisionConstraints) cb.generateCollisionConstraints(P.x, P.x);"
  WHY "generates the collision constraints from x instead of the predicted p (line 8)")
