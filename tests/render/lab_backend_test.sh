#!/usr/bin/env bash
# ./lab render picks the offscreen program at run time: OSMesa (clothlab-render) where it is built and
# its libOSMesa loads, else EGL (clothlab-render-egl); CLOTHLAB_OFFSCREEN=osmesa|egl forces one.
# `./lab demo` renders its reel through the same choice (offscreen_program in lab). A libOSMesa that
# does not load is played by an empty libOSMesa.so.8 first on LD_LIBRARY_PATH; no EGL driver by a
# GLVND vendor list that names none. Writes only to TMP (and BUILD's build log: ./lab brings the
# two programs up to date first, nothing to do after the build).
set -u
root=$1; build=$2; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp/broken"
: >"$tmp/broken/libOSMesa.so.8"
fail=0
bad() { echo "FAIL: $*"; fail=1; }
# case NAME [VAR=value...]: ./lab render of one frame (the spring at t = 0) to TMP/NAME.
case_() {
  local name=$1; shift
  env "$@" CLOTHLAB_BUILD="$build" CLOTHLAB_NO_BUILD=1 bash "$root/lab" render scenes/spring.json --seconds 0 --size 160x120 --quiet \
    --out "$tmp/$name" >"$tmp/$name.out" 2>"$tmp/$name.err"
  echo $? >"$tmp/$name.code"
}
# expect_frame NAME BACKEND-LABEL: it rendered its frame and said which backend did.
expect_frame() {
  [[ $(cat "$tmp/$1.code") -eq 0 ]] || { bad "$1: exit code $(cat "$tmp/$1.code"): $(tail -3 "$tmp/$1.err")"; return; }
  [[ -s $tmp/$1/frame_0000.png ]] || bad "$1: no frame_0000.png"
  grep -q "^renderer: $2 (" "$tmp/$1.out" || bad "$1: want 'renderer: $2 (...)', got: $(grep '^renderer' "$tmp/$1.out")"
}
# expect_error NAME PATTERN: one 'error: renderer: ...' line matching PATTERN, a non-zero exit, no crash.
expect_error() {
  local code; code=$(cat "$tmp/$1.code")
  [[ $code -ne 0 && $code -lt 128 ]] || bad "$1: exit code $code"
  [[ $(grep -c '^error: ' "$tmp/$1.err") -eq 1 ]] && grep -q "^error: renderer: .*$2" "$tmp/$1.err" \
    || bad "$1: want one 'error: renderer: ...$2...' line, got: $(cat "$tmp/$1.err")"
}

case_ egl CLOTHLAB_OFFSCREEN=egl
expect_frame egl "EGL surfaceless"
case_ bogus CLOTHLAB_OFFSCREEN=vulkan
expect_error bogus "CLOTHLAB_OFFSCREEN=vulkan"
case_ no_egl CLOTHLAB_OFFSCREEN=egl __EGL_VENDOR_LIBRARY_FILENAMES="$tmp/none.json"
expect_error no_egl "egl: EGL: "
if [[ -x $build/bin/clothlab-render ]]; then
  case_ auto
  expect_frame auto "OSMesa"
  case_ osmesa CLOTHLAB_OFFSCREEN=osmesa
  expect_frame osmesa "OSMesa"
  case_ broken_osmesa LD_LIBRARY_PATH="$tmp/broken"
  expect_frame broken_osmesa "EGL surfaceless"
  case_ forced_broken CLOTHLAB_OFFSCREEN=osmesa LD_LIBRARY_PATH="$tmp/broken"
  expect_error forced_broken "osmesa: .*libOSMesa"
  case_ neither LD_LIBRARY_PATH="$tmp/broken" __EGL_VENDOR_LIBRARY_FILENAMES="$tmp/none.json"
  expect_error neither "osmesa: .*; egl: EGL: "
else
  case_ auto
  expect_frame auto "EGL surfaceless"
  case_ osmesa CLOTHLAB_OFFSCREEN=osmesa
  expect_error osmesa "osmesa: clothlab-render is not built"
fi
[[ $fail -eq 0 ]] && echo "ok: ./lab render picks OSMesa, else EGL; CLOTHLAB_OFFSCREEN forces one; one error line when none works"
exit $fail
