#!/usr/bin/env bash
# Every task sheet (exercises/NN_name/README.md) shows the points of tests/NN_name.points.json: in its
# "## Before you start" section a table "| task | what | points |" with one row per task N.M (the sum
# of the tests TaskN_M_*.*), a row "Experiments" (the sum of Experiments.*), a row "total" (the
# file's total), when the file has bonus tests BonusN_M_*.*, a row "N.M (bonus)" with their sum, a row
# "Write-up" with the write-up's points (docs/rubric.md: "(every stage: W points)") and a row "stage"
# (total + W). And every points file follows the rule of docs/grading.md "Points per task" (points by
# effort): per task, by its class in exercises/NN_name/stage.json, formula 3 to 5, short derivation 6,
# algorithm 8, derivation 15 (a bonus task is beside the rule); the experiment 7: the predictions
# (Experiments.*Predicted) 4, the measurements (Experiments.*Measured) 2, AnswerFileIsComplete 1; every
# test a multiple of 0.5. Then it proves it fails on copies with one number changed (sheet and file,
# and a file that breaks the rule).
# Usage: sheet_points_check.sh SOURCE_DIR
set -u
root=$1

writeup=$(sed -n 's/^## The scale (every stage: \([0-9]*\) points)$/\1/p' "$root/docs/rubric.md")
[[ -n $writeup ]] || { echo "FAIL: docs/rubric.md has no heading '## The scale (every stage: W points)'"; exit 1; }

check() {  # check TREE: one line per disagreement
  local tree=$1 bad=0 pf name sheet want got
  for pf in "$tree"/tests/[0-9][0-9]_*.points.json; do
    name=$(basename "$pf" .points.json) sheet=$tree/exercises/$name/README.md
    [[ -f $sheet ]] || { echo "$name: no sheet exercises/$name/README.md"; bad=1; continue; }
    # "ROW POINTS" lines from the file: per task N.M, Experiments, total
    want=$(jq -r --argjson w "$writeup" 'def task: capture("^Task(?<n>[0-9]+)_(?<m>[0-9]+)_") | "\(.n).\(.m)";
      .bonus as $bonus | .tests | to_entries
      | (map(select(.key | startswith("Task"))) | group_by(.key | task)[] | "\(.[0].key | task) \(map(.value) | add)"),
        "Experiments \(map(select(.key | startswith("Experiments.")) | .value) | add // 0)",
        "total \(map(.value) | add)", "Write-up \($w)", "stage \((map(.value) | add) + $w)",
      (($bonus // {}) | to_entries | map(.key |= sub("^Bonus"; "Task"))
        | group_by(.key | task)[] | "\(.[0].key | task)(bonus) \(map(.value) | add)")' "$pf" | sort)
    # the same from the sheet's table (first and last cell of each row after the header)
    got=$(sed -n '/^## Before you start/,/^## /p' "$sheet" \
      | sed -n '/^| task | what | points |$/,/^$/p' | tail -n +3 | grep '^|' \
      | awk -F'|' '{ t = $2; p = $(NF - 1); gsub(/[ *]/, "", t); gsub(/[ *]/, "", p); print t, p }' | sort)
    [[ -n $got ]] || { echo "exercises/$name/README.md: no '| task | what | points |' table in '## Before you start'"; bad=1; continue; }
    [[ $got == "$want" ]] || {
      echo "exercises/$name/README.md: the Points table disagrees with tests/$name.points.json (< sheet, > file):"
      diff <(echo "$got") <(echo "$want") | grep '^[<>]'
      bad=1
    }
  done
  return $bad
}

rule() {  # rule TREE: one line per points file that breaks docs/grading.md's points by effort
  local tree=$1 bad=0 pf name
  for pf in "$tree"/tests/[0-9][0-9]_*.points.json; do
    name=$(basename "$pf" .points.json)
    jq -r --slurpfile m "$tree/exercises/$name/stage.json" --arg f "tests/$name.points.json" '
      def task: capture("^Task(?<n>[0-9]+)_(?<m>[0-9]+)_") | "\(.n).\(.m)";
      def range: {"formula": [3, 5], "short derivation": [6, 6], "algorithm": [8, 8], "derivation": [15, 15]}[.];
      .tests as $t
      | ($m[0].tasks[] | select(.bonus | not) | .task as $n | .class as $c
         | ([$t | to_entries[] | select(.key | task? == $n) | .value] | add // 0) as $p
         | ($c | range) as $r
         | select($p < $r[0] or $p > $r[1]) | "\($f): task \($n) (\($c)) has \($p) points, the rule gives \($r[0])\(if $r[1] > $r[0] then " to \($r[1])" else "" end)"),
        ([$t | to_entries[] | select(.key | test("^Experiments\\..*Predicted$")) | .value] | add // 0 | select(. != 4) | "\($f): the predictions have \(.) points, the rule gives 4"),
        ([$t | to_entries[] | select(.key | test("^Experiments\\..*Measured$")) | .value] | add // 0 | select(. != 2) | "\($f): the measurements have \(.) points, the rule gives 2"),
        ($t["Experiments.AnswerFileIsComplete"] // 0 | select(. != 1) | "\($f): Experiments.AnswerFileIsComplete has \(.) points, the rule gives 1"),
        ($t | to_entries[] | select(.value * 2 != (.value * 2 | floor)) | "\($f): \(.key) has \(.value) points, not a multiple of 0.5")' "$pf" || bad=1
  done
  return $bad
}

sheets=$(ls "$root"/tests/[0-9][0-9]_*.points.json | wc -l)
((sheets >= 7)) || { echo "FAIL: only $sheets points files found"; exit 1; }
check "$root" || { echo "FAIL: a task sheet shows other points than its points file"; exit 1; }
broken=$(rule "$root")
[[ -z $broken ]] || { echo "$broken"; echo "FAIL: a points file breaks the rule of docs/grading.md (points by effort)"; exit 1; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/t/tests" "$tmp/t/exercises/01_hooke"
cp "$root/tests/01_hooke.points.json" "$tmp/t/tests/" && cp "$root/exercises/01_hooke/README.md" "$tmp/t/exercises/01_hooke/"
jq '.tests["Task1_5_VelocityVerlet.PinnedParticleStaysPut"] += 1' "$root/tests/01_hooke.points.json" >"$tmp/t/tests/01_hooke.points.json"
out=$(check "$tmp/t")
grep -q '^< 1\.5 ' <<<"$out" && grep -q '^< total ' <<<"$out" || { echo "FAIL: the check misses a planted mismatch"; exit 1; }
# a file that breaks the rule: a formula task with many points, a derivation with few
mkdir -p "$tmp/r/tests" "$tmp/r/exercises/01_hooke"
cp "$root/exercises/01_hooke/stage.json" "$tmp/r/exercises/01_hooke/"
jq '.tests["Task1_1_HookeForce.PullsBackWhenStretched"] += 4 | .tests["Task1_5_VelocityVerlet.PinnedParticleStaysPut"] -= 0.5' \
  "$root/tests/01_hooke.points.json" >"$tmp/r/tests/01_hooke.points.json"
out=$(rule "$tmp/r")
grep -q 'task 1.1 (formula) has 9 points, the rule gives 3 to 5' <<<"$out" && grep -q 'task 1.5 (derivation) has 14.5 points, the rule gives 15' <<<"$out" \
  || { echo "FAIL: the rule check misses a planted break: $out"; exit 1; }
echo "all $sheets task sheets show the points per task, the experiments, the total, the write-up and the stage's points of their points file, every points file follows the rule of points by effort (and a planted mismatch and a planted break are caught)"
