#!/usr/bin/env bash
# ./lab release writes a student distribution that builds, runs and grades on its own:
# no solutions/, no instructor tests, every graded test "not implemented", every scene stops
# with "not implemented: exercise ..." instead of crashing. The copy holds exactly the committed files
# (git ls-tree HEAD) minus solutions/ and tests/instructor/, and gives away no reference function body
# (clothlab-leak-check, the last step).
set -u
root=$1; leak_check=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$root/lab" release "$tmp/copy" || fail "lab release"
[[ -d $tmp/copy/exercises && -f $tmp/copy/lab && -f $tmp/copy/README.md ]] || fail "copy lacks exercises/, lab or README.md"
[[ ! -e $tmp/copy/solutions && ! -e $tmp/copy/tests/instructor ]] || fail "copy contains solutions/ or tests/instructor/"
# Exactly the committed files: nothing untracked, no build output.
{ git -C "$root" ls-tree -r --name-only HEAD | grep -v -E '^(solutions|tests/instructor)/'; echo .github/workflows/classroom.yml
  git -C "$root" ls-tree -r --name-only HEAD exercises | grep -E '^exercises/[0-9][0-9]_[^/]*/[^/]*\.cpp$' | sed 's|^exercises/|framework/stubs/|'; } | sort >"$tmp/want.txt"
(cd "$tmp/copy" && find . -type f -o -type l) | sed 's|^\./||' | sort >"$tmp/got.txt"
cmp -s "$tmp/want.txt" "$tmp/got.txt" \
  || fail "the copy is not git ls-tree HEAD minus solutions/, tests/instructor/, plus the Classroom workflow and framework/stubs/: $(diff "$tmp/want.txt" "$tmp/got.txt" | grep '^[<>]' | head -5 | tr '\n' ' ')"

cd "$tmp/copy" || fail "cd"
# The build is outside the copy, so the copy stays as released (the leak check reads it last).
export CLOTHLAB_BUILD="$tmp/build"
# Only stubs run here (they throw at once), so an unoptimised build is enough and compiles faster.
export CLOTHLAB_BUILD_TYPE=Debug
./lab grade --json "$tmp/grade.json" >"$tmp/grade.log" 2>&1 || { tail -20 "$tmp/grade.log"; fail "grading the copy"; }
grep -q '"max_points": [1-9]' "$tmp/grade.json" || fail "grade.json has no points"
grep -q '"passed": true' "$tmp/grade.json" && fail "the untouched copy passes a graded test: $(grep -B3 '"passed": true' "$tmp/grade.json" | head -4)"
# The copy's own graded binaries (its stubs): every test fails with "not implemented", through the grader.
targets=(clothlab)
for d in exercises/[0-9][0-9]_*/; do nn=$(basename "$d"); targets+=("grade_${nn:0:2}_exercises"); done
cmake --build "$CLOTHLAB_BUILD" -j "$(nproc)" --target "${targets[@]}" >"$tmp/build.log" 2>&1 || { tail "$tmp/build.log"; fail "build the copy's CLI and graded binaries"; }
specs=()
for exe in "$CLOTHLAB_BUILD"/bin/grade_*_exercises; do
  nn=$(basename "$exe"); nn=${nn#grade_}; nn=${nn%%_*}
  specs+=(--stage "$nn=$exe")
done
((${#specs[@]})) || fail "no graded test binaries in the copy"
"$CLOTHLAB_BUILD/bin/clothlab-grade" --points-dir tests --quiet --expect all-fail --message "not implemented: exercise" "${specs[@]}" \
  || fail "the untouched copy must fail every graded test with 'not implemented'"
for s in scenes/*.json; do
  "$CLOTHLAB_BUILD/bin/clothlab" run "$s" --steps 5 >"$tmp/run.log" 2>&1
  code=$?
  [[ $code -eq 2 ]] && grep -q "not implemented: exercise" "$tmp/run.log" || fail "$s in the copy: exit $code, $(tail -2 "$tmp/run.log")"
  # advice that works in a copy without solutions/: finish the task, grade, hint (not --reference)
  grep -q "./lab hint [1-9]" "$tmp/run.log" && ! grep -q -- "--reference" "$tmp/run.log" || fail "$s in the copy: advice $(tail -1 "$tmp/run.log")"
done
# The instructors' batched bending kernel is not in the copy (nothing registers it at the solver's
# extension point): asking for it is one clear input error that lists what there is.
"$CLOTHLAB_BUILD/bin/clothlab" run scenes/pbd_hanging.json --set solver.bending_kernel=batched --steps 5 >"$tmp/run.log" 2>&1
code=$?
[[ $code -eq 1 && $(grep -c '^error: scenes/pbd_hanging.json: solver.bending_kernel: unknown value "batched" (allowed: exercise)$' "$tmp/run.log") -eq 1 ]] \
  || fail "bending_kernel batched in the copy: exit $code, $(tail -2 "$tmp/run.log")"
# GitHub Classroom: the workflow's grading commands, run here as its job runs them (the Debian setup,
# the grader, the base64 output the reporter reads), give the reporter's format with every test.
wf=.github/workflows/classroom.yml
awk '/id: clothlab/ { on = 1 } on && /run: \|/ { run = 1; next } run && /^ *- name:/ { exit } run { sub(/^ +/, ""); print }' "$wf" >"$tmp/step.sh"
grep -q 'lab grade' "$tmp/step.sh" || fail "$wf: no grading step found"
mkdir -p "$tmp/runner"; : >"$tmp/gh_output"
RUNNER_TEMP=$tmp/runner GITHUB_OUTPUT=$tmp/gh_output bash -e "$tmp/step.sh" >"$tmp/step.log" 2>&1 || { tail "$tmp/step.log"; fail "the workflow's grading step fails"; }
grep '^result=' "$tmp/gh_output" | cut -d= -f2- | base64 -d >"$tmp/classroom.json" || fail "the step's result is not base64"
tests=$(grep -c '"name":' "$tmp/grade.json")  # one per graded test
grep -q '"version":1' "$tmp/classroom.json" && grep -q '"status":"fail"' "$tmp/classroom.json" \
  && [[ $(grep -o '"score":0' "$tmp/classroom.json" | wc -l) -eq $tests ]] \
  || fail "the reporter's JSON lacks version/status or a score per test ($tests tests): $(head -c 300 "$tmp/classroom.json")"
# Last, so that the checks above run even while a known leak waits to be removed.
"$leak_check" "$root" "$tmp/copy" || fail "the copy gives away reference code (lines above)"
echo "release copy builds, grades (0 points) and runs every scene up to 'not implemented'; no untracked file, no leak"
