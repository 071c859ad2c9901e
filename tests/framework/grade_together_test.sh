#!/usr/bin/env bash
# The grader runs a stage's tests together first and reruns alone every test that did not pass there
# (docs/grading.md, "run"). Checked against the tests run one by one, without the grader: a
# submission that is the reference of stage 05 except that bendingStencils() crashes gets exactly the
# passes its tests give when each runs in a process of its own, and every other test fails with the
# crash in its message.
# Usage: grade_together_test.sh SOURCE_DIR GRADER KIT
set -u
root=$1 grader=$2 kit=$3
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

mkdir -p "$tmp/sub"
cp -r "$root"/solutions/[0-9][0-9]_* "$tmp/sub/"
f=$tmp/sub/05_bending/bending.cpp
grep -q '^std::vector<BendingStencil> bendingStencils(.*) {$' "$f" || fail "bendingStencils() not found in $f"
sed -i 's/^\(std::vector<BendingStencil> bendingStencils(.*) {\)$/\1 *static_cast<volatile int*>(nullptr) = 1;/' "$f"
"$grader" --kit "$kit" --submission "$tmp/sub" --work "$tmp/work" --only 05 --json "$tmp/r.json" >"$tmp/grade.log" 2>&1
[[ -f $tmp/r.json ]] || { tail "$tmp/grade.log"; fail "no results"; }
jq -r '.stages[0].tests[] | select(.passed) | .name' "$tmp/r.json" | sort >"$tmp/grader.txt"
# The same programs, each test alone, outside the grader.
exe=$tmp/work/bin/grade_05
server=$(ls "$tmp"/work/bin/submission_* | grep -v '\.key$' | head -1)
[[ -x $exe && -x $server ]] || fail "the grader's programs are not in $tmp/work/bin"
: >"$tmp/alone.txt"
for t in $(jq -r '.stages[0].tests[].name' "$tmp/r.json"); do
  CLOTHLAB_ANSWERS_DIR=$tmp/sub/05_bending OMP_NUM_THREADS=1 "$exe" --gtest_filter="$t" --clothlab-server="$server" >"$tmp/one.log" 2>&1 \
    && echo "$t" >>"$tmp/alone.txt"
done
sort -o "$tmp/alone.txt" "$tmp/alone.txt"
diff "$tmp/alone.txt" "$tmp/grader.txt" >"$tmp/diff.txt" || { cat "$tmp/diff.txt"; fail "the grader's passes (>) differ from the tests run alone (<)"; }
passed=$(wc -l <"$tmp/grader.txt") all=$(jq '.stages[0].tests | length' "$tmp/r.json")
((passed > 0 && passed < all)) || fail "$passed of $all passed: the planted crash should fail some tests and not others"
bad=$(jq -r '.stages[0].tests[] | select(.passed | not) | select(.message | test("crashed") | not) | .name' "$tmp/r.json")
[[ -z $bad ]] || fail "failed without the crash in the message: $bad"
echo "a crash in one function: $passed of $all tests pass, the same tests as run one by one; every other one names the crash"
