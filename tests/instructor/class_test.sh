#!/usr/bin/env bash
# ./lab grade --class on a generated class writes the right gradebook. The class mixes the layouts an
# LMS export or a clone of each student's repository gives (nested folders, a .zip with an extra top folder, a
# .tar.gz) and the submissions a course sees: the reference, untouched stubs, typical mistakes, a
# stage that does not compile, a hostile stage, a missing stage, an unreadable layout. The expected
# points come from the points files (full or zero) and, for a mistake, from its graded binary that
# the build made with CMake (another path than the grader's sandboxed compile and link).
# Usage: class_test.sh SOURCE_DIR BUILD_DIR small|full
set -u
root=$1 build=$2 size=${3:-small}
grader=$build/bin/clothlab-grade kit=$build/grade-kit/kit.json
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
class=$tmp/class; mkdir -p "$class"
stages=(); for d in "$root"/exercises/[0-9][0-9]_*/; do stages+=("$(basename "$d")"); done

# small (./lab test) grades stage 01 only (--stage: the others read 0), where the class's
# hostile, broken and mistaken stages sit; full grades every stage.
graded=" 01 "; only=(--stage 01)
[[ $size == full ]] && { graded=" ${stages[*]%%_*} "; only=(); }
declare -A max expect status
for s in "${stages[@]}"; do
  max[${s:0:2}]=$(jq '[.tests[]] | add' "$root/tests/$s.points.json")  # the graded tests' points, experiments included
  [[ $graded == *" ${s:0:2} "* ]] || max[${s:0:2}]=0
done
# expect_row NAME STATUS [NN=POINTS ...]: every other stage full points; a status "NN ..." of a stage
# not graded is left out.
expect_row() {
  local name=$1 st=$2 part kept=(); shift 2
  local s; for s in "${stages[@]}"; do expect[$name,${s:0:2}]=${max[${s:0:2}]}; done
  local kv; for kv in "$@"; do [[ $graded == *" ${kv%%=*} "* ]] && expect[$name,${kv%%=*}]=${kv#*=}; done
  IFS=';' read -r -a parts <<<"$st"
  for part in "${parts[@]}"; do
    part=${part# }
    [[ $part =~ ^([0-9][0-9])\  && $graded != *" ${BASH_REMATCH[1]} "* ]] || kept+=("$part")
  done
  st=$(IFS=';'; echo "${kept[*]}"); st=${st//;/; }
  status[$name]=${st:-ok}
}
zero_all() { local s out=(); for s in "${stages[@]}"; do out+=("${s:0:2}=0"); done; echo "${out[@]}"; }
reference() { mkdir -p "$1"; cp -r "$root"/solutions/[0-9][0-9]_* "$1/"; }

# --- the submissions ---------------------------------------------------------------------------
reference "$class/ref_plain";                       expect_row ref_plain ok
reference "$class/ref_exercises/exercises";         expect_row ref_exercises ok   # one folder deeper
mkdir -p "$class/stub_untouched"; cp -r "$root"/exercises/[0-9][0-9]_* "$class/stub_untouched/"
expect_row stub_untouched ok $(zero_all)
reference "$class/broken_compile"; echo 'this is not C++ ;' >>"$class/broken_compile/01_hooke/hooke.cpp"
expect_row broken_compile "01 does not compile" 01=0
reference "$class/hostile_static"
cat >>"$class/hostile_static/01_hooke/hooke.cpp" <<'CPP'
#include <cstdlib>
namespace { struct Forge { Forge() { std::system("echo forged"); } } forge; }
CPP
expect_row hostile_static "01 rejected" 01=0
reference "$tmp/zip/frank-submission-main/exercises"
(cd "$tmp/zip" && zip -qr "$class/zip_extra_folder.Zip" frank-submission-main) || fail "zip"  # .Zip: any case is a zip
expect_row zip_extra_folder ok
mistake_names=()
add_mistake() {  # add_mistake NN_dir NAME
  local dir=$1 m=$2 nn=${1:0:2} name="mistake_$2"
  local exe=$build/bin/grade_${nn}_mistake_$m src=$build/tests/mistakes/$dir/$m
  [[ -x $exe && -d $src ]] || fail "no built mistake $dir/$m (build first)"
  reference "$class/$name"; rm -rf "${class:?}/$name/$dir"; mkdir -p "$class/$name/$dir"; cp "$src"/*.cpp "$class/$name/$dir/"
  "$grader" --points-dir "$root/tests" --binary "$nn=$exe" --quiet --json "$tmp/$name.json" >/dev/null 2>&1
  local pts; pts=$(grep -E '^  "points":' "$tmp/$name.json" | grep -oE '[0-9.]+' | head -1)
  [[ -n $pts ]] || fail "no points for the CMake-built $exe"
  expect_row "$name" ok "$nn=$(awk -v p="$pts" 'BEGIN { printf "%g", p }')"
}
add_mistake 01_hooke sign_flipped
# Names that clash once made safe for file names: each keeps its own points and files.
mkdir -p "$class/bob smith"; cp -r "$root/exercises/01_hooke" "$class/bob smith/"
expect_row "bob smith" "02 not submitted; 03 not submitted; 04 not submitted; 05 not submitted; 06 not submitted; 07 not submitted" $(zero_all)
reference "$class/bob_smith"; expect_row bob_smith ok
# The reference with stage 01's answers not measured yet (null): its experiments fail, naming the file.
reference "$class/ref_no_answers"; jq '(.predict, .measure) |= map_values(.value = null)' "$root/solutions/01_hooke/answers.json" >"$class/ref_no_answers/01_hooke/answers.json"
expect_row ref_no_answers ok "01=$(jq '[.tests | to_entries[] | select(.key | startswith("Experiments.") | not) | .value] | add' "$root/tests/01_hooke.points.json")"
if [[ $size == full ]]; then
  for i in 1 2 3 4 5 6 7; do reference "$class/ref_student$i"; expect_row "ref_student$i" ok; done
  reference "$class/ref_lms/ref_lms/submission/exercises"; expect_row ref_lms ok
  for i in 1 2 3; do mkdir -p "$class/stub_$i"; cp -r "$root"/exercises/[0-9][0-9]_* "$class/stub_$i/"; expect_row "stub_$i" ok $(zero_all); done
  reference "$tmp/tar/gina"; (cd "$tmp/tar" && tar -czf "$class/tar_gz.tar.gz" gina) || fail "tar"; expect_row tar_gz ok
  mkdir -p "$class/missing_stages"; cp -r "$root"/solutions/0[1-3]_* "$class/missing_stages/"
  expect_row missing_stages "04 not submitted; 05 not submitted; 06 not submitted; 07 not submitted" 04=0 05=0 06=0 07=0
  mkdir -p "$class/no_layout"; echo "my homework" >"$class/no_layout/README.txt"
  expect_row no_layout "error" $(zero_all)
  add_mistake 02_mfn shear_uses_structural_group
  add_mistake 03_pbd_loop "$(ls "$build/tests/mistakes/03_pbd_loop" | grep -v '\.tmp$\|\.error\.txt$' | head -1)"
  for d in 04_distance 05_bending 06_collision 01_hooke 02_mfn; do
    add_mistake "$d" "$(ls "$build/tests/mistakes/$d" | grep -v '\.tmp$\|\.error\.txt$' | sed -n 2p)"
  done
fi
n=$(ls "$class" | wc -l)
if [[ $size == full ]]; then
  # Like a real class, no two submissions share a file: a comment with the student's name makes every
  # file different, so nothing is compiled once for several students (the shared cache never hits).
  for d in "$class"/*/; do
    find "$d" -name '*.cpp' -exec sh -c 'for f; do printf "\n// %s\n" "$0" >>"$f"; done' "$(basename "$d")" {} +
  done
fi

# --- grade and compare ----------------------------------------------------------------------------
# While the small class is graded, the CPUs each test and compile may run on, read from outside every
# 0.5 s (/proc/PID/status; docs/grading.md, "run"): the test's process ("test", started by bwrap) and
# its submission process ("submission", started by the test) on one CPU, the same one; the compiler
# (cc1plus) on one CPU; with two CPUs or more, the students graded at once test on different CPUs, so
# both are used. Not in the full run, which this script times.
watch_cpus() {
  local poll=0
  while [[ -e $tmp/grading ]]; do
    poll=$((poll + 1))
    grep -s -e '^Name:' -e '^PPid:' -e '^Cpus_allowed_list:' /proc/[0-9]*/status |
      awk -v poll=$poll -v top="$(cat "$tmp/grading")" -F'\t' '{ split($1, p, "/"); sub(/:$/, "", $1)
                                  if ($1 ~ /Name$/) name[p[3]] = $2; else if ($1 ~ /PPid$/) ppid[p[3]] = $2; else cpus[p[3]] = $2 }
                                END { for (q in name)
                                        { mine = 0; for (a = ppid[q]; a != "" && a > 1 && !mine; a = ppid[a]) mine = a == top  # under this grader only
                                          if (mine && (name[q] == "test" && name[ppid[q]] == "bwrap" || name[q] == "submission" && name[ppid[q]] == "test" ||
                                              name[q] == "cc1plus")) print poll, q, name[q], cpus[q], cpus[ppid[q]] }
}'
    sleep 0.5  # a poll reads every process's status: about 40 ms of CPU here
  done >"$tmp/cpus.txt"
}
start=$(date +%s)
# Relative --class and --out, as an instructor types them (the class's build links from other folders).
(cd "$tmp" && "$grader" --kit "$kit" --class "${class#"$tmp"/}" --out out "${only[@]}") >"$tmp/grade.log" 2>&1 &
gpid=$!
if [[ $size != full ]]; then echo "$gpid" >"$tmp/grading"; watch_cpus & watcher=$!; fi
wait "$gpid" || { tail -20 "$tmp/grade.log"; fail "grading the class failed"; }
secs=$(( $(date +%s) - start ))
if [[ $size != full ]]; then
  rm -f "$tmp/grading"; wait "$watcher"
  [[ -s $tmp/cpus.txt ]] || fail "no test process was seen while the class was graded (/proc)"
  awk '$3 != "submission" && $4 !~ /^[0-9]+$/ { print "a " $3 " process (pid " $2 ") may run on CPUs " $4 ", not on one"; bad = 1 }
       $3 == "submission" && $4 != $5 { print "a submission process (pid " $2 ") may run on CPUs " $4 ", its test on " $5; bad = 1 }
       END { exit bad }' "$tmp/cpus.txt" || fail "the tests or compiles do not keep to one CPU (lines above)"
  used=$(awk '$3 == "test" { print $4 }' "$tmp/cpus.txt" | sort -u | tr '\n' ' ')
  if (($(nproc) >= 2)); then
    [[ $(wc -w <<<"$used") -ge 2 ]] || fail "every test of the class ran on CPU $used: the two students graded at once must test on different CPUs"
  fi
fi
book=$tmp/out/gradebook.csv
[[ -f $book ]] || fail "no gradebook"
bad=0 rows=0
IFS=, read -r -a H <"$book"
while IFS= read -r row; do
  IFS=, read -r -a C <<<"$row"
  name=${C[0]}; [[ $name == student ]] && continue
  rows=$((rows + 1))
  [[ -n ${status[$name]:-} ]] || { echo "unexpected row: $name"; bad=1; continue; }
  for ((i = 1; i <= ${#stages[@]}; i++)); do
    want=${expect[$name,${H[$i]}]}
    [[ ${C[$i]} == "$want" ]] || { echo "$name: stage ${H[$i]}: ${C[$i]} points, want $want"; bad=1; }
  done
  got_status=$(echo "$row" | cut -d, -f$((${#stages[@]} + 4)))  # student, stages, total, max, status, bonus
  case ${status[$name]} in
    error) [[ $got_status == *error* ]] || { echo "$name: status '$got_status', want an error"; bad=1; } ;;
    *) [[ $got_status == "${status[$name]}" ]] || { echo "$name: status '$got_status', want '${status[$name]}'"; bad=1; } ;;
  esac
done <"$book"
((rows == n)) || { echo "$rows rows for $n submissions"; bad=1; }
(($(ls "$tmp/out/feedback" | wc -l) == n && $(ls "$tmp/out/junit" | wc -l) == n)) || { echo "not one feedback JSON and one JUnit file per student"; bad=1; }
((bad == 0)) || { cat "$book"; fail "the gradebook is wrong (lines above)"; }
# An experiment's message names the answers file as the student knows it, not the sandbox's copy.
grep -qE 'exercises/01_hooke/answers.json: (predict|measure)[.][a-z0-9_]*[.]value: null, not entered yet' "$tmp/out/feedback/ref_no_answers.json" \
  && ! grep -q '/grade/answers' "$tmp/out/feedback/ref_no_answers.json" \
  || fail "ref_no_answers's feedback does not name exercises/01_hooke/answers.json (or names the sandbox path)"
# The LMS imports (docs/grading.md "Exports") carry the same points per stage: moodle.csv is the
# identifier and the stages, canvas.csv the identifier as Student and SIS User ID, a Points Possible row.
# (With --stage, the graded stages' columns.)
k=1; for ((i = 1; i <= ${#stages[@]}; i++)); do [[ $graded == *" ${H[$i]} "* ]] && k+=",$((i + 1))"; done
tail -n +2 "$book" | cut -d, -f"$k" >"$tmp/book_points.csv"
tail -n +2 "$tmp/out/moodle.csv" | cmp -s - "$tmp/book_points.csv" || fail "moodle.csv's points differ from gradebook.csv: $(head -3 "$tmp/out/moodle.csv")"
sed -n 2p "$tmp/out/canvas.csv" | grep -q '^Points Possible,,,,' || fail "canvas.csv has no Points Possible row"
tail -n +3 "$tmp/out/canvas.csv" | awk -F, '$1 != $3 || $2 != "" || $4 != "" { exit 1 }' || fail "canvas.csv: Student and SIS User ID differ, or ID/Section are set"
tail -n +3 "$tmp/out/canvas.csv" | cut -d, -f1,5- | cmp -s - "$tmp/book_points.csv" || fail "canvas.csv's points differ from gradebook.csv: $(head -4 "$tmp/out/canvas.csv")"
# A second run regrades nothing (content hashes) and writes the same gradebook.
cp "$book" "$tmp/first.csv"
"$grader" --kit "$kit" --class "$class" --out "$tmp/out" "${only[@]}" >"$tmp/grade2.log" 2>&1 || fail "second run"
cmp -s "$book" "$tmp/first.csv" || fail "the second run wrote another gradebook"
[[ $(grep -c "unchanged, not regraded" "$tmp/grade2.log") -eq $n ]] || { tail "$tmp/grade2.log"; fail "the second run regraded unchanged submissions"; }
[[ $size == full ]] || echo "every test and compile process kept to one CPU, each submission process to its test's; the tests used CPUs $used"
echo "class of $n graded (stages${graded% }) in ${secs} s ($(nproc) cores): gradebook (and its Moodle and Canvas forms), feedback and JUnit per student match the expected points; a rerun regrades nothing"
