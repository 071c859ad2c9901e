#!/usr/bin/env bash
# Bubblewrap's PID namespace is load-bearing (issue 44; tests/instructor/hostile/README.md, "Every attack
# proven live"). The grader runs as root here, so bubblewrap runs every program as one user (nobody):
# without a PID namespace of its own a run could signal every other run of that user. The attack
# kill_other_runs starts a setsid() daemon that sends SIGKILL to every process it may signal for 30 s.
# Graded in a class beside the reference (two students at once) by clothlab-grade-weakened with
# CLOTHLAB_WEAKEN=pid (bubblewrap without --unshare-pid, the programs as a user of this test's own,
# 64198, so that the daemon reaches this test's runs and no other program of user nobody), the
# reference must lose points, and lose them to SIGKILL (its failure messages say so). With the PID
# namespace on (clothlab-grade), the same class gives the attack 0 and the reference full points.
# Usage: pid_namespace_test.sh SOURCE_DIR BUILD_DIR. As root with bubblewrap working, else exit 77 (skipped).
set -u
root=$1 build=$2
weakened=$build/bin/clothlab-grade-weakened kit=$build/grade-kit/kit.json
fail() { echo "FAIL: $*"; exit 1; }
[[ $(id -u) == 0 ]] || { echo "skipped: bubblewrap runs the programs as user nobody only when the grader is root"; exit 77; }
[[ -x $weakened && -f $kit ]] || fail "build clothlab-grade-weakened and the grading kit first"
[[ $("$build/bin/clothlab-grade" --which-sandbox 2>/dev/null) == bubblewrap:* ]] || { echo "skipped: bubblewrap does not work here"; exit 77; }
kill_test_user() {  # the daemon, if still running (it ends by itself within 30 s): every process of user 64198
  for s in /proc/[0-9]*/status; do
    [[ $(awk '/^Uid:/ { print $2 }' "$s" 2>/dev/null) == 64198 ]] && kill -9 "$(basename "$(dirname "$s")")" 2>/dev/null
  done
}
tmp=$(mktemp -d); trap 'kill_test_user; rm -rf "$tmp"' EXIT
mkdir -p "$tmp/class/2_reference"
bash "$root/tests/instructor/assemble_attack.sh" "$root" kill_other_runs 01 "$tmp/class/1_kill_other_runs" || fail "assembling kill_other_runs"
cp -r "$root"/solutions/01_* "$tmp/class/2_reference/"
want=$(jq -s '[.[] | (.tests + (.bonus // {})) | to_entries[] | .value] | add' "$root"/tests/01_*.points.json)
CLOTHLAB_WEAKEN=pid "$weakened" --kit "$kit" --class "$tmp/class" --out "$tmp/out" --stage 01 --jobs 2 --timeout 8 \
  --sandbox bubblewrap >"$tmp/grade.log" 2>&1 || { tail -5 "$tmp/grade.log"; fail "the weakened grader (pid)"; }
kill_test_user
feedback=$tmp/out/feedback/2_reference.json
got=$(jq '.stages[0].points + .stages[0].bonus' "$feedback")
[[ $got != "$want" ]] || fail "without the PID namespace kill_other_runs did not cost the reference a point ($got of $want): DEAD"
jq -e '[.stages[0].problem, .stages[0].tests[].message] | any(test("signal 9|[Kk]illed"))' "$feedback" >/dev/null \
  || fail "the reference lost points ($got of $want), but not to SIGKILL: $(jq -c '[.stages[0].status, .stages[0].problem[:200], [.stages[0].tests[].message[:120]]]' "$feedback")"
# The same class with the namespace (clothlab-grade, as ./lab grade runs it): the attack 0, the reference all.
"$build/bin/clothlab-grade" --kit "$kit" --class "$tmp/class" --out "$tmp/out_on" --stage 01 --jobs 2 --timeout 8 \
  >"$tmp/grade_on.log" 2>&1 || { tail -5 "$tmp/grade_on.log"; fail "clothlab-grade"; }
on=$(jq '.stages[0].points + .stages[0].bonus' "$tmp/out_on/feedback/2_reference.json")
attack=$(jq '.stages[0].points + .stages[0].bonus' "$tmp/out_on/feedback/1_kill_other_runs.json")
[[ $on == "$want" && $attack == 0 ]] || fail "with the PID namespace: the reference $on of $want, kill_other_runs $attack (want $want and 0)"
echo "with it (clothlab-grade): the reference $on of $want, kill_other_runs 0"
echo "without bubblewrap's PID namespace kill_other_runs killed the runs of the student graded beside it: the reference scored $got of $want (SIGKILL in its messages)"
