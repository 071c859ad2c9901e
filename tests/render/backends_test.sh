#!/usr/bin/env bash
# The same frames through both offscreen backends: clothlab-render (OSMesa) and clothlab-render-egl
# (EGL surfaceless) render two frames of a scene and the app with its panels at fixed sizes, and the
# pictures must agree (docs/render.md): the scene's frames within a mean difference of 0.5/255 per
# channel and at most 0.1 % of the pixels with a channel off by more than 32 (both are Mesa's
# llvmpipe: measured 0.003/255 and 0.003 %, a few edge pixels); the app within 1/255 and 0.5 %, as its
# panel shows the wall time per step, which differs from run to run.
# Each program prints its one "renderer:" line; with no EGL driver, one "error: renderer:" line.
set -u
osmesa=$1; egl=$2; check=$3; root=$4; tmp=$5
rm -rf "$tmp"; mkdir -p "$tmp"
fail=0
bad() { echo "FAIL: $*"; fail=1; }
export OMP_NUM_THREADS=1  # the same simulation, step for step
declare -A label=([osmesa]="OSMesa" [egl]="EGL surfaceless")
for b in osmesa egl; do
  exe=${!b}
  if ! "$exe" render "$root/scenes/pbd_sphere.json" --seconds 0.5 --fps 2 --size 320x240 --strain --quiet \
         --out "$tmp/$b" >"$tmp/$b.out" 2>&1; then
    bad "$b: render failed: $(tail -3 "$tmp/$b.out")"; continue
  fi
  "$exe" gui "$root/scenes/mfn_hanging.json" --frames 10 --size 640x400 --screenshot "$tmp/$b-app.png" >"$tmp/$b-app.out" 2>&1 \
    || bad "$b: gui --screenshot failed: $(tail -3 "$tmp/$b-app.out")"
  for out in "$tmp/$b.out" "$tmp/$b-app.out"; do
    n=$(grep -c '^renderer: ' "$out")
    [[ $n -eq 1 ]] || bad "$b: want one renderer line, got $n in $out"
    grep -q "^renderer: ${label[$b]} (.*)$" "$out" || bad "$b: want 'renderer: ${label[$b]} (...)', got: $(grep '^renderer' "$out")"
  done
done
for f in frame_0000.png frame_0001.png; do
  "$check" --compare-images "$tmp/osmesa/$f" "$tmp/egl/$f" 0.5 0.001 || bad "$f differs between OSMesa and EGL"
done
"$check" --compare-images "$tmp/osmesa-app.png" "$tmp/egl-app.png" 1 0.005 || bad "the app screenshot differs between OSMesa and EGL"
"$check" --check-app-screenshot "$tmp/egl-app.png" || bad "EGL app screenshot content"

# No EGL driver (GLVND finds no vendor library): one error line, exit code 4, no crash.
__EGL_VENDOR_LIBRARY_FILENAMES=$tmp/none.json "$egl" render "$root/scenes/spring.json" --seconds 0 --out "$tmp/none" \
  >"$tmp/none.out" 2>"$tmp/none.err"
code=$?
[[ $code -eq 4 ]] || bad "no EGL driver: want exit code 4, got $code"
[[ $(wc -l <"$tmp/none.err") -eq 1 ]] && grep -q '^error: renderer: EGL: ' "$tmp/none.err" \
  || bad "no EGL driver: want one 'error: renderer: EGL: ...' line, got: $(cat "$tmp/none.err")"
[[ $fail -eq 0 ]] && echo "ok: OSMesa and EGL draw the same frames and app; no EGL driver gives one error line"
exit $fail
