#!/usr/bin/env bash
# The stage's experiment (answers.json: predict, measure, explain) is graded by the instructor's tests
# (tests/instructor/experiments/) and checked for completeness by the student's (AnswerFileIsComplete).
# With the reference code and the reference answers every Experiments test passes; with the stub
# answers (null), a missing file, malformed JSON or a one-word explanation every one fails with a
# message naming the file (and the field), without a crash; each reference number made wrong (times 1.5)
# fails the test that grades it, and that failure names no target (not the reference's number).
# Usage: experiments_check.sh GRADED_BINARY REFERENCE_ANSWERS_DIR STUB_ANSWERS_DIR WORK_DIR
set -uo pipefail
bin=$1 ref=$2 stub=$3 work=$4
rm -rf "$work" && mkdir -p "$work"
bad=0
fail() { echo "FAIL: $*"; bad=1; }

# run DIR: the Experiments tests with CLOTHLAB_ANSWERS_DIR=DIR; sets out, rc, passed, failed
run() {
  out=$(CLOTHLAB_ANSWERS_DIR=$1 "$bin" --gtest_filter='Experiments.*' --gtest_color=no 2>&1); rc=$?
  passed=$(grep -cE '^\[       OK \] Experiments\.' <<<"$out")
  failed=$(grep -cE '^\[  FAILED  \] Experiments\.[A-Za-z0-9_]+ \(' <<<"$out")
}

total=$("$bin" --gtest_list_tests --gtest_filter='Experiments.*' | grep -c '^  ')
((total > 1)) || { echo "FAIL: $bin has no instructor's Experiments tests beside AnswerFileIsComplete"; exit 1; }
[[ -f $ref/answers.json && -f $stub/answers.json ]] || { echo "FAIL: no $ref/answers.json or $stub/answers.json"; exit 1; }
jq -e '(.predict | to_entries | all(.value.value == null and (.value.what | type == "string")))
       and (.measure | to_entries | all(.value.value == null and (.value.how | type == "string"))) and .explain == ""' \
  "$stub/answers.json" >/dev/null || fail "$stub/answers.json: every predict field needs \"value\": null and a \"what\", every measure field \"value\": null and a \"how\", and \"explain\" \"\""
[[ "$(jq -c '[(.predict | keys), (.measure | keys)]' "$ref/answers.json")" == "$(jq -c '[(.predict | keys), (.measure | keys)]' "$stub/answers.json")" ]] \
  || fail "the reference and the stub answers.json name different fields"

run "$ref"
((rc == 0 && passed == total)) || { echo "$out" | tail -30; fail "the reference code with $ref/answers.json: $passed of $total experiment tests pass"; }
echo "reference answers: $passed of $total experiment tests pass"

run "$stub"
((rc == 1 && failed == total)) || fail "the stub answers (null): $failed of $total experiment tests fail (exit $rc), want all"
grep -q 'answers.json: .*null, not entered yet' <<<"$out" || fail "the stub answers: no message naming the file and the null field"
echo "stub answers (null): $failed of $total experiment tests fail"

run "$work/missing"
((rc == 1 && failed == total)) || fail "no answers file: $failed of $total fail (exit $rc, want 1: no crash)"
grep -q "$work/missing/answers.json: cannot read" <<<"$out" || fail "no answers file: no message naming the file"

mkdir -p "$work/malformed" && printf '{ "oops": [1, 2,\n' >"$work/malformed/answers.json"
run "$work/malformed"
((rc == 1 && failed == total)) || fail "malformed JSON: $failed of $total fail (exit $rc, want 1: no crash)"
grep -q "malformed/answers.json: not valid JSON" <<<"$out" || fail "malformed JSON: no message naming the file"
echo "missing file, malformed JSON: every experiment test fails with a message naming the file, no crash"

mkdir -p "$work/short" && jq '.explain = "it agrees"' "$ref/answers.json" >"$work/short/answers.json"
run "$work/short"
grep -q '^\[  FAILED  \] Experiments.AnswerFileIsComplete (' <<<"$out" && grep -q 'answers.json: explain: 2 words' <<<"$out" \
  || fail "a two-word explanation: AnswerFileIsComplete does not fail naming explain"

# Each number made wrong: the test that grades it fails, names the field, and shows no target.
for section in predict measure; do
  for field in $(jq -r ".$section | keys[]" "$ref/answers.json"); do
    dir=$work/wrong_${section}_$field
    mkdir -p "$dir"
    jq --arg s "$section" --arg f "$field" '.[$s][$f].value |= (if . == 0 then 1 else . * 1.5 end)' "$ref/answers.json" >"$dir/answers.json"
    run "$dir"
    if ((failed >= 1)) && grep -q "answers.json: $section.$field (" <<<"$out"; then
      echo "$section.$field made wrong (x 1.5): caught ($failed of $total fail)"
    else
      fail "$section.$field made wrong (x 1.5): no experiment test fails naming it"
    fi
    right=$(jq -r --arg s "$section" --arg f "$field" '.[$s][$f].value' "$ref/answers.json")
    for shown in $(printf '%.3g %.4g %g' "$right" "$right" "$right"); do
      [[ $shown =~ ^-?[0-9]$ ]] && continue  # a one-digit integer is in every message
      grep -F "$section.$field (" <<<"$out" | grep -qF -- "$shown" && fail "$section.$field made wrong: the failure shows the right number $shown"
    done
    grep -E "$section.$field \(" <<<"$out" | grep -qiE 'expect|within|tolerance' && fail "$section.$field made wrong: the failure names a target or a tolerance"
    grep -qE 'grade(Prediction|Measurement)\(' <<<"$out" && fail "$section.$field made wrong: the failure quotes the grading call (its arguments are the target)"
  done
done
((bad == 0)) && echo "the experiments grade the numbers and show no target" || exit 1
