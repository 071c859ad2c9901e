#!/usr/bin/env bash
# clothlab-grade under docker_default, a simulation of Docker's default confinement (issue 45), as
# hostile_test.sh calls a grader: in_container.sh LAUNCHER GRADER ARGS... (the build's grade_in_container).
# Passes the grader's exit status on, and fails when the grader did not grade in container mode or when
# a failure message of the class (its --out DIR/feedback) says that a red-team attack escaped
# ("ESCAPED:", written by the attacks on what container mode adds, e.g. ctor_reads_solutions).
set -u
launcher=$1 grader=$2
shift 2
out="" prev=""
for a in "$@"; do [[ $prev == --out ]] && out=$a; prev=$a; done
log=$(mktemp); trap 'rm -f "$log"' EXIT
"$launcher" "$grader" "$@" | tee "$log"
rc=${PIPESTATUS[0]}
((rc == 0)) || exit "$rc"
grep -q '^sandbox: container mode (' "$log" || { echo "in_container.sh: the grader did not grade in container mode: $(grep '^sandbox:' "$log")"; exit 1; }
if [[ -n $out ]] && grep -l 'ESCAPED:' "$out"/feedback/*.json; then
  grep -h -o 'ESCAPED:[^"]*' "$out"/feedback/*.json | sort -u | head -5
  echo "in_container.sh: an attack escaped container mode (above)"
  exit 1
fi
exit 0
