#!/usr/bin/env bash
# Stubs state requirements, not code: the student derives the answer from the task sheet and the
# header's requirements; the stub only says which task it is. Checked on every stub exercises/NN_*/*.cpp:
#   1. no key expression of an answer (the notation a task sheet would write its formula in:
#      tests/instructor/keys/notation.txt), ignoring whitespace and case;
#   2. at most 3 comment lines inside any function body, and every TODO line reads exactly
#      "// TODO N.M: <task name> (task sheet N.M; contract in the header)" (no formula characters);
#      one TODO per task, for the same tasks as the `throw NotImplemented("exercise N.M ...")` lines;
#   3. exercises/NN_*/hints.json has, for every task of the stage's stubs and for no other,
#      exactly 3 non-empty hint levels (read by `./lab hint N.M`).
# Usage: stub_requirements_check.sh SOURCE_DIR   (checks that tree; then proves each check fails on a
# temporary copy with a key expression planted into a stub and a hint level removed).
set -u
root=$1
[[ -d $root/exercises ]] || { echo "error: $root/exercises: no such folder"; exit 2; }

# Key expressions of the answers: how a task sheet, a TODO or a hint would write the formula (STAGE
# EXPRESSION per line, whitespace-insensitive), from the instructor-only tests/instructor/keys/notation.txt
# (not in the student copy). The reference's own lines are the leak test's: release.leak_test reads every
# statement of solutions/ at test time and finds none in the copy, whose stubs it searches too.
notation=$root/tests/instructor/keys/notation.txt
[[ -f $notation ]] || { echo "error: $notation: no such file (the instructor's keys; this check runs in the instructor's tree)"; exit 2; }
KEYS=$(grep -vE '^(#|$)' "$notation" | sed -E 's/^([0-9]+) /\1 text /')

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
plant_stub 04_distance/distance.cpp '/^    (void)p1; (void)p2; (void)w1;/i\    // share = w1/( w1 +w2 )'
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

echo "stubs state requirements: no key expression of an answer ($(grep -c . <<<"$KEYS") guarded), at most 3 comment lines per body, one TODO per task, 3 hint levels per task; each check fails on a planted violation"
