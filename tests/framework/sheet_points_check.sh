#!/usr/bin/env bash
# Every task sheet (exercises/NN_name/README.md) shows the points of tests/NN_name.points.json: in its
# "## Before you start" section a table "| task | what | points |" with one row per task N.M (the sum
# of the tests TaskN_M_*.*), a row "Experiments" (the sum of Experiments.*), a row "total" (the
# file's total) and, when the file has bonus tests BonusN_M_*.*, a row "N.M (bonus)" with their sum.
# Then it proves it fails on a copy with one number changed.
# Usage: sheet_points_check.sh SOURCE_DIR
set -u
root=$1

check() {  # check TREE: one line per disagreement
  local tree=$1 bad=0 pf name sheet want got
  for pf in "$tree"/tests/[0-9][0-9]_*.points.json; do
    name=$(basename "$pf" .points.json) sheet=$tree/exercises/$name/README.md
    [[ -f $sheet ]] || { echo "$name: no sheet exercises/$name/README.md"; bad=1; continue; }
    # "ROW POINTS" lines from the file: per task N.M, Experiments, total
    want=$(jq -r 'def task: capture("^Task(?<n>[0-9]+)_(?<m>[0-9]+)_") | "\(.n).\(.m)";
      .bonus as $bonus | .tests | to_entries
      | (map(select(.key | startswith("Task"))) | group_by(.key | task)[] | "\(.[0].key | task) \(map(.value) | add)"),
        "Experiments \(map(select(.key | startswith("Experiments.")) | .value) | add // 0)",
        "total \(map(.value) | add)",
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

sheets=$(ls "$root"/tests/[0-9][0-9]_*.points.json | wc -l)
((sheets >= 7)) || { echo "FAIL: only $sheets points files found"; exit 1; }
check "$root" || { echo "FAIL: a task sheet shows other points than its points file"; exit 1; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/t/tests" "$tmp/t/exercises/01_hooke"
cp "$root/tests/01_hooke.points.json" "$tmp/t/tests/" && cp "$root/exercises/01_hooke/README.md" "$tmp/t/exercises/01_hooke/"
jq '.tests["Task1_5_VelocityVerlet.PinnedParticleStaysPut"] += 1' "$root/tests/01_hooke.points.json" >"$tmp/t/tests/01_hooke.points.json"
out=$(check "$tmp/t")
grep -q '^< 1\.5 ' <<<"$out" && grep -q '^< total ' <<<"$out" || { echo "FAIL: the check misses a planted mismatch"; exit 1; }
echo "all $sheets task sheets show the points per task, the experiments and the total of their points file (and a planted mismatch is caught)"
