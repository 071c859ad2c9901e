#!/usr/bin/env bash
# Bonus points (docs/grading.md "Bonus"): stage 04's bonus tests (tests/04_distance.points.json,
# "bonus") count beside the stage's points, never in its maximum, in every output. The reference earns
# the stage's maximum plus the whole bonus, the stub none of either; Gradescope gets each bonus test as
# extra credit (max_score 0); the Markdown and JUnit call a bonus test not passed "not earned" /
# skipped, not failed; a class's gradebook.csv has the bonus in its last column; a points file that
# lists a test under both "tests" and "bonus", or a "bonus" that is no object, is one error naming it.
# Usage: bonus_points_test.sh SOURCE_DIR BUILD_DIR
set -u
root=$1 build=$2
grader=$build/bin/clothlab-grade kit=$build/grade-kit/kit.json
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
pf=$root/tests/04_distance.points.json
max=$(jq '[.tests[]] | add' "$pf") bonus=$(jq '[.bonus[]] | add' "$pf") nbonus=$(jq '.bonus | length' "$pf")
((nbonus > 0)) || fail "$pf has no bonus tests (this test is about them)"

for variant in solutions exercises; do
  exe=$build/bin/grade_04_$variant
  [[ -x $exe ]] || fail "no $exe (build grade_04_$variant first)"
  answers=$root/$variant/04_distance/answers.json
  "$grader" --points-dir "$root/tests" --binary "04=$exe" --answers "04=$answers" --json "$tmp/$variant.json" \
    --gradescope "$tmp/$variant.gs.json" --markdown "$tmp/$variant.md" --junit "$tmp/$variant.xml" >"$tmp/$variant.log" 2>&1
done
# The table counts the bonus tests apart from the stage's: "16 / 16 ... 27.0 / 27.0   + bonus 5 / 5 tests, 8 / 8 points".
ntests=$(jq '.tests | length' "$pf")
grep -qE "^04 .* $ntests / $ntests +$max\.0 / $max\.0 +\+ bonus $nbonus / $nbonus tests, $bonus / $bonus points$" "$tmp/solutions.log" \
  || fail "the reference's table row is not '$ntests / $ntests  $max / $max  + bonus $nbonus / $nbonus tests, $bonus / $bonus points': $(grep '^04' "$tmp/solutions.log")"
grep -qE "^04 .* 0 / $ntests +0\.0 / $max\.0 +\+ bonus 0 / $nbonus tests, 0 / $bonus points$" "$tmp/exercises.log" \
  || fail "the stub's table row is not '0 / $ntests  0 / $max  + bonus 0 / $nbonus tests, 0 / $bonus points': $(grep '^04' "$tmp/exercises.log")"
grep -qE "^total .* $max\.0 / $max\.0 +\+ bonus $bonus / $bonus points$" "$tmp/solutions.log" \
  || fail "the reference's total row: $(grep '^total' "$tmp/solutions.log")"
jq -e --argjson m "$max" --argjson b "$bonus" --argjson n "$nbonus" '.points == $m and .max_points == $m and .bonus == $b
     and .stages[0].bonus == $b and ([.stages[0].tests[] | select(.bonus)] | length) == $n' "$tmp/solutions.json" >/dev/null \
  || fail "the reference's JSON: points $max of $max and bonus $bonus expected: $(jq -c '{points, max_points, bonus}' "$tmp/solutions.json")"
jq -e --argjson m "$max" '.points == 0 and .max_points == $m and .bonus == 0' "$tmp/exercises.json" >/dev/null \
  || fail "the stub's JSON: 0 points and 0 bonus expected: $(jq -c '{points, max_points, bonus}' "$tmp/exercises.json")"
jq -e --argjson m "$max" --argjson b "$bonus" --argjson n "$nbonus" '.score == $m + $b
     and ([.tests[] | select(.name | endswith(" (bonus)")) | select(.max_score == 0)] | length) == $n
     and ([.tests[].max_score] | add) == $m and (.output | contains("+ \($b) bonus"))' "$tmp/solutions.gs.json" >/dev/null \
  || fail "Gradescope: the bonus must be extra credit ($max + $bonus, bonus tests max_score 0): $(jq -c '{score, output}' "$tmp/solutions.gs.json")"
grep -q "^| \*\*total\*\* | | | | \*\*$max / $max + $bonus bonus\*\* |" "$tmp/solutions.md" \
  || fail "the reference's Markdown total: $(grep total "$tmp/solutions.md")"
grep -q "^| 04 | .* | graded | $ntests / $ntests + $nbonus / $nbonus bonus | $max / $max + $bonus bonus |" "$tmp/solutions.md" \
  || fail "the reference's Markdown row does not count the bonus tests apart: $(grep '^| 04' "$tmp/solutions.md")"
grep -q "failed, $nbonus bonus not earned</summary>" "$tmp/exercises.md" || fail "the stub's Markdown does not call the bonus tests not earned"
grep -q "skipped=\"$nbonus\"" "$tmp/exercises.xml" && [[ $(grep -c '<skipped message="bonus not earned' "$tmp/exercises.xml") -eq $nbonus ]] \
  || fail "JUnit: the stub's bonus tests are not skipped"

# A class of one (the reference, stage 04 only): gradebook.csv's last column is the bonus.
mkdir -p "$tmp/class/ref" && cp -r "$root/solutions/04_distance" "$tmp/class/ref/"
"$grader" --kit "$kit" --class "$tmp/class" --out "$tmp/out" --stage 04 >"$tmp/class.log" 2>&1 || { tail "$tmp/class.log"; fail "grading the class"; }
[[ $(head -1 "$tmp/out/gradebook.csv") == *",total,max,status,bonus" ]] && grep -q "^ref,.*,$max,$max,ok,$bonus$" "$tmp/out/gradebook.csv" \
  || fail "gradebook.csv: the reference's row must end with $max,$max,ok,$bonus: $(cat "$tmp/out/gradebook.csv")"

# Bad points files: one error naming the file and the field.
bad() {  # bad WHAT JQ-EDIT EXPECTED-ERROR
  mkdir -p "$tmp/bad" && cp "$root"/tests/*.points.json "$tmp/bad/" && jq "$2" "$pf" >"$tmp/bad/04_distance.points.json"
  "$grader" --points-dir "$tmp/bad" --binary "04=$build/bin/grade_04_solutions" >"$tmp/bad.log" 2>&1 && fail "$1: accepted"
  [[ $(grep -c '^error' "$tmp/bad.log") -eq 1 ]] && grep -qE "^error: .*04_distance\.points\.json: $3" "$tmp/bad.log" || fail "$1: $(cat "$tmp/bad.log")"
}
bad "a test under tests and bonus" '.bonus[(.tests | keys_unsorted[0])] = 1' 'bonus\.Task4_1_[A-Za-z_.]+: also under tests'
bad "a bonus that is no object" '.bonus = [1]' 'bonus: not an object'
bad "a bonus of 0 points" '.bonus[(.bonus | keys_unsorted[0])] = 0' 'bonus\.Bonus4_4_[A-Za-z_.]+: points must be a number > 0'
echo "stage 04's bonus ($bonus points, $nbonus tests) counts beside its $max points in the table, JSON, Markdown, JUnit, Gradescope (extra credit) and gradebook.csv; bad bonus entries are one error each"
