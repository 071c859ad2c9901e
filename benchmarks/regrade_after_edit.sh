#!/usr/bin/env bash
# How long the instructor waits for a regrade after editing one file of a submission.
#   bash benchmarks/regrade_after_edit.sh [BUILD_DIR] [ROUNDS] [GRADER ...]     (defaults: build, 5)
# Needs the grading kit (./lab build, or cmake --build BUILD_DIR --target clothlab-grade-kit).
#
# Copies solutions/ to a scratch folder and grades it once per grader (a cold build, not timed), then,
# in each round and for each grader in turn: appends a comment line to 04_distance/distance.cpp and
# times `clothlab-grade --submission ... --reference none` (all seven stages; every stage links the
# submission's own code, so all of them rerun their tests). GRADER: clothlab-grade programs to compare
# (default: BUILD_DIR/bin/clothlab-grade alone), each with its own work folder, interleaved round by
# round. Prints each round's times and per grader the median, lowest and highest, and checks that
# every grading gave the reference's full points. Not covered: a cold build, --class, other stages' files.
set -euo pipefail
build=${1:-build}
rounds=${2:-5}
cd "$(dirname "$0")/.."
graders=("${@:3}")
((${#graders[@]})) || graders=("$build/bin/clothlab-grade")
kit=$build/grade-kit/kit.json
[[ -f $kit ]] || { echo "error: $kit missing: cmake --build $build --target clothlab-grade-kit" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp -r solutions "$tmp/sub"
grade() {  # grade INDEX: grades the scratch copy with grader INDEX; prints the wall time in s
  local start
  start=$(date +%s.%N)
  "${graders[$1]}" --kit "$kit" --submission "$tmp/sub" --work "$tmp/work$1" --reference none --quiet >"$tmp/out" 2>&1 ||
    { cat "$tmp/out" >&2; echo "error: ${graders[$1]} failed" >&2; exit 1; }
  grep -q '^total .* \([0-9.]*\) / \1\( \|$\)' "$tmp/out" || { cat "$tmp/out" >&2; echo "error: the reference lost points" >&2; exit 1; }
  echo "$(date +%s.%N) - $start" | bc
}
for i in "${!graders[@]}"; do grade "$i" >/dev/null; done  # the cold build, not timed
for ((r = 1; r <= rounds; r++)); do
  for i in "${!graders[@]}"; do
    echo "// edit $r/$i" >>"$tmp/sub/04_distance/distance.cpp"
    t=$(grade "$i")
    echo "$i $t" >>"$tmp/times"
    printf 'round %d/%d  %-40s %6.2f s\n' "$r" "$rounds" "${graders[$i]}" "$t"
  done
done
for i in "${!graders[@]}"; do
  awk -v i="$i" '$1 == i { print $2 }' "$tmp/times" | sort -n |
    awk -v g="${graders[$i]}" '{ v[NR] = $1 } END { printf "%-40s median %.2f s (lowest %.2f, highest %.2f; %d rounds)\n", g, (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2, v[1], v[NR], NR }'
done
