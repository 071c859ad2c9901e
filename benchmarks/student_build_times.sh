#!/usr/bin/env bash
# The student's first impression: in a fresh student copy, how long the first `./lab build`
# takes, then a change of --reference, then the first `./lab grade --stage 01` (which builds the grader).
#   bash benchmarks/student_build_times.sh [BUILD_DIR] [COPY_DIR]     (defaults: build, a temp folder)
# BUILD_DIR is the instructor's Release build whose reference objects the copy takes (./lab release
# with CLOTHLAB_BUILD); it must be built. The Debian packages must be installed (./lab setup): their
# download is not part of these figures. Prints one line per command with its wall time; run it on an
# otherwise idle machine (README and docs/performance.md quote it). Each command runs as a student
# types it, in the copy, with the copy's own build folder (nothing shared with BUILD_DIR but the
# released reference objects).
set -euo pipefail
cd "$(dirname "$0")/.."
build=$(cd "${1:-build}" && pwd)
copy=${2:-$(mktemp -d)/copy}
[[ -f $build/CMakeCache.txt ]] || { echo "error: $build: not a configured build (./lab build)" >&2; exit 2; }
CLOTHLAB_BUILD=$build ./lab release "$copy" >/dev/null
cd "$copy"
timed() {  # timed LABEL COMMAND...: one line, the wall time in seconds
  local label=$1 t0; shift
  t0=$(date +%s.%N)
  "$@" >/tmp/student_build_times.log 2>&1 || { tail -20 /tmp/student_build_times.log; echo "error: $label failed" >&2; exit 1; }
  awk -v l="$label" -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%-58s %6.1f s\n", l, b - a }'
}
echo "student copy $copy ($(nproc) cores, $(git -C "$OLDPWD" rev-parse --short HEAD 2>/dev/null || echo '?'))"
timed "first ./lab build (the command line)" ./lab build
timed "./lab build --reference 01 (a --reference change)" ./lab build --reference 01
timed "./lab build (back to the student's own code)" ./lab build
timed "first ./lab grade --stage 01 (builds the grader, grades)" ./lab grade --stage 01
echo '// an edit' >>exercises/01_hooke/hooke.cpp
timed "edit hooke.cpp, ./lab run scenes/spring.json --quiet" bash -c './lab run scenes/spring.json --quiet || true'
