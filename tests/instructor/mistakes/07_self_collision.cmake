# Typical mistakes in stage 07. Each is the reference with one edit; ./lab test proves that
# the graded tests catch every one (stage_07.mistake_caught.<name>). Included from tests/CMakeLists.txt.
clothlab_mistake(cell_truncates_towards_zero FILE self_collision.cpp
  FIND "static_cast<int>(std::floor(p.y() / spacing))" REPLACE "static_cast<int>(p.y() / spacing)"
  WHY "rounds the cell coordinate towards zero: cells -1 and 0 become one cell twice as wide, neighbours across it are missed")
clothlab_mistake(hash_negative_remainder FILE self_collision.cpp
  FIND "return static_cast<int>(((h % tableSize) + tableSize) % tableSize);" REPLACE "return static_cast<int>(h % tableSize);"
  WHY "C++'s % keeps the sign: negative cell coordinates give a negative bucket, an index outside the table")
clothlab_mistake(hash_sum_of_coordinates FILE self_collision.cpp
  FIND "const int64_t h = (int64_t{cell.x()} * 73856093) ^ (int64_t{cell.y()} * 19349663) ^ (int64_t{cell.z()} * 83492791);"
  REPLACE "const int64_t h = int64_t{cell.x()} + cell.y() + cell.z();"
  WHY "adds the coordinates: every cell on a diagonal plane shares a bucket, most of the table stays empty and the query slows down")
clothlab_mistake(hash_ignores_z FILE self_collision.cpp
  FIND "^ (int64_t{cell.z()} * 83492791)" REPLACE ""
  WHY "hashes only x and y: every column of cells along z falls into one bucket")
clothlab_mistake(prefix_sum_misses_the_end FILE self_collision.cpp
  FIND "for (int b = 0; b <= tableSize; ++b) {" REPLACE "for (int b = 0; b < tableSize; ++b) {"
  WHY "the prefix sum stops before the sentinel: cellStart[T] is not N, the last bucket loses its particles")
clothlab_mistake(query_only_own_cell FILE self_collision.cpp
  FIND "for (int dx = -1; dx <= 1; ++dx)" REPLACE "for (int dx = 0; dx <= 0; ++dx)"
  WHY "searches only the cells in the same x slab: a neighbour across a cell boundary in x is missed")
clothlab_mistake(query_buckets_twice FILE self_collision.cpp
  FIND "if (std::find(visited.begin(), visited.end(), b) != visited.end()) continue;" REPLACE ""
  WHY "visits a bucket once per cell that hashes to it: when two of the 27 cells share a bucket, pairs come twice")
clothlab_mistake(pairs_in_both_orders FILE self_collision.cpp
  FIND "if (j > i &&" REPLACE "if (j != i &&"
  WHY "reports every pair twice, as (i, j) and (j, i): the separation is applied twice")
clothlab_mistake(separation_pulls FILE self_collision.cpp
  FIND "if (dist >= d || wsum <= 0.0) return {};" REPLACE "if (wsum <= 0.0) return {};"
  WHY "an equality instead of an inequality: pulls every nearby pair to the distance d, glues layers together")
clothlab_mistake(separation_equal_shares FILE self_collision.cpp
  FIND "return {wi / wsum * push * n, -wj / wsum * push * n};" REPLACE "return {0.5 * push * n, -0.5 * push * n};"
  WHY "moves both particles by half, whatever their masses: momentum is not kept and pinned particles move")
clothlab_mistake(separation_nan_when_coincident FILE self_collision.cpp
  FIND "return len >= 1e-12 ? Vec3(diff / len) : Vec3(0, 1, 0);" REPLACE "return Vec3(diff / len);"
  WHY "divides by the distance of two coincident particles: NaN spreads through the cloth")
clothlab_mistake(friction_always_sticks FILE self_collision.cpp
  FIND "if (slip >= mu * depth) rt *= mu * depth / slip;" REPLACE ""
  WHY "removes the whole tangential slip however small the friction: layers never slide over each other")
clothlab_mistake(friction_not_tangential FILE self_collision.cpp
  FIND "Vec3 rt = r - r.dot(n) * n;" REPLACE "Vec3 rt = r;"
  WHY "friction also removes the normal part of the relative motion: it undoes the separation")
