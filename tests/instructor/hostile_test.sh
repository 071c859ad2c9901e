#!/usr/bin/env bash
# The red team: every submission in tests/instructor/hostile/ (listed in attacks.tsv; each an attack
# snippet put together with today's stub by assemble_attack.sh) scores 0 on the
# stage it attacks and leaves every other stage's points, every other submission's points and the
# instructor's tree unchanged; the benign files (typical harmless student additions) are accepted.
# All of them are graded as one class, beside the reference: each attack is the reference with the
# attacked stage's folder replaced by the attack.
# full: every submission graded on every stage (the proof that nothing else changes; ctest label
# heavy). fast: each attack graded on the stage it attacks only, one class run per stage (./lab test).
# full with STAGES ("04" or "02,04"): every submission graded on those stages only (the fast proof for
# the cross-stage attacks: a stage none of them attacks keeps the reference's points).
# Usage: hostile_test.sh SOURCE_DIR GRADER KIT full|fast [name-regex] [STAGES]
set -u
root=$1 grader=$2 kit=$3 mode=$4 only=${5:-.} stages=${6:-}
grade_only=(); for s in ${stages//,/ }; do grade_only+=(--stage "$s"); done
hostile=$root/tests/instructor/hostile
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
chmod 711 "$tmp"  # container mode: a run's user passes through to its work folder (bubblewrap mounts it)
# What the reference lost, from its feedback files: the message of each test that did not pass.
reference_losses() {
  for f in "$tmp"/out*/feedback/reference.json; do
    [[ -f $f ]] && jq -r '.. | objects | select(has("passed") and .passed == false) | "  \(.name): \(.message // "" | .[0:300])"' "$f"
  done
}
fail() { echo "FAIL: $*"; [[ $* == *"the reference scores"* ]] && reference_losses; exit 1; }
[[ -f $hostile/attacks.tsv ]] || fail "$hostile/attacks.tsv: missing"

before=$(cd "$root" && { git status --porcelain 2>/dev/null; cat tests/*.points.json; } | cksum)
mkdir -p "$tmp/class"
cp -r "$root/solutions" "$tmp/class/reference"
declare -A stage_of kind_of open_of
n=0
while IFS=$'\t' read -r name stage _defence what expect; do
  [[ $name == name || -z $name || ! $name =~ $only ]] && continue
  student="$name"; [[ $name == benign ]] && student="benign_$stage"
  # The attack snippet on today's stub of its stage (assemble_attack.sh), in place of the reference's stage.
  bash "$root/tests/instructor/assemble_attack.sh" "$root" "$student" "$stage" "$tmp/attack_$student" \
    || fail "attacks.tsv: $name: cannot put the attack together"
  dir=$(cd "$tmp/attack_$student" && ls -d "$stage"_*/)
  cp -r "$root/solutions" "$tmp/class/$student"
  rm -rf "$tmp/class/$student/${dir%/}"
  cp -r "$tmp/attack_$student/${dir%/}" "$tmp/class/$student/"
  stage_of[$student]=$stage
  kind_of[$student]=$([[ $what == benign:* ]] && echo benign || echo attack)
  [[ ${expect:-} == known-open ]] && open_of[$student]=1
  n=$((n + 1))
done <"$hostile/attacks.tsv"
((n > 0)) || fail "no attack matches '$only'"

# --timeout 8 (CPU seconds per process; the wall clock 24 s): the reference's slowest graded test
# (Experiments.CurtainStrainMeasured, curtain runs through the submission's process) needs
# between 2 and 4 s; the attacks that spin or sleep end sooner than with the default 30 s.
if [[ $mode == full ]]; then
  "$grader" --kit "$kit" --class "$tmp/class" --out "$tmp/out" --timeout 8 "${grade_only[@]}" >"$tmp/grade.log" 2>&1 \
    || { tail -20 "$tmp/grade.log"; fail "the class grading run failed"; }
  book=$tmp/out/gradebook.csv
else  # one run per attacked stage, that stage only; the gradebooks joined (other stages read 0 there)
  book=$tmp/gradebook.csv
  for s in $(printf '%s\n' "${stage_of[@]}" | sort -u); do
    mkdir -p "$tmp/class_$s"
    mv "$tmp/class/reference" "$tmp/class_$s/reference"
    for st in "${!stage_of[@]}"; do [[ ${stage_of[$st]} == "$s" ]] && mv "$tmp/class/$st" "$tmp/class_$s/"; done
    "$grader" --kit "$kit" --class "$tmp/class_$s" --out "$tmp/out_$s" --stage "$s" --timeout 8 >"$tmp/grade_$s.log" 2>&1 \
      || { tail -20 "$tmp/grade_$s.log"; fail "the class grading run for stage $s failed"; }
    mv "$tmp/class_$s/reference" "$tmp/class/reference"
    [[ -f $book ]] || head -1 "$tmp/out_$s/gradebook.csv" >"$book"
    tail -n +2 "$tmp/out_$s/gradebook.csv" | grep -v '^reference,' >>"$book"
    grep '^reference,' "$tmp/out_$s/gradebook.csv" >>"$tmp/reference_rows.csv"
  done
  # The reference row: each stage's points from the run that graded it.
  IFS=, read -r -a H0 <<<"$(head -1 "$book")"
  ref_row="reference"
  for ((i = 1; i <= ${#H0[@]} - 5; i++)); do
    p=0; while IFS=, read -r -a RR; do [[ ${RR[$i]} != 0 ]] && p=${RR[$i]}; done <"$tmp/reference_rows.csv"
    ref_row+=",$p"
    if printf '%s\n' "${stage_of[@]}" | grep -qx "${H0[$i]}"; then  # a graded stage: the reference keeps full points
      pf=$(ls "$root"/tests/"${H0[$i]}"_*.points.json)
      want=$(jq '[.tests[]] | add' "$pf")  # the graded tests' points, experiments included
      [[ $p == "$want" ]] || fail "the reference scores $p of $want on stage ${H0[$i]}"
    fi
  done
  echo "$ref_row,0,0,ok,0" >>"$book"
fi
[[ -f $book ]] || fail "no gradebook"
# Columns: student,01,...,07,total,max,status,bonus. The reference row gives each stage's maximum.
header=$(head -1 "$book")
ref=$(grep '^reference,' "$book") || fail "no reference row"
IFS=, read -r -a H <<<"$header"
IFS=, read -r -a R <<<"$ref"
nstages=$((${#H[@]} - 5))
[[ $mode == fast || ${R[$((nstages + 1))]} == "${R[$((nstages + 2))]}" ]] || fail "the reference scores ${R[$((nstages + 1))]} of ${R[$((nstages + 2))]}: $ref"
bad=0
while IFS= read -r row; do
  IFS=, read -r -a C <<<"$row"
  student=${C[0]}
  [[ $student == student || $student == reference ]] && continue
  s=${stage_of[$student]:-}
  [[ -n $s ]] || { echo "unexpected row: $row"; bad=1; continue; }
  status=$(echo "$row" | cut -d, -f$((nstages + 4)))
  for ((i = 1; i <= nstages; i++)); do
    if [[ ${H[$i]} == "$s" && -n ${open_of[$student]:-} ]]; then
      # A known open hole (attacks.tsv: known-open; README "Not covered"): reported, and the day it
      # scores 0 this test fails so that the mark is removed.
      [[ ${C[$i]} != 0 ]] || { echo "$student: scores 0 now: the known hole is closed, remove 'known-open' in attacks.tsv and README"; bad=1; }
      echo "KNOWN OPEN: $student still scores ${C[$i]} on stage $s (README: not covered)"
    elif [[ ${H[$i]} == "$s" ]]; then
      [[ ${C[$i]} == 0 ]] || { echo "$student: ${C[$i]} points on the stage it attacks ($s), want 0"; bad=1; }
    elif [[ $mode == full ]]; then
      [[ ${C[$i]} == "${R[$i]}" ]] || { echo "$student: stage ${H[$i]} scores ${C[$i]}, want ${R[$i]} (an attack must not change other stages)"; bad=1; }
    fi
  done
  if [[ ${kind_of[$student]} == benign ]]; then
    [[ $status == ok ]] || { echo "$student: a benign file is not accepted: $status"; bad=1; }
  fi
  printf "%-34s stage %s  %s\n" "$student" "$s" "$(echo "$status" | cut -c1-100)"
done <"$book"
after=$(cd "$root" && { git status --porcelain 2>/dev/null; cat tests/*.points.json; } | cksum)
[[ $before == "$after" ]] || { echo "the instructor's tree changed (git status or points files)"; bad=1; }
((bad == 0)) || { tail -5 "$tmp/grade.log"; fail "an attack got through (lines above)"; }
if [[ -n $stages ]]; then
  echo "$n hostile or benign submissions graded on stage(s) $stages only: each keeps the reference's points there, the reference keeps full points, the tree is unchanged"
elif [[ $mode == full ]]; then
  echo "$n hostile or benign submissions: each attack scores 0 on its stage, no other stage or submission changes, the reference keeps full points, benign files are accepted, the tree is unchanged"
else
  echo "$n hostile or benign submissions, each graded on the stage it attacks: every attack scores 0 there, benign files are accepted, the tree is unchanged (every stage: ctest -L heavy)"
fi
