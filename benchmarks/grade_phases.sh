#!/usr/bin/env bash
# Where the time of grading one submission goes: compile, link and the tests of each stage.
#   bash benchmarks/grade_phases.sh [BUILD_DIR] [ROUNDS]     (defaults: build, 3)
# Needs the grading kit (./lab build, or cmake --build BUILD_DIR --target clothlab-grade-kit).
#
# Grades solutions/ (all seven stages) with `clothlab-grade --jobs 1` in a fresh work folder, as a
# class grades each student (one job; --class runs two students at once), and reads the times off the
# grader's progress lines (it compiles every stage, then links every stage, then runs all their tests:
# "compiling stage", "linking stage", "grading stages"). Two kits, interleaved
# round by round: the build's kit as it is, and a copy that links with the default linker (ld.bfd)
# instead of gold (nothing else differs: same objects, headers and flags). Prints per kit the median
# over the rounds of: compile (all seven stages), link (the two programs of each stage), tests (every
# stage's tests) and the whole grading. Not covered: building the kit, a class's
# shared cache (a class links each stage's test program once for all students).
set -euo pipefail
build=${1:-build}
rounds=${2:-3}
cd "$(dirname "$0")/.."
kit=$build/grade-kit/kit.json
[[ -f $kit && -x $build/bin/clothlab-grade ]] || { echo "error: $kit missing: cmake --build $build --target clothlab-grade-kit" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
jq '.link_flags |= map(select(. != "-fuse-ld=gold"))' "$kit" >"$tmp/kit_bfd.json"
if cmp -s <(jq -S . "$kit") <(jq -S . "$tmp/kit_bfd.json"); then
  echo "note: this kit does not link with gold (no ld.gold here): both rows use ld.bfd" >&2
fi

# phases KIT: one grading; prints "compile link tests total" in seconds
phases() {
  local work=$tmp/work start
  rm -rf "$work"
  start=$(date +%s.%N)
  "$build/bin/clothlab-grade" --kit "$1" --submission solutions --work "$work" --jobs 1 --quiet 2>&1 >/dev/null |
    while IFS= read -r line; do echo "$(date +%s.%N) $line"; done >"$tmp/progress.txt"
  awk -v start="$start" -v end="$(date +%s.%N)" '
    / linking stage / { if (!linked) linked = $1 }
    / grading stages? / { if (!graded) graded = $1 }
    END { printf "%.2f %.2f %.2f %.2f\n", linked - start, graded - linked, end - graded, end - start }' "$tmp/progress.txt"
}

for ((r = 1; r <= rounds; r++)); do
  echo "round $r of $rounds" >&2
  phases "$kit" >>"$tmp/gold.txt"
  phases "$tmp/kit_bfd.json" >>"$tmp/bfd.txt"
done
median() { sort -n | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
printf "%-22s %9s %9s %9s %9s\n" "kit (median of $rounds)" compile link tests total
for k in gold bfd; do
  row=()
  for col in 1 2 3 4; do row+=("$(cut -d' ' -f"$col" "$tmp/$k.txt" | median)"); done
  printf "%-22s %8.1fs %8.1fs %8.1fs %8.1fs\n" "$([[ $k == gold ]] && echo "the kit (gold)" || echo "ld.bfd")" "${row[@]}"
done
