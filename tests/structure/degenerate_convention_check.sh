#!/usr/bin/env bash
# One convention for degenerate input: the notation table of every stage's sheet carries the
# same "degenerate" row (a length below 1e-12 m, an area |a × b| below 1e-12 m²); every contract (a doc
# block of an exercise header) and every hint that speaks of coincident points or zero-area triangles
# states that threshold; no text uses another one ("(nearly) zero", "its square is 0", "exactly zero").
# The check runs on the tree and then on copies with one violation planted each, which it must fail.
# Usage: degenerate_convention_check.sh SOURCE_DIR
set -u
root=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

# check TREE: prints each violation, exit 1 if any.
check() {
  local t=$1 bad=0 f row first=""
  for f in "$t"/exercises/[0-9][0-9]_*/README.md; do
    row=$(grep '^| degenerate (\*entartet\*) |' "$f")
    [[ -n $row ]] || { echo "$f: the notation table has no 'degenerate' row"; bad=1; continue; }
    [[ $row == *"1e-12 m"* && $row == *"1e-12 m²"* ]] || { echo "$f: the 'degenerate' row does not state 1e-12 m and 1e-12 m²"; bad=1; }
    [[ -z $first || $row == "$first" ]] || { echo "$f: the 'degenerate' row differs from the other sheets'"; bad=1; }
    first=$row
  done
  # Contracts: each block of /// lines in an exercise header that mentions coincident points or a
  # zero-area triangle states 1e-12.
  for f in "$t"/framework/include/clothlab/exercise/*.h; do
    awk -v file="$f" '
      /^ *\/\/\// { block = block "\n" $0; if (start == 0) start = NR; next }
      { judge(); block = ""; start = 0 }
      END { judge() }
      function judge() {
        if (tolower(block) ~ /coincident|zero-area|zero area/ && block !~ /1e-12/) {
          printf "%s:%d: a contract speaks of degenerate input without its threshold (1e-12: notation table)\n", file, start; bad = 1
        }
      }
      END { exit bad }' "$f" || bad=1
  done
  # Hints: each hint text that mentions coincident points states 1e-12; no other threshold anywhere.
  for f in "$t"/exercises/[0-9][0-9]_*/hints.json; do
    jq -r '.. | strings' "$f" | grep -i 'coincident' | grep -v '1e-12' | sed "s|^|$f: a hint speaks of coincident points without 1e-12: |" | grep . && bad=1
  done
  grep -rn -i -E '\(nearly\) zero|its square is 0|square is zero|exactly zero length' "$t"/exercises/*/hints.json \
    "$t"/exercises/*/README.md "$t"/framework/include/clothlab/exercise/ && { echo "(another threshold for degenerate input than 1e-12)"; bad=1; }
  return $bad
}

mk() { rm -rf "$tmp/t"; mkdir -p "$tmp/t/framework/include/clothlab"; cp -r "$root/exercises" "$tmp/t/"; cp -r "$root/framework/include/clothlab/exercise" "$tmp/t/framework/include/clothlab/"; }
check "$root" || { echo "FAIL: the tree breaks the degenerate-input convention (lines above)"; exit 1; }
# Planted violations: each must be found.
mk; sed -i 's/below 1e-12 m (degenerate: notation table), return zero/(nearly) zero, return zero/' "$tmp/t/exercises/01_hooke/hints.json"
check "$tmp/t" >/dev/null && { echo "FAIL: a hint with '(nearly) zero' passed"; exit 1; }
mk; sed -i 's/(|p1 − p2| < 1e-12 m, degenerate: notation table)//' "$tmp/t/framework/include/clothlab/exercise/04_distance.h"
check "$tmp/t" >/dev/null && { echo "FAIL: a contract without its threshold passed"; exit 1; }
mk; sed -i 's/^| degenerate (\*entartet\*) |.*$/| degenerate (*entartet*) | a length below 1e-9 m | m |/' "$tmp/t/exercises/05_bending/README.md"
check "$tmp/t" >/dev/null && { echo "FAIL: a sheet with another 'degenerate' row passed"; exit 1; }
echo "one degenerate-input convention (1e-12 m, 1e-12 m²) in every sheet, contract and hint; 3 planted violations found"
