# Typical mistakes in stage 06. Each is the reference with one edit; ./lab test proves that
# the graded tests catch every one (stage_06.mistake_caught.<name>). Included from tests/CMakeLists.txt.
clothlab_mistake(thickness_ignored FILE collision.cpp
  FIND "if ((p - collider.point).dot(collider.normal) >= h) return false;" REPLACE "if ((p - collider.point).dot(collider.normal) >= 0.0) return false;"
  WHY "generates plane constraints only below the surface, not within the thickness")
clothlab_mistake(sphere_end_point_only FILE collision.cpp
  FIND "if (t < 0.0 || t > 1.0) return false;" REPLACE "if ((p - c).norm() >= Rh) return false;"
  WHY "tests only the end point p: fast particles tunnel through the sphere")
clothlab_mistake(sphere_normal_at_p FILE collision.cpp
  FIND "n = (f + t * u).normalized();" REPLACE "n = (p - c).normalized();"
  WHY "normal at p instead of at the entry point: pushed out on the wrong side")
clothlab_mistake(projection_always FILE collision.cpp
  FIND "if (C >= 0.0 || w <= 0.0) return Vec3::Zero();" REPLACE "if (w <= 0.0) return Vec3::Zero();"
  WHY "treats the inequality as an equality: glues particles to the surface")
clothlab_mistake(projection_sign FILE collision.cpp
  FIND "Vec3 dp = -C * c.n;" REPLACE "Vec3 dp = C * c.n;"
  WHY "pushes the particle further into the collider")
clothlab_mistake(no_static_friction FILE collision.cpp
  FIND "if (t.norm() < c.friction * (-C)) dp -= t;" REPLACE ""
  WHY "friction only at velocity level: a block on an incline creeps")
clothlab_mistake(friction_reverses FILE collision.cpp
  FIND "if (vtLen > 0.0) vt *= (vtLen - std::min(vtLen, c.friction * dvn)) / vtLen;"
  REPLACE "if (vtLen > 0.0) vt *= (vtLen - c.friction * dvn) / vtLen;"
  WHY "friction larger than the sliding velocity reverses the motion")
clothlab_mistake(restitution_ignored FILE collision.cpp
  FIND "const double vnNew = std::max(vn, -c.restitution * c.vnBefore);" REPLACE "const double vnNew = vn;"
  WHY "no bounce")
clothlab_mistake(restitution_of_outgoing FILE collision.cpp
  FIND "const double vnNew = std::max(vn, -c.restitution * c.vnBefore);" REPLACE "const double vnNew = -c.restitution * vn;"
  WHY "reflects the normal velocity after the solve (about zero) instead of the incoming one")
clothlab_mistake(plane_height_not_distance FILE collision.cpp
  FIND "if ((p - collider.point).dot(collider.normal) >= h) return false;" REPLACE "if (p.y() - collider.point.y() >= h) return false;"
  WHY "tests the height p.y instead of the distance along the normal: only right for a horizontal floor")
clothlab_mistake(friction_from_incoming_speed FILE collision.cpp
  FIND "const double dvn = std::max(0.0, vn - c.vnBefore);" REPLACE "const double dvn = std::max(0.0, -c.vnBefore);"
  WHY "friction from the incoming normal speed instead of the normal velocity change of the solve: too much friction for a particle that lands within the step")
clothlab_mistake(sphere_normal_at_start FILE collision.cpp
  FIND "n = (f + t * u).normalized();" REPLACE "n = f.normalized();"
  WHY "normal from the centre to the start x instead of to the entry point: right only for a path aimed at the centre; an oblique hit is pushed out on the wrong side")
