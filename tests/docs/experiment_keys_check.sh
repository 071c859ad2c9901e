#!/usr/bin/env bash
# The student copy holds no experiment's key: no file that ./lab release ships (the committed files
# tools/student_copy.txt lists) contains a number the reference's answers.json enters (predictions
# and measurements, written to 4 significant digits, as a word; numbers of fewer digits, such as 0.25,
# 1.02 or 2, are everyday numbers and not searched, nor are the meshes' vertex lists), and no sheet's
# experiment states a tolerance.
# Usage: experiment_keys_check.sh SOURCE_DIR
set -uo pipefail
root=$1
cd "$root" || exit 1
bad=0
mapfile -t keep < <(sed 's/#.*//; s/[[:space:]]*$//' tools/student_copy.txt | grep .)
mapfile -t shipped < <(git ls-files -- "${keep[@]}" | grep -v -E '\.obj$' | while read -r f; do [[ -f $f ]] && echo "$f"; done)
((${#shipped[@]} > 100)) || { echo "FAIL: git ls-files lists ${#shipped[@]} files in $root"; exit 1; }
n=0
for answers in solutions/[0-9][0-9]_*/answers.json; do
  while IFS=$'\t' read -r name value; do
    for shown in $(printf '%.4g' "$value"); do
      digits=$(tr -cd '0-9' <<<"${shown%%e*}" | sed 's/^0*//')
      ((${#digits} >= 4)) || continue
      n=$((n + 1))
      hits=$(grep -lwF -- "$shown" "${shipped[@]}" 2>/dev/null | head -3 | tr '\n' ' ')
      [[ -z $hits ]] || { echo "FAIL: $answers $name = $value: $shown is in the student copy: $hits"; bad=1; }
    done
  done < <(jq -r '(.predict, .measure) | to_entries[] | select(.value.value != null) | "\(.key)\t\(.value.value)"' "$answers")
done
((n >= 10)) || { echo "FAIL: only $n key numbers searched: are the reference answers filled in?"; exit 1; }
for sheet in exercises/[0-9][0-9]_*/README.md; do
  section=$(sed -n '/^## Experiment/,/^## [^E]/p' "$sheet")
  grep -nE 'within|±|tolerance|graded against' <<<"$section" && { echo "FAIL: $sheet: its experiment states how it is graded (a target or a tolerance)"; bad=1; }
done
((bad == 0)) && echo "$n key numbers of the reference answers: none is in the ${#shipped[@]} files of the student copy; no sheet states a tolerance" || exit 1
