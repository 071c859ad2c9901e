#!/usr/bin/env bash
# The graded experiments (TEST(Experiments, ...)) grade the numbers in answers.json: with the reference
# code and the reference answers every experiment passes; with the stub answers (null), a missing file
# or malformed JSON every experiment fails with a message naming the file (and the field), without a
# crash; and each reference number made wrong (times 1.5) fails the experiment that grades it.
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
((total > 0)) || { echo "FAIL: $bin has no Experiments tests"; exit 1; }
[[ -f $ref/answers.json && -f $stub/answers.json ]] || { echo "FAIL: no $ref/answers.json or $stub/answers.json"; exit 1; }
jq -e 'to_entries | all(.value.value == null and (.value.how | type == "string"))' "$stub/answers.json" >/dev/null \
  || fail "$stub/answers.json: every field must have \"value\": null and a \"how\" text"
[[ "$(jq -c keys "$ref/answers.json")" == "$(jq -c keys "$stub/answers.json")" ]] \
  || fail "the reference and the stub answers.json name different fields"

run "$ref"
((rc == 0 && passed == total)) || { echo "$out" | tail -30; fail "the reference code with $ref/answers.json: $passed of $total experiments pass"; }
echo "reference answers: $passed of $total experiments pass"

run "$stub"
((rc == 1 && failed == total)) || fail "the stub answers (null): $failed of $total experiments fail (exit $rc), want all"
grep -q 'answers.json: .*null, not measured yet' <<<"$out" || fail "the stub answers: no message naming the file and the null field"
echo "stub answers (null): $failed of $total experiments fail"

run "$work/missing"
((rc == 1 && failed == total)) || fail "no answers file: $failed of $total experiments fail (exit $rc, want 1: no crash)"
grep -q "$work/missing/answers.json: cannot read" <<<"$out" || fail "no answers file: no message naming the file"

mkdir -p "$work/malformed" && printf '{ "oops": [1, 2,\n' >"$work/malformed/answers.json"
run "$work/malformed"
((rc == 1 && failed == total)) || fail "malformed JSON: $failed of $total experiments fail (exit $rc, want 1: no crash)"
grep -q "malformed/answers.json: not valid JSON" <<<"$out" || fail "malformed JSON: no message naming the file"
echo "missing file, malformed JSON: every experiment fails with a message naming the file, no crash"

for field in $(jq -r 'keys[]' "$ref/answers.json"); do
  mkdir -p "$work/wrong_$field"
  jq --arg f "$field" '.[$f].value |= (if . == 0 then 1 else . * 1.5 end)' "$ref/answers.json" >"$work/wrong_$field/answers.json"
  run "$work/wrong_$field"
  if ((failed >= 1)) && grep -q "answers.json: $field (" <<<"$out"; then
    echo "$field made wrong (x 1.5): caught ($failed of $total experiments fail)"
  else
    fail "$field made wrong (x 1.5): no experiment fails naming it"
  fi
done
((bad == 0)) && echo "the experiments grade the numbers" || exit 1
