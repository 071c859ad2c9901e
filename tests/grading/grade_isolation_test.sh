#!/usr/bin/env bash
# One broken stage costs one stage: a submission that is the reference except for a stage-01 file
# that does not compile gets 0 points for stage 01, with the compiler's message, and full points for
# every other stage (each stage is graded with the reference for the stages it is not about).
# Usage: grade_isolation_test.sh SOURCE_DIR GRADER KIT [more clothlab-grade options]
set -u
root=$1 grader=$2 kit=$3; shift 3
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

mkdir -p "$tmp/sub"
cp -r "$root"/solutions/[0-9][0-9]_* "$tmp/sub/"
echo 'this line is not C++ ;' >>"$tmp/sub/01_hooke/hooke.cpp"
"$grader" --kit "$kit" --submission "$tmp/sub" --work "$tmp/work" "$@" >"$tmp/grade.log" 2>&1
grep -q "DOES NOT COMPILE" "$tmp/grade.log" || { tail -20 "$tmp/grade.log"; fail "the broken stage 01 is not reported"; }
grep -q "hooke.cpp:[0-9]*:[0-9]*: error" "$tmp/grade.log" || { tail -20 "$tmp/grade.log"; fail "the compiler's message (file:line) is not shown"; }
# The grader's table: one row per stage, "NN  title  passed / tests  points / max" (then "+ B bonus"
# for a stage with bonus tests: cut first).
awk '
  /^[0-9][0-9] / { sub(/ *[+] [0-9.]+ bonus *$/, ""); n++; got = $(NF-2); max = $NF
    if ($1 == "01" && got + 0 != 0) { print "stage 01: " got " points, want 0"; bad = 1 }
    if ($1 != "01" && got + 0 != max + 0) { print "stage " $1 ": " got " of " max " points, want all"; bad = 1 } }
  END { if (n < 6) { print "only " n " stages graded"; bad = 1 }; exit bad }' "$tmp/grade.log" \
  || { tail -15 "$tmp/grade.log"; fail "one broken stage must cost exactly one stage"; }
echo "a stage that does not compile costs that stage only (0 points, with the compiler's message); the other stages keep full points"
