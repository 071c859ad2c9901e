#!/usr/bin/env bash
# The grader's exports for the systems instructors use, each checked against the fields its
# documentation names:
#  - Gradescope's results.json (https://gradescope-autograders.readthedocs.io/en/latest/specs/, "Output
#    format"): top-level score (number), execution_time (seconds), output, stdout_visibility; tests[]
#    with name, score, max_score (numbers), status "passed"/"failed", output, visibility, name_format
#    (a bonus test: max_score 0, its score extra credit).
#    The scores sum to the top-level score and to clothlab's own JSON; a stage that does not compile
#    gives each of its tests the compiler's message (file:line: error) as its output.
#  - ./lab grade --markdown: the table with a row per stage and the total.
#  - Moodle's grade import (docs.moodle.org "Grade import", CSV: a header row, an identifier column the
#    import maps to username / email address / ID number, one column per grade item).
#  - Canvas's gradebook import (Canvas guide "How do I import grades in the Gradebook?": the columns
#    Student, ID, SIS User ID, Section, then one per assignment; Canvas's own export has a "Points
#    Possible" row under the header).
#  - Bad input: one clear error line and a non-zero exit before any grading.
# Usage: exports_test.sh SOURCE_DIR BUILD_DIR
set -u
root=$1 build=$2
grader=$build/bin/clothlab-grade kit=$build/grade-kit/kit.json
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
points="$root/tests"
max01=$(jq '[.tests[]] | add' "$root"/tests/01_*.points.json)
n01=$(jq '.tests | length' "$root"/tests/01_*.points.json)
title01=$(jq -r .title "$root"/tests/01_*.points.json)

# gradescope_fields FILE: the fields and types Gradescope's specification gives.
gradescope_fields() {
  jq -e '(.score | type) == "number" and (.execution_time | type) == "number" and (.output | type) == "string"
         and (.stdout_visibility | IN("hidden", "visible", "after_due_date", "after_published"))
         and (.tests | type) == "array" and (.tests | length) > 0
         and all(.tests[]; (.name | type) == "string" and (.score | type) == "number" and (.max_score | type) == "number"
                 and (.status | IN("passed", "failed")) and (.output | type) == "string"
                 and (.visibility | IN("hidden", "visible", "after_due_date", "after_published"))
                 and (.name_format | IN("text", "html", "simple_format", "md", "ansi"))
                 and .score >= 0
                 and if (.name | endswith(" (bonus)")) then .max_score == 0 and ((.status == "passed") == (.score > 0))
                     else .score <= .max_score and ((.status == "passed") == (.score == .max_score)) end)
         and ((([.tests[].score] | add) - .score) | fabs) < 1e-9' "$1" >/dev/null \
    || fail "$1 lacks a field of Gradescope's format or its score is not the sum of the tests': $(head -c 600 "$1")"
}

# 1. The reference (every test passes) and the stub (every test fails), through the graded binaries.
for variant in solutions exercises; do
  exe=$build/bin/grade_01_$variant
  [[ -x $exe ]] || fail "no $exe (build grade_01_$variant first)"
  "$grader" --points-dir "$points" --quiet --binary "01=$exe" --answers "01=$root/$variant/01_hooke/answers.json" --json "$tmp/$variant.json" \
    --gradescope "$tmp/$variant.gs.json" --markdown "$tmp/$variant.md" >"$tmp/$variant.log" 2>&1 \
    || { tail "$tmp/$variant.log"; fail "clothlab-grade --binary 01=grade_01_$variant"; }
  gradescope_fields "$tmp/$variant.gs.json"
  [[ $(jq '.tests | length' "$tmp/$variant.gs.json") -eq $n01 ]] || fail "$variant: not one Gradescope test per graded test ($n01)"
  jq -e --slurpfile own "$tmp/$variant.json" '.score == $own[0].points and ([.tests[].max_score] | add) == $own[0].max_points' \
    "$tmp/$variant.gs.json" >/dev/null || fail "$variant: Gradescope's score differs from clothlab's JSON"
  grep -q "^| 01 | $title01 | graded | " "$tmp/$variant.md" && grep -q '^| \*\*total\*\* |' "$tmp/$variant.md" \
    || fail "$variant: the Markdown table lacks the stage-01 row or the total: $(head -5 "$tmp/$variant.md")"
done
jq -e --argjson max "$max01" '.score == $max and all(.tests[]; .status == "passed" and .output == "")' "$tmp/solutions.gs.json" >/dev/null \
  || fail "the reference does not score $max01 with every test passed"
jq -e '.score == 0 and all(.tests[]; .status == "failed" and (.output | contains("not implemented: exercise") or contains("not entered yet")))' "$tmp/exercises.gs.json" >/dev/null \
  || fail "the stub's tests are not all failed with their message as output"
grep -q "^| \*\*total\*\* | | | | \*\*$max01 / $max01\*\* |" "$tmp/solutions.md" || fail "the Markdown total is not $max01 / $max01"

# 2. A stage that does not compile (one submission, stage 01 only): each of its tests fails with the
# compiler's message as its output.
mkdir -p "$tmp/sub/01_hooke"
cp "$root"/exercises/01_hooke/*.cpp "$tmp/sub/01_hooke/"
echo 'this line is not C++ ;' >>"$tmp/sub/01_hooke/hooke.cpp"
"$grader" --kit "$kit" --submission "$tmp/sub" --work "$tmp/work" --stage 01 --gradescope "$tmp/broken.gs.json" \
  --markdown "$tmp/broken.md" >"$tmp/broken.log" 2>&1 || { tail "$tmp/broken.log"; fail "grading a stage that does not compile"; }
gradescope_fields "$tmp/broken.gs.json"
jq -e --argjson n "$n01" '.score == 0 and (.tests | length) == $n
       and all(.tests[]; .status == "failed" and (.output | test("does not compile: .*hooke[.]cpp:[0-9]+:[0-9]+: error")))
       and (.output | contains("01 does not compile"))' "$tmp/broken.gs.json" >/dev/null \
  || fail "the broken stage's tests do not carry the compiler's message: $(jq -c '.output, .tests[0]' "$tmp/broken.gs.json" | head -c 600)"
grep -q "^| 01 | $title01 | does not compile | 0 / $n01 | 0 / $max01 |" "$tmp/broken.md" && grep -q "hooke.cpp:[0-9]*:[0-9]*: error" "$tmp/broken.md" \
  || fail "the Markdown table does not show the broken stage with the compiler's message: $(head -12 "$tmp/broken.md")"

# 3. A class (stage 01 only): the gradebooks for Moodle and Canvas beside gradebook.csv, the student
# identified by the folder name (one with a comma, which CSV must quote).
mkdir -p "$tmp/class/alice@example.org/01_hooke" "$tmp/class/bob/01_hooke" "$tmp/class/smith, carol/01_hooke"
cp "$root"/solutions/01_hooke/* "$tmp/class/alice@example.org/01_hooke/"
cp "$tmp"/sub/01_hooke/*.cpp "$tmp/class/bob/01_hooke/"
cp "$root"/exercises/01_hooke/*.cpp "$tmp/class/smith, carol/01_hooke/"
# alice's write-up and her report (./lab report 01) are collected beside the gradebook; a link is not.
printf '# Write-up\n\nalice explains the energy.\n' >"$tmp/class/alice@example.org/01_hooke/writeup.md"
mkdir -p "$tmp/class/alice@example.org/out/report" && echo '<html>report 01</html>' >"$tmp/class/alice@example.org/out/report/01_hooke.html"
ln -s /etc/passwd "$tmp/class/alice@example.org/out/report/02_mfn.html"
"$grader" --kit "$kit" --class "$tmp/class" --out "$tmp/out" --stage 01 --jobs 2 >"$tmp/class.log" 2>&1 \
  || { tail "$tmp/class.log"; fail "grading the class"; }
item="clothlab 01 $title01"
printf '%s\n' "Identifier,$item" "alice@example.org,$max01" "bob,0" "\"smith, carol\",0" >"$tmp/moodle.want"
diff "$tmp/moodle.want" "$tmp/out/moodle.csv" >"$tmp/moodle.diff" || fail "moodle.csv: $(cat "$tmp/moodle.diff")"
printf '%s\n' "Student,ID,SIS User ID,Section,$item" "Points Possible,,,,$max01" "alice@example.org,,alice@example.org,,$max01" \
  "bob,,bob,,0" "\"smith, carol\",,\"smith, carol\",,0" >"$tmp/canvas.want"
diff "$tmp/canvas.want" "$tmp/out/canvas.csv" >"$tmp/canvas.diff" || fail "canvas.csv: $(cat "$tmp/canvas.diff")"
w="$tmp/out/writeups/alice@example.org"
cmp -s "$tmp/class/alice@example.org/01_hooke/writeup.md" "$w/01_hooke/writeup.md" && grep -q 'report 01' "$w/01_hooke.html" \
  || fail "alice's write-up and report were not collected: $(find "$tmp/out/writeups" | head)"
[[ ! -e $w/02_mfn.html && ! -e $tmp/out/writeups/bob ]] || fail "writeups/ has a link's target or a student without a write-up: $(find "$tmp/out/writeups")"
grep -q "write-ups of 1 in writeups/NAME/" "$tmp/class.log" || fail "the class summary does not mention the write-ups: $(tail -1 "$tmp/class.log")"
# The same points as clothlab's gradebook.csv (student, then stage 01).
cut -d, -f1-2 "$tmp/out/gradebook.csv" | sed -n 2p | grep -qx "alice@example.org,$max01" || fail "gradebook.csv disagrees: $(head -3 "$tmp/out/gradebook.csv")"

# 4. Bad input: one line "error: FILE: OPTION: reason", non-zero, before grading.
"$grader" --points-dir "$points" --binary "01=$build/bin/grade_01_solutions" --gradescope "$tmp/no/such/dir/results.json" >"$tmp/bad.log" 2>&1 \
  && fail "--gradescope into a missing folder succeeds"
[[ $(grep -c . "$tmp/bad.log") -eq 1 ]] && grep -qx "error: $tmp/no/such/dir/results.json: --gradescope: the folder $tmp/no/such/dir does not exist" "$tmp/bad.log" \
  || fail "--gradescope into a missing folder: $(cat "$tmp/bad.log")"
"$grader" --kit "$kit" --class "$tmp/class" --out "$tmp/out2" --markdown "$tmp/m.md" >"$tmp/bad.log" 2>&1 && fail "--markdown with --class succeeds"
grep -qx "error: $tmp/m.md: --markdown: not with --class (the class's gradebooks and feedback go to --out)" "$tmp/bad.log" \
  || fail "--markdown with --class: $(cat "$tmp/bad.log")"
[[ ! -e $tmp/out2 ]] || fail "--markdown with --class graded before saying no"
echo "results.json has Gradescope's fields (scores sum, the compiler's message on a broken stage's tests); the Markdown table; moodle.csv and canvas.csv in their import formats; the write-ups collected; bad output paths are one error line"
