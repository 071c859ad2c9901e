#!/usr/bin/env bash
# Stubs state requirements, not code: the student derives the answer from the task sheet and the
# header's requirements; the stub only says which task it is. Checked on every stub exercises/NN_*/*.cpp:
#   1. no key expression of an answer (the formulas and code of the reference, and the notation a task
#      sheet would write them in; list below), ignoring whitespace and case;
#   2. at most 3 comment lines inside any function body, and every TODO line reads exactly
#      "// TODO N.M: <task name> (task sheet N.M; contract in the header)" (no formula characters);
#      one TODO per task, for the same tasks as the `throw NotImplemented("exercise N.M ...")` lines;
#   3. exercises/NN_*/hints.json has, for every task of the stage's stubs and for no other,
#      exactly 3 non-empty hint levels (read by `./lab hint N.M`).
# Every key expression of kind `code` must still occur in the reference (solutions/, whitespace-insensitive,
# // comments ignored), so the list follows the reference when it is edited.
# Usage: stub_requirements_check.sh SOURCE_DIR   (checks that tree; then proves each check fails on a
# temporary copy with a key expression planted into a stub and a hint level removed).
set -u
root=$1
[[ -d $root/exercises ]] || { echo "error: $root/exercises: no such folder"; exit 2; }

# Key expressions of the answers: STAGE KIND EXPRESSION (kind code: from solutions/NN_*/; text: how a
# task sheet or a TODO comment would write the formula). Whitespace inside an expression does not matter.
read -r -d '' KEYS <<'EOF'
01 code -k * (length - l0) * (d / length)
01 code -kd * (v1 - v0).dot(dir) * dir
01 code (v1 - v0).dot(
01 code f * w.asDiagonal()
01 code x += dt * v
01 code 0.5 * dt * (f * w.asDiagonal())
01 text -k (|p1 - p0| - l0)
01 text (|p1 - p0| - l0)
01 text (p1 - p0) / |p1 - p0|
01 text (p1 - p0).normalized()
01 text -kd ((v1 - v0) . d) d
01 text x += dt * v_old
01 text v += dt * w_i * f_i
01 text half kick, drift
01 text with the NEW velocity
02 code (x.col(j) - x.col(i)).norm()
02 code f.col(s.j) += force
02 code f.col(s.i) -= force
02 code g / w[i] - c * v.col(i)
02 text m_i g - c v_i
02 text l0 = |x_j - x_i|
02 text (c+1, r) and (c, r+1)
02 text add F to f.col(j)
03 code 1.0 - std::pow(1.0 - k, 1.0 / iterations)
03 code std::pow(1.0 - k
03 code P.p = P.x + dt * P.v
03 code P.v = (P.p - P.x) / dt
03 code P.v += dt * (f * P.w.asDiagonal())
03 code vcm + omega.cross(x.col(i) - xcm) - v.col(i)
03 code r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose()
03 code L += r.cross(m * v.col(i))
03 code SelfAdjointEigenSolver
03 text 1 - (1 - k)^(1/n)
03 text pow(1 - k
03 text p = x + dt v
03 text v = (p - x) / dt
03 text v_i += dt w_i f_i
03 text v_cm + omega x r_i - v_i
03 text |r_i|^2 Id - r_i r_i^T
03 text omega = I^-1 L
04 code (p1 - p2).norm() - d
04 code e / len
04 code k * (len - d) / (wsum * len)
04 code {-w1 * s, w2 * s}
04 text |p1 - p2| - d
04 text (p1 - p2) / |p1 - p2|
04 text (p1 - p2).normalized()
04 text w1 / (w1 + w2)
04 text w2 / (w1 + w2)
05 code n1.cross(n2).norm()
05 code std::clamp(n1.dot(n2), -1.0, 1.0)
05 code n2.cross(p2) + p2.cross(n1) * d
05 code n1.cross(p2) + p2.cross(n2) * d
05 code p3.cross(n2) + n1.cross(p3) * d
05 code p4.cross(n1) + n2.cross(p4) * d
05 code -g.q2 - g.q3 - g.q4
05 code std::atan2(g.sinPhi, g.d)
05 code k * g.sinPhi * C / sumWq2
05 code std::minmax(a, b)
05 text q1 = -q2 - q3 - q4
05 text sinPhi = |n1 x n2|
05 text p2 x p3 / |p2 x p3|
05 text atan2(sin(phi), d)
05 text sin(phi) (phi - phi0) / sum_j w_j |q_j|^2
05 text std::map from the edge
06 code (p - collider.point).dot(collider.normal)
06 code (p - x).dot(n) / dt
06 code B * B - A * Cq
06 code (-B - std::sqrt(disc)) / A
06 code f.squaredNorm() - Rh * Rh
06 code c + R * n
06 code -C * c.n
06 code moved - moved.dot(c.n) * c.n
06 code c.friction * (-C)
06 code std::max(vn, -c.restitution * c.vnBefore)
06 code std::max(0.0, vn - c.vnBefore)
06 code std::min(vtLen, c.friction * dvn)
06 text (p - q_s).n_s < h
06 text (p - x).n / dt
06 text q = c + R n
06 text dp = -C n
06 text mu |C|
06 text max(v_n, -e vnBefore)
06 text -e vnBefore
06 text e * vn
06 text max(0, v_n - vnBefore)
06 text min(|v_t|, mu dvn)
06 text a quadratic in t
07 code std::floor(p.x() / spacing)
07 code ((h % tableSize) + tableSize) % tableSize
07 code int64_t{cell.x()} * 73856093
07 code --hash.cellStart[bucket[i]]
07 code hashCell(c + Eigen::Vector3i(dx, dy, dz), tableSize)
07 code std::find(visited.begin(), visited.end(), b)
07 code wi / wsum * push * n
07 code r - r.dot(n) * n
07 code rt *= mu * depth / slip
07 text floor(p / s)
07 text (x p1) XOR (y p2) XOR (z p3)
07 text 73856093
07 text j > i
07 text w_i / (w_i + w_j)
EOF

squash() { tr -d '[:space:]'; }                                 # whitespace-insensitive
uncomment() { sed -E 's://.*$::' "$@"; }                           # // comments dropped

# The keys once, as STAGE<TAB>KIND<TAB>EXPRESSION<TAB>expression without whitespace, lower case: every
# stub is then searched for all of them by one awk (a process per key and stub took minutes).
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
keyfile=$work/keys.tsv
awk '{ expr = $0; sub(/^[^ ]+ [^ ]+ /, "", expr); sq = expr; gsub(/[[:space:]]/, "", sq)
       printf "%s\t%s\t%s\t%s\n", $1, $2, expr, tolower(sq) }' <<<"$KEYS" >"$keyfile"
# gives_away FILE REL: one line per key expression found in FILE (whitespace and case ignored).
gives_away() {
  awk -F'\t' -v rel="$2" 'NR == FNR { st[NR] = $1; ex[NR] = $3; sq[NR] = $4; n = NR; next }
    { text = text $0 }
    END { gsub(/[[:space:]]/, "", text); text = tolower(text)
          for (i = 1; i <= n; i++) if (index(text, sq[i])) { printf "%s: gives away the answer (key expression of stage %s): %s\n", rel, st[i], ex[i]; bad = 1 }
          exit bad }' "$keyfile" "$1"
}

# The TODO numbers and the NotImplemented numbers of a stub, sorted.
todo_numbers() { grep -ohE '//[[:space:]]*TODO[[:space:]]+[0-9]+\.[0-9]+' "$@" | grep -oE '[0-9]+\.[0-9]+' | sort; }
task_numbers() { grep -ohE 'NotImplemented\("exercise [0-9]+\.[0-9]+' "$@" | grep -oE '[0-9]+\.[0-9]+' | sort; }

# check_hints FILE TASK...: every task has exactly 3 non-empty levels, no entry for another task (CMake's
# string(JSON): cmake is what the course needs anyway).
check_hints() {
  local file=$1; shift
  local script; script=$(mktemp --suffix=.cmake)
  cat >"$script" <<'CMAKE'
cmake_minimum_required(VERSION 3.25)
file(READ "${FILE}" j)
set(bad "")
string(JSON type ERROR_VARIABLE err TYPE "${j}")
if(err OR NOT type STREQUAL "OBJECT")
  message(NOTICE "${NAME}: not a JSON object: ${err}")
  message(FATAL_ERROR "")
endif()
string(REPLACE "," ";" tasks "${TASKS}")
foreach(task IN LISTS tasks)
  string(JSON t ERROR_VARIABLE err TYPE "${j}" "${task}")
  if(err OR NOT t STREQUAL "ARRAY")
    list(APPEND bad "${NAME}: task ${task} has no hint list")
    continue()
  endif()
  string(JSON n LENGTH "${j}" "${task}")
  if(NOT n EQUAL 3)
    list(APPEND bad "${NAME}: task ${task} has ${n} hint levels, want exactly 3")
  endif()
  if(n GREATER 0)
    math(EXPR last "${n} - 1")
    foreach(i RANGE ${last})
      string(JSON ti TYPE "${j}" "${task}" ${i})
      string(JSON s GET "${j}" "${task}" ${i})
      string(STRIP "${s}" s)
      math(EXPR level "${i} + 1")
      if(NOT ti STREQUAL "STRING" OR s STREQUAL "")
        list(APPEND bad "${NAME}: task ${task}, level ${level} is empty or not text")
      endif()
    endforeach()
  endif()
endforeach()
string(JSON nk LENGTH "${j}")
if(nk GREATER 0)
  math(EXPR last "${nk} - 1")
  foreach(i RANGE ${last})
    string(JSON key MEMBER "${j}" ${i})
    if(NOT key IN_LIST tasks)
      list(APPEND bad "${NAME}: hints for ${key}, a task no stub of this stage has")
    endif()
  endforeach()
endif()
if(bad)
  foreach(line IN LISTS bad)
    message(NOTICE "${line}")
  endforeach()
  message(FATAL_ERROR "")
endif()
CMAKE
  local tasks; tasks=$(IFS=,; echo "$*")
  cmake -DFILE="$file" -DNAME="${file#"$tree"/}" -DTASKS="$tasks" -P "$script" 2>&1 | grep -vE '^(CMake Error|-- Configuring incomplete|$)' ; local rc=${PIPESTATUS[0]}
  rm -f "$script"
  return "$rc"
}

# check TREE: prints one line per violation, exit status 1 if there are any.
check() {
  tree=$1
  local bad=0 dir stage stubs f rel
  for dir in "$tree"/exercises/[0-9][0-9]_*/; do
    dir=${dir%/}; stage=$(basename "$dir"); stage=${stage:0:2}
    stubs=("$dir"/*.cpp)
    [[ -e ${stubs[0]} ]] || continue
    for f in "${stubs[@]}"; do
      rel=${f#"$tree"/}
      # 1. no key expression of any stage's answer
      gives_away "$f" "$rel" || bad=1
      # 2. short bodies: at most 3 comment lines per function body; TODO lines in the one format
      awk -v rel="$rel" '
        function count(s, c,   n) { n = gsub(c, "", s); return n }
        {
          line = $0; code = line
          gsub(/"([^"\\]|\\.)*"/, "\"\"", code)                   # string literals hide nothing
          commented = inblock || code ~ /\/\/|\/\*/
          if (inblock && code ~ /\*\//) inblock = 0
          if (code ~ /\/\*/ && code !~ /\*\//) inblock = 1
          sub(/\/\/.*/, "", code); gsub(/\/\*.*\*\//, "", code)
          if (depth == 0 && code ~ /^[[:space:]]*namespace[^{]*\{[[:space:]]*$/) next
          if (depth == 0 && code ~ /[A-Za-z_][A-Za-z0-9_]*[[:space:]]*\(/) name = code
          before = depth
          depth += count(code, "{") - count(code, "}")
          if (depth < 0) depth = 0
          if (before > 0 && commented) n++
          if (before > 0 && depth == 0) {
            if (n > 3) { sub(/^[[:space:]]+/, "", name); sub(/\(.*/, "", name)
                         printf "%s: %d comment lines in the body of %s (at most 3: the TODO names the task, the task sheet and the header say the rest)\n", rel, n, name; bad = 1 }
            n = 0
          }
        }
        END { exit bad }' "$f" || bad=1
      while IFS= read -r line; do
        if ! grep -qE '^    // TODO ([0-9]+\.[0-9]+): [A-Za-z0-9][A-Za-z0-9 ,()'"'"'-]* \(task sheet \1; contract in the header\)$' <<<"$line"; then
          echo "$rel: a TODO line is not \"// TODO N.M: <task name> (task sheet N.M; contract in the header)\" (letters, digits, spaces, commas, parentheses, hyphens): ${line#"${line%%[![:space:]]*}"}"; bad=1
        fi
      done < <(grep -E 'TODO' "$f")
    done
    local todos tasks
    todos=$(todo_numbers "${stubs[@]}"); tasks=$(task_numbers "${stubs[@]}")
    if [[ $todos != "$tasks" ]]; then
      echo "exercises/$(basename "$dir"): one TODO line per task: TODO numbers [$(echo $todos)] but tasks [$(echo $tasks)]"; bad=1
    fi
    # 3. three hint levels per task
    if [[ ! -f $dir/hints.json ]]; then
      echo "${dir#"$tree"/}/hints.json: missing (three hint levels per task for ./lab hint)"; bad=1
    else
      # shellcheck disable=SC2046
      check_hints "$dir/hints.json" $(sort -u <<<"$tasks") || bad=1
    fi
  done
  return $bad
}

fail=0
# Every key of kind `code` is still in the reference (else the list is stale: update it with the reference).
if [[ -d $root/solutions ]]; then
  while read -r stage kind expr; do
    [[ $kind == code ]] || continue
    ref=$(cat "$root"/solutions/"$stage"_*/*.cpp 2>/dev/null | uncomment | squash)
    grep -qF -- "$(squash <<<"$expr")" <<<"$ref" \
      || { echo "FAIL: key expression of stage $stage is no longer in solutions/${stage}_*/ (update the list in $0): $expr"; fail=1; }
  done <<<"$KEYS"
fi
check "$root" || { echo "FAIL: the stubs give away answers or the hints are incomplete (lines above)"; exit 1; }
[[ $fail -eq 0 ]] || exit 1

# The checks can fail: plant violations into a temporary copy of exercises/.
tmp=$work
fresh() { rm -rf "$tmp/t" && mkdir -p "$tmp/t" && cp -r "$root/exercises" "$tmp/t/"; }
json_edit() {  # json_edit FILE CMAKE-JSON-ARGS...: rewrite FILE with string(JSON out <ARGS>)
  local s; s=$(mktemp --suffix=.cmake)
  printf 'cmake_minimum_required(VERSION 3.25)\nfile(READ "%s" j)\nstring(JSON out %s)\nfile(WRITE "%s" "${out}")\n' "$1" "$2" "$1" >"$s"
  cmake -P "$s" >/dev/null 2>&1; local rc=$?; rm -f "$s"; return $rc
}
expect_caught() {  # expect_caught NAME PATTERN: the check fails on the copy and names the planted violation
  local name=$1 pattern=$2 out
  if out=$(check "$tmp/t"); then echo "FAIL: the check misses a planted violation: $name"; exit 1; fi
  grep -qE -- "$pattern" <<<"$out" || { echo "FAIL: planted $name, but the report does not name it: $out"; exit 1; }
}
plant_stub() { sed -i "$2" "$tmp/t/exercises/$1" && ! cmp -s "$root/exercises/$1" "$tmp/t/exercises/$1" \
  || { echo "FAIL: could not plant into exercises/$1 (update this test)"; exit 1; }; }

# A key expression as code, other whitespace than in the list, and a hint level removed: both reported.
fresh
plant_stub 04_distance/distance.cpp '/^    (void)p1; (void)p2; (void)w1;/i\    const double share = w1/( w1 +w2 );'
json_edit "$tmp/t/exercises/06_collision/hints.json" 'REMOVE "${j}" "6.4" 0' || { echo "FAIL: could not remove a hint level"; exit 1; }
expect_caught "key expression and missing hint level" 'distance\.cpp: gives away the answer .*w1 / \(w1 \+ w2\)'
expect_caught "key expression and missing hint level" 'hints\.json: task 6\.4 has 2 hint levels'
# Each alone, and the other checks: a formula in the TODO, long comments, an empty level, a missing task.
fresh; plant_stub 03_pbd_loop/pbd_loop.cpp "s|^    // TODO 3.2: .*|    // TODO 3.2: k' = 1 - (1 - k)^(1/n)|"
expect_caught "formula in a TODO" "TODO line is not|1 - \(1 - k\)\^\(1/n\)"
fresh; plant_stub 01_hooke/hooke.cpp '/^    \/\/ TODO 1.5:/a\    // first half a kick\n    // then a drift\n    // then new forces'
expect_caught "comment lines in a body" 'hooke\.cpp: 4 comment lines in the body of void velocityVerletStep'
fresh; json_edit "$tmp/t/exercises/05_bending/hints.json" 'SET "${j}" "5.2" 2 "\"  \""' || { echo "FAIL: could not blank a hint level"; exit 1; }
expect_caught "empty hint level" 'task 5\.2, level 3 is empty'
fresh; json_edit "$tmp/t/exercises/02_mfn/hints.json" 'REMOVE "${j}" "2.3"' || { echo "FAIL: could not remove a task's hints"; exit 1; }
expect_caught "task without hints" 'task 2\.3 has no hint list'
fresh; plant_stub 06_collision/collision.cpp '/^    \/\/ TODO 6.3:/d'
expect_caught "task without TODO" 'one TODO line per task'

echo "stubs state requirements: no key expression of an answer ($(grep -c . <<<"$KEYS") guarded, each code one still in the reference), at most 3 comment lines per body, one TODO per task, 3 hint levels per task; each check fails on a planted violation"
