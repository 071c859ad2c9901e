#!/usr/bin/env bash
# ./lab gui in the lecturer's copy (solutions/kernels/ present) runs the batched kernels unless the
# command names a kernel, and says so; the app's status (and its panel, beside the step time) names
# the kernel. Writes only to TMP.
set -u
root=$1; build=$2; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
fail=0
bad() { echo "FAIL: $*"; fail=1; }
# gui NAME ARGS...: two offscreen frames of pbd_hanging with ARGS; its status to TMP/NAME.json
gui() {
  local name=$1; shift
  CLOTHLAB_BUILD="$build" CLOTHLAB_NO_BUILD=1 bash "$root/lab" gui scenes/pbd_hanging.json --screenshot "$tmp/$name.png" --frames 2 \
    --status "$tmp/$name.json" "$@" >"$tmp/$name.out" 2>"$tmp/$name.err" || bad "$name: exit code $?: $(tail -3 "$tmp/$name.err")"
}
kernel() { jq -r '.runs[0].kernel' "$tmp/$1.json" 2>/dev/null; }
gui default
[[ $(kernel default) == batched ]] || bad "default: the run's kernel is '$(kernel default)', want batched"
grep -q 'gui: the batched kernels (solver.kernel=batched; --set solver.kernel=exercise' "$tmp/default.err" || bad "default: no note on the kernel: $(cat "$tmp/default.err")"
gui exercise --set solver.kernel=exercise
[[ $(kernel exercise) == exercise ]] || bad "exercise: the run's kernel is '$(kernel exercise)', want exercise (the command named it)"
grep -q 'gui: the batched kernels' "$tmp/exercise.err" && bad "exercise: the note on the batched kernels, though the command named a kernel"
[[ $fail -eq 0 ]] && echo "ok: ./lab gui runs the batched kernels in the lecturer's copy, unless the command names a kernel"
exit $fail
