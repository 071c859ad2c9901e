#!/usr/bin/env bash
# The real GLFW window under a virtual X server: run 20 frames, save the window, check the picture.
# Exit 77 (skipped) when Xvfb is not installed.
set -u
gui=$1; check=$2; root=$3; tmp=$4
command -v Xvfb >/dev/null || { echo "skip: Xvfb is not installed (apt-get install xvfb)"; exit 77; }
rm -rf "$tmp"; mkdir -p "$tmp"
# A free display number, told by Xvfb itself.
Xvfb -displayfd 3 -screen 0 1400x900x24 -nolisten tcp >"$tmp/xvfb.log" 2>&1 3>"$tmp/display" &
xpid=$!
trap 'kill $xpid 2>/dev/null; wait $xpid 2>/dev/null' EXIT
disp=""
for _ in $(seq 100); do disp=$(tr -dc 0-9 <"$tmp/display"); [[ -n $disp ]] && break; sleep 0.1; done
[[ -n $disp ]] || { echo "FAIL: Xvfb did not start: $(cat "$tmp/xvfb.log")"; exit 1; }
if ! DISPLAY=:$disp "$gui" "$root/scenes/spring.json" --screenshot "$tmp/window.png" --frames 20 >"$tmp/out" 2>&1; then
  echo "FAIL: clothlab-gui under Xvfb: $(tail -5 "$tmp/out")"; exit 1
fi
"$check" --check-app-screenshot "$tmp/window.png" || { echo "FAIL: window screenshot content"; exit 1; }
echo "ok: clothlab-gui window under Xvfb (display :$disp)"
