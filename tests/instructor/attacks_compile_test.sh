#!/usr/bin/env bash
# Every red-team attack, put together with today's stub (assemble_attack.sh), compiles when the
# instructor's tree is in view (-I framework/include, tests/ and the generated test headers). An
# attack that no longer compiles would score 0 in the grader for the wrong reason and test nothing:
# this catches the attack left behind by a changed signature or test file.
# Usage: attacks_compile_test.sh SOURCE_DIR GENERATED_DIR [name-regex]
set -u
root=$1 generated=$2 only=${3:-.}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
list=$tmp/list
while IFS=$'\t' read -r name stage _; do
  [[ $name == name || -z $name || ! $name =~ $only ]] && continue
  student=$name; [[ $name == benign ]] && student=benign_$stage
  bash "$root/tests/instructor/assemble_attack.sh" "$root" "$student" "$stage" "$tmp/$student" || exit 1
  echo "$student $(ls "$tmp/$student"/*/*.cpp)" >>"$list"
done <"$root/tests/instructor/hostile/attacks.tsv"
[[ -s $list ]] || { echo "FAIL: no attack matches '$only'"; exit 1; }
# Two compilers at a time; each prints its attack's name and first error when it fails.
xargs -P 2 -L 1 bash -c 'g++ -std=c++17 -fsyntax-only -I "$0/framework/include" -I "$0/tests" -I "$1" \
    -isystem /usr/include/eigen3 "$3" 2>"$3.err" || { echo "FAIL: attack $2 does not compile:"; grep -m3 error "$3.err"; }' \
    "$root" "$generated" <"$list" >"$tmp/out"
cat "$tmp/out"
! grep -q FAIL "$tmp/out" || exit 1
echo "$(wc -l <"$list") attacks put together with today's stubs: each compiles"
