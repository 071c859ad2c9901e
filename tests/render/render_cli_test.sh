#!/usr/bin/env bash
# clothlab-render on good and bad input: frames of a scene, one error line on bad input, the app screenshot.
set -u
exe=$1; check=$2; root=$3; tmp=$4
rm -rf "$tmp"; mkdir -p "$tmp"
fail=0
bad() { echo "FAIL: $*"; fail=1; }

# 0.2 s at 20 fps: frames 0..4.
if "$exe" render "$root/scenes/spring.json" --seconds 0.2 --fps 20 --size 320x240 --out "$tmp/spring" --quiet >"$tmp/out" 2>&1; then
  n=$(ls "$tmp/spring"/frame_*.png 2>/dev/null | wc -l)
  [[ $n -eq 5 ]] || bad "render spring: want 5 frames, got $n"
  grep -q "ms per frame" "$tmp/out" || bad "render spring: no timing line: $(cat "$tmp/out")"
else
  bad "render spring failed: $(tail -5 "$tmp/out")"
fi

# Bad input: one 'error: <file>: <field>: <reason>' line and a non-zero exit.
expect_error() {
  local name=$1 pattern=$2; shift 2
  "$exe" "$@" >"$tmp/out" 2>"$tmp/err"; local code=$?
  if [[ $code -eq 0 || $code -ge 128 ]]; then bad "$name: exit code $code";
  elif [[ $(grep -c '^error: ' "$tmp/err") -ne 1 ]]; then bad "$name: want one error line, got: $(cat "$tmp/err")";
  elif ! grep -q "$pattern" "$tmp/err"; then bad "$name: want '$pattern', got: $(cat "$tmp/err")"; fi
}
expect_error missing_scene "error: $tmp/nope.json: (file)" render "$tmp/nope.json" --out "$tmp/x"
expect_error bad_size "error: command line: --size" render "$root/scenes/spring.json" --out "$tmp/x" --size 12
printf '{"model": "spring", "solver": {"dt": -1}}' >"$tmp/bad.json"
expect_error bad_dt "error: $tmp/bad.json: solver.dt" render "$tmp/bad.json" --out "$tmp/x"
printf '{"model": "spring", "view": {"eye": [0, 0, 1], "target": [0, 0, 1]}}' >"$tmp/badview.json"
expect_error bad_view "error: $tmp/badview.json: view.target" render "$tmp/badview.json" --out "$tmp/x"

# A blow-up stops with one error line (frames up to it are written), not with garbage pictures.
expect_error unstable "error: $root/scenes/spring.json: solver: unstable at step" render "$root/scenes/spring.json" \
  --set solver.method=explicit_euler --set solver.dt=0.2 --seconds 100 --fps 1 --size 160x120 --out "$tmp/unstable" --quiet

# A video only with ffmpeg; without it a clear note and the frames anyway.
if "$exe" render "$root/scenes/spring.json" --seconds 0.1 --fps 20 --size 320x240 --out "$tmp/v" --video "$tmp/v.mp4" --quiet >"$tmp/out" 2>&1; then
  if command -v ffmpeg >/dev/null; then [[ -s $tmp/v.mp4 ]] || bad "video: no $tmp/v.mp4"
  else grep -q "ffmpeg is not installed" "$tmp/out" || bad "video: no note about ffmpeg"; fi
else bad "render --video failed: $(tail -3 "$tmp/out")"; fi

# The whole app offscreen, panels included.
if "$exe" gui "$root/scenes/spring.json" --screenshot "$tmp/app.png" --frames 10 >"$tmp/out" 2>&1; then
  "$check" --check-app-screenshot "$tmp/app.png" || bad "app screenshot content"
else
  bad "gui --screenshot failed: $(tail -3 "$tmp/out")"
fi
# When the result is not a result, the renderer and the app say what `clothlab run` says (run.h):
# pbd_sphere at three times its step falls through the sphere; at its own step nothing is flagged.
"$exe" render "$root/scenes/pbd_sphere.json" --set solver.dt=0.03 --seconds 1 --fps 5 --size 160x120 --out "$tmp/fall" --quiet >"$tmp/out" 2>&1
grep -q "warning: fell through: .* at step [0-9]" "$tmp/out" || bad "render: no fell-through warning: $(grep -i warn "$tmp/out")"
"$exe" gui "$root/scenes/pbd_sphere.json" --set solver.dt=0.03 --frames 40 --size 640x400 --screenshot "$tmp/fall.png" >"$tmp/out" 2>&1
grep -q "panel warning: fell through" "$tmp/out" || bad "app: no fell-through warning in the panel: $(tail -3 "$tmp/out")"
"$exe" gui "$root/scenes/pbd_sphere.json" --frames 40 --size 640x400 --screenshot "$tmp/stays.png" >"$tmp/out" 2>&1
! grep -q "panel warning" "$tmp/out" || bad "app: a warning on pbd_sphere at its own step: $(grep warning "$tmp/out")"
[[ $fail -eq 0 ]] && echo "ok: clothlab-render frames, errors, video, app screenshot, warnings"
exit $fail
