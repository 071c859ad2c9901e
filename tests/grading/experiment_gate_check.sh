#!/usr/bin/env bash
# A wrong implementation earns no measurement points, whatever number it measures: each stage built
# with a typical mistake that changes its experiment's physics, graded with the reference's (right)
# answers, passes its predictions (they do not depend on the code) and fails every Experiments.*Measured
# test (the instructor's physics check of the student's code comes before the number is compared).
# Usage: experiment_gate_check.sh SOURCE_DIR BIN_DIR NN_mistake ...   (e.g. 01_sign_flipped)
set -uo pipefail
root=$1 bin=$2; shift 2
bad=0
for spec in "$@"; do
  nn=${spec%%_*} mistake=${spec#*_}
  exe=$bin/grade_${nn}_mistake_$mistake
  [[ -x $exe ]] || { echo "FAIL: $exe: not built"; bad=1; continue; }
  answers=$(ls -d "$root"/solutions/"$nn"_*)
  out=$(CLOTHLAB_ANSWERS_DIR=$answers "$exe" --gtest_filter='Experiments.*Predicted:Experiments.*Measured' --gtest_color=no 2>&1)
  measured=$("$exe" --gtest_list_tests --gtest_filter='Experiments.*Measured' | grep -c '^  ')
  lost=$(grep -cE '^\[  FAILED  \] Experiments\.[A-Za-z0-9_]+Measured \(' <<<"$out")
  wrongly=$(grep -cE '^\[  FAILED  \] Experiments\.[A-Za-z0-9_]+Predicted \(' <<<"$out")
  if ((measured > 0 && lost == measured && wrongly == 0)); then
    echo "stage $nn with mistake $mistake and right numbers: $lost of $measured measurement tests lost, predictions kept"
  else
    echo "FAIL: stage $nn with mistake $mistake and right numbers: $lost of $measured measurement tests lost, $wrongly predictions lost"; bad=1
  fi
done
exit $bad
