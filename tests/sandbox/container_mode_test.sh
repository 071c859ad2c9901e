#!/usr/bin/env bash
# The grader's two confinements (framework/grading/grader/sandbox.h, docs/grading.md "Two confinements"),
# container mode tested under docker_default, a simulation of Docker's default confinement (issue 45).
# Usage: container_mode_test.sh SOURCE_DIR BUILD_DIR MODE [ARGS]
#   launcher      docker_default refuses namespaces as Docker's default profile does: bwrap prints
#                 "Creating new namespace failed", the capabilities are Docker's default set.
#   chosen        this machine without the launcher: bubblewrap where it works, said by the table, the
#                 JSON and ./lab doctor.
#   red-team fast|full [REGEX]
#                 tests/instructor/hostile_test.sh under the launcher (grade_in_container: fails unless
#                 the grader says container mode and no failure message says "ESCAPED:").
#   load-bearing  each defence container mode adds, switched off in clothlab-grade-weakened, lets its
#                 attack through: Landlock (the reference solution read, /tmp written), seccomp (a socket
#                 to 127.0.0.1), a user per run (another run's processes killed).
#   no-landlock   under docker_default --no-landlock: one error line naming what cannot hold with the
#                 instructor's tree readable; --class refused; it grades (and says so) once the
#                 instructor's files are out of other users' reach.
#   gradescope    the Gradescope bundle's run_autograder under the launcher: a complete results.json
#                 with full points for the reference (the points files' totals), container mode named.
# As root only (container mode switches users): otherwise exit 77 (ctest: skipped).
set -u
root=$1 build=$2 mode=$3
shift 3
bin=$build/bin launcher=$build/bin/docker_default grader=$build/bin/clothlab-grade kit=$build/grade-kit/kit.json
fail() { echo "FAIL: $*"; exit 1; }
[[ $(id -u) == 0 ]] || { echo "skipped: container mode and its launcher need root"; exit 77; }
[[ -x $launcher && -x $grader && -f $kit ]] || fail "build docker_default, clothlab-grade and clothlab-grade-kit first"
# Container mode's users must pass every folder above the kit and the checkout (docs/grading.md "Two
# confinements"): a checkout under /root (mode 700) cannot be graded in container mode, and the grader
# says so in one line (checked here). The tests then run in a view where those folders let others pass:
# a private mount namespace of this test alone (unshare, as root), each such folder replaced by a
# tmpfs of mode 711 that holds a bind mount of the one entry on the way down. The host is not changed.
blocking() {  # the first folder above $root or $build (the highest first) that lets no other user pass
  local p q
  for p in "$root" "$build"; do
    p=$(realpath "$p") q=""
    local IFS=/
    for part in ${p#/}; do
      q=$q/$part
      [[ $q == "$p" ]] && break
      [[ $(( 0$(stat -c %a "$q") & 1 )) == 1 ]] || { echo "$q"; return 0; }
    done
  done
  return 1
}
if [[ $mode != launcher ]] && d=$(blocking); then
  if [[ -z ${CLOTHLAB_PASSABLE_VIEW:-} ]]; then
    "$grader" --which-sandbox --sandbox container --kit "$kit" >"/tmp/clothlab-which-$$.log" 2>&1
    grep -q "^none: the grader refuses to grade here: container mode.*: the programs cannot reach .*: $d lets no other user pass (chmod o+x it)" \
      "/tmp/clothlab-which-$$.log" || fail "the checkout lies under $d (no o+x), and the grader does not refuse with one line naming it: $(cat "/tmp/clothlab-which-$$.log")"
    rm -f "/tmp/clothlab-which-$$.log"
    echo "$d lets no other user pass: the grader refuses container mode here with one line naming it; the test goes on in a private view where it lets them pass"
    unshare --mount true 2>/dev/null || { echo "skipped: $d lets no other user pass, and no private mount namespace can be made here (unshare)"; exit 77; }
    CLOTHLAB_PASSABLE_VIEW=1 exec unshare --mount --propagation private bash "$0" "$root" "$build" "$mode" "$@"
  fi
  # In the private view: replace each blocking folder, from the top, by a passable one.
  while d=$(blocking); do
    side=$(mktemp -d /tmp/clothlab-view.XXXXXX)
    mount --bind "$d" "$side" || fail "mount --bind $d"
    mount -t tmpfs -o mode=711 clothlab-view "$d" || fail "mount tmpfs on $d"
    for p in "$(realpath "$root")" "$(realpath "$build")"; do
      [[ $p == "$d"/* ]] || continue
      e=${p#"$d"/}; e=${e%%/*}
      [[ -e $d/$e ]] && continue
      if [[ -d $side/$e ]]; then mkdir "$d/$e"; else touch "$d/$e"; fi
      mount --bind "$side/$e" "$d/$e" || fail "mount --bind $side/$e"
    done
    umount "$side" && rmdir "$side"  # (never removed with rm -r: while mounted it is $d)
  done
fi
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
chmod 711 "$tmp"  # the runs' users pass through to their work folders (Landlock adds no permission)
# The reference as a submission: every stage folder of solutions/ (with its answers.json).
reference() { mkdir -p "$1" && cp -r "$root"/solutions/[0-9][0-9]_* "$1/"; }
# The sum of the points a stage's tests (and bonus tests) are worth, from the points files themselves.
max_points() { jq -s '[.[] | (.tests + (.bonus // {})) | to_entries[] | .value] | add' "$@"; }

case $mode in
launcher)
  "$launcher" bwrap --dev-bind / / true >"$tmp/bwrap.log" 2>&1 && fail "bwrap made its namespaces under docker_default"
  grep -q "bwrap: Creating new namespace failed: Operation not permitted" "$tmp/bwrap.log" \
    || fail "bwrap under docker_default: $(cat "$tmp/bwrap.log")"
  # Docker's default capabilities (moby's oci/caps/defaults.go): CHOWN DAC_OVERRIDE FOWNER FSETID KILL
  # SETGID SETUID SETPCAP NET_BIND_SERVICE NET_RAW SYS_CHROOT MKNOD AUDIT_WRITE SETFCAP = 0xa80425fb.
  "$launcher" cat /proc/self/status >"$tmp/status" || fail "docker_default cat"
  for set in CapBnd CapEff CapPrm; do
    grep -q "^$set:[[:space:]]*00000000a80425fb$" "$tmp/status" || fail "$set under docker_default: $(grep "^$set" "$tmp/status")"
  done
  grep -q '^Seccomp:[[:space:]]*2$' "$tmp/status" || fail "docker_default: no seccomp filter: $(grep '^Seccomp:' "$tmp/status")"
  "$launcher" unshare --net true 2>/dev/null && fail "unshare --net worked under docker_default"
  echo "docker_default: bwrap cannot make its namespaces (as in the issue), unshare fails, the capabilities are Docker's default set"
  ;;
chosen)
  # Bubblewrap works here (the probe ./lab doctor uses): then the grader must choose it.
  bwrap --unshare-pid --unshare-net --ro-bind /usr /usr --symlink usr/lib /lib --symlink usr/lib64 /lib64 --dev /dev /usr/bin/true 2>/dev/null \
    || { echo "skipped: bubblewrap does not work on this machine"; exit 77; }
  mkdir -p "$tmp/sub/01_hooke"
  printf 'int main() { return 0; }\n' >"$tmp/sub/01_hooke/hooke.cpp"  # rejected by the lint: nothing is compiled
  "$grader" --kit "$kit" --submission "$tmp/sub" --work "$tmp/work" --stage 01 --json "$tmp/r.json" >"$tmp/grade.log" 2>&1 \
    || { cat "$tmp/grade.log"; fail "grading a rejected stage"; }
  grep -qx "sandbox: bubblewrap" "$tmp/grade.log" || fail "the table does not say 'sandbox: bubblewrap': $(tail -3 "$tmp/grade.log")"
  jq -e '.sandbox == "bubblewrap"' "$tmp/r.json" >/dev/null || fail "the JSON's sandbox: $(jq .sandbox "$tmp/r.json")"
  "$grader" --which-sandbox --kit "$kit" >"$tmp/which.log" 2>&1 || fail "--which-sandbox: $(cat "$tmp/which.log")"
  grep -qx "bubblewrap: it works here" "$tmp/which.log" || fail "--which-sandbox: $(cat "$tmp/which.log")"
  CLOTHLAB_BUILD=$build "$root/lab" doctor >"$tmp/doctor.log" 2>&1 || fail "./lab doctor: $(tail -3 "$tmp/doctor.log")"
  grep -q "^  the grader's confinement: bubblewrap: it works here" "$tmp/doctor.log" \
    || fail "./lab doctor does not name bubblewrap: $(grep -A6 '^sandbox' "$tmp/doctor.log")"
  # Forced, container mode works here too (the other tests run it under the launcher).
  "$grader" --which-sandbox --sandbox container --kit "$kit" >"$tmp/which.log" 2>&1 || fail "--which-sandbox --sandbox container: $(cat "$tmp/which.log")"
  grep -q "^container mode (.*): asked for" "$tmp/which.log" || fail "--which-sandbox --sandbox container: $(cat "$tmp/which.log")"
  echo "without the launcher the grader chooses bubblewrap (table, JSON, --which-sandbox, ./lab doctor)"
  ;;
red-team)
  sub=$1; shift
  bash "$root/tests/instructor/hostile_test.sh" "$root" "$build/tests/sandbox/grade_in_container" "$kit" "$sub" "$@"
  exit $?
  ;;
load-bearing)
  weakened=$bin/clothlab-grade-weakened
  [[ -x $weakened ]] || fail "build clothlab-grade-weakened first"
  want=$(max_points "$root/tests/01_hooke.points.json")
  # 1. Landlock and the seccomp filter off: the three attacks whose static initialisers read, write, connect.
  mkdir -p "$tmp/class"
  for a in ctor_reads_solutions ctor_socket ctor_writes_outside; do
    bash "$root/tests/instructor/assemble_attack.sh" "$root" "$a" 01 "$tmp/class/$a" || fail "assembling $a"
  done
  # Through in_container.sh, as the red team grades: its check of the messages must catch the escapes.
  CLOTHLAB_WEAKEN=landlock,container-seccomp bash "$root/tests/sandbox/in_container.sh" "$launcher" "$weakened" --kit "$kit" --class "$tmp/class" \
    --out "$tmp/out" --stage 01 --timeout 8 >"$tmp/grade.log" 2>&1 && fail "in_container.sh passed a class whose attacks escaped"
  grep -q "^in_container.sh: an attack escaped container mode" "$tmp/grade.log" || { tail -5 "$tmp/grade.log"; fail "the weakened grader (landlock, seccomp)"; }
  fb=$tmp/out/feedback
  grep -q "ESCAPED: read .*solutions/01_hooke/hooke.cpp: $(head -1 "$root/solutions/01_hooke/hooke.cpp" | cut -c1-40)" "$fb/ctor_reads_solutions.json" \
    || fail "Landlock off: ctor_reads_solutions did not read the reference solution: $(jq -r '.stages[0].tests[0].message' "$fb/ctor_reads_solutions.json")"
  grep -q "ESCAPED: wrote /tmp/clothlab-escape-" "$fb/ctor_writes_outside.json" \
    || fail "Landlock off: ctor_writes_outside did not write /tmp: $(jq -r '.stages[0].tests[0].message' "$fb/ctor_writes_outside.json")"
  grep -q "ESCAPED: an AF_INET socket reached 127.0.0.1" "$fb/ctor_socket.json" \
    || fail "seccomp off: ctor_socket did not reach the network: $(jq -r '.stages[0].tests[0].message' "$fb/ctor_socket.json")"
  for f in $(grep -o 'ESCAPED: wrote [^ "\\]*' "$fb/ctor_writes_outside.json" | cut -d' ' -f3 | sort -u); do
    [[ ! -e $f ]] || fail "what a run's user left was not removed: $f"
  done
  # 2. One user for every run: the reference graded beside kill_other_runs (two jobs: at once).
  mkdir -p "$tmp/class2"
  bash "$root/tests/instructor/assemble_attack.sh" "$root" kill_other_runs 01 "$tmp/class2/1_kill_other_runs" || fail "assembling kill_other_runs"
  reference "$tmp/ref" && mkdir "$tmp/class2/2_reference" && mv "$tmp/ref/01_hooke" "$tmp/class2/2_reference/"
  CLOTHLAB_WEAKEN=uid "$launcher" "$weakened" --kit "$kit" --class "$tmp/class2" --out "$tmp/out2" --stage 01 --jobs 2 \
    --timeout 8 >"$tmp/grade2.log" 2>&1 || { tail -5 "$tmp/grade2.log"; fail "the weakened grader (uid)"; }
  # Without a user per run nothing kills what a run left behind: the daemon of kill_other_runs (user
  # 64199, the test tool's one user) would end by itself within 30 s; end it now, by its process id.
  for s in /proc/[0-9]*/status; do
    [[ $(awk '/^Uid:/ { print $2 }' "$s" 2>/dev/null) == 64199 ]] && kill -9 "$(basename "$(dirname "$s")")" 2>/dev/null
  done
  got=$(jq '.stages[0].points + .stages[0].bonus' "$tmp/out2/feedback/2_reference.json")
  [[ $got != "$want" ]] || fail "one user for every run: kill_other_runs did not cost the reference a point ($got of $want)"
  echo "each defence is load-bearing: without Landlock the reference solution was read and /tmp written (and removed after), without seccomp a socket reached 127.0.0.1, with one user for every run the reference lost points ($got of $want); grade.container_mode_red_team_scores_zero: with them, none of it"
  ;;
no-landlock)
  reference "$tmp/ref"
  # The instructor's tree (solutions/, tests/instructor/) is readable by every user here: one line.
  "$launcher" --no-landlock "$grader" --kit "$kit" --submission "$tmp/ref" --work "$tmp/work" --stage 01 >"$tmp/out.log" 2>"$tmp/err.log" \
    && fail "graded without Landlock with solutions/ readable: $(tail -3 "$tmp/out.log")"
  [[ $(wc -l <"$tmp/err.log") == 1 ]] || fail "not one line: $(cat "$tmp/err.log")"
  grep -q "^error: the sandbox does not work here: bubblewrap: bwrap cannot create a sandbox here (exit 1): bwrap: Creating new namespace failed: Operation not permitted; container mode without Landlock: the submission could read $root/" "$tmp/err.log" \
    || fail "the line does not name bubblewrap's failure and the file container mode cannot hide: $(cat "$tmp/err.log")"
  # A class: students could read each other's files.
  mkdir -p "$tmp/class/a" && "$launcher" --no-landlock "$grader" --kit "$kit" --class "$tmp/class" --out "$tmp/classout" --stage 01 >/dev/null 2>"$tmp/err.log" \
    && fail "graded a class without Landlock"
  grep -q "^error: .*container mode without Landlock: a class cannot be graded" "$tmp/err.log" || fail "--class without Landlock: $(cat "$tmp/err.log")"
  # The instructor's files out of other users' reach (a copy of the points files in a folder only root
  # may enter; no reference objects, so no solutions/ behind the kit): it grades, and says how.
  mkdir -p "$tmp/tree/tests" && chmod 700 "$tmp/tree" && cp "$root"/tests/*.points.json "$tmp/tree/tests/"
  jq --arg p "$tmp/tree/tests" '.points_dir = $p | .stages[].reference = []' "$kit" >"$tmp/kit.json"
  "$launcher" --no-landlock "$grader" --kit "$tmp/kit.json" --submission "$tmp/ref" --work "$tmp/work" --stage 01 --json "$tmp/r.json" \
    >"$tmp/out.log" 2>&1 || { tail -5 "$tmp/out.log"; fail "grading without Landlock, the instructor's files out of reach"; }
  want=$(max_points "$root/tests/01_hooke.points.json")
  jq -e --argjson want "$want" '.points + .bonus == $want and (.sandbox | startswith("container mode without Landlock ("))' "$tmp/r.json" >/dev/null \
    || fail "without Landlock: $(jq -c '{points, bonus, sandbox}' "$tmp/r.json") (want $want points)"
  echo "without Landlock: one line names the file it cannot hide; a class is refused; with the instructor's files out of reach it grades stage 01 to $want and says 'container mode without Landlock'"
  ;;
gradescope)
  # The bundle as an instructor uploads it (no reference objects: this build's kit grades, as in
  # release.gradescope_bundle_and_ci_workflow), run_autograder in a scratch /autograder under the launcher.
  CLOTHLAB_BUILD=$build "$root/lab" release "$tmp/gs" --gradescope --no-reference-objects >"$tmp/release.log" 2>&1 \
    || { tail -5 "$tmp/release.log"; fail "./lab release --gradescope"; }
  ag=$tmp/autograder
  mkdir -p "$ag" && ln -s "$tmp/gs" "$ag/source" && reference "$ag/submission/my-repo/exercises"
  AUTOGRADER_ROOT=$ag CLOTHLAB_BUILD=$build CLOTHLAB_NO_BUILD=1 "$launcher" "$tmp/gs/run_autograder" >"$tmp/run.log" 2>&1
  r=$ag/results/results.json
  [[ -s $r ]] || { tail -5 "$tmp/run.log"; fail "run_autograder wrote no results.json"; }
  want=$(max_points "$root"/tests/[0-9][0-9]_*.points.json)
  n=$(jq -s '[.[] | (.tests + (.bonus // {})) | length] | add' "$root"/tests/[0-9][0-9]_*.points.json)
  jq -e --argjson want "$want" --argjson n "$n" \
    '.score == $want and (.tests | length) == $n and all(.tests[]; .status == "passed")
     and (.output | test("\nsandbox: container mode [(]"))' "$r" >/dev/null \
    || { tail -5 "$tmp/run.log"; fail "results.json: $(jq -c '{score, tests: (.tests | length), output}' "$r" | head -c 600) (want $want points, $n tests)"; }
  echo "run_autograder under docker_default: results.json with all $n tests passed, $want points (the points files' total, as bubblewrap gives the reference), 'sandbox: container mode'"
  ;;
*) fail "unknown mode $mode" ;;
esac
