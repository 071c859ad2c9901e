#!/usr/bin/env bash
# The browser's simulation step against the native one, in one run (docs/performance.md "In a browser").
#   bash benchmarks/web_step.sh [BUILD_DIR] [STEPS]      (after ./lab web --no-serve; about a minute)
# 1. Step time, per kernel (exercise; batched where the copy has solutions/kernels/): the 64² draped
#    cloth (scenes/pbd_sphere.json at cloth.nx = ny = 64), STEPS steps
#    (default 100): the sum of the simulation's pass times per step (Simulation::timer(), what the run
#    report's "passes that ran" lists), native on one thread (solver.threads=1, BUILD_DIR/bin/clothlab)
#    and in headless chromium (WebAssembly, one thread, -msimd128; ?steps=N), and their ratio.
#    The simulation's time per displayed frame of 1/60 s follows: the step time x (1/60 s) / dt; then
#    each pass of the step (the run report's "passes that ran", the page's app.runs[0].passes).
# 2. The app's frame in the browser, playing in real time for 10 s (?timing=1; the last kernel above): the simulation's time per
#    displayed frame (app.timings_ms.simulate), the drawing's and the panel's, and the frame rate. In
#    headless chromium without a GPU (SwiftShader renders WebGL on the CPU) drawing dominates and says
#    little about a laptop's GPU; the simulation's time is the figure to compare with the frame's
#    simulated time (16.7 ms at 60 fps).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build} steps=${2:-100}
page=$build/web/bin
[[ -f $page/clothlab.wasm ]] || { echo "error: $page: no clothlab.wasm (./lab web --no-serve first)" >&2; exit 1; }
tmp=$(mktemp -d)
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 -m http.server "$port" --bind 127.0.0.1 --directory "$page" >/dev/null 2>&1 &
server=$!
trap 'kill $server 2>/dev/null; rm -rf "$tmp"' EXIT
sleep 1
set64="set=cloth.nx=64&set=cloth.ny=64"
echo "load: $(cut -d' ' -f1-3 /proc/loadavg) ($(nproc) cores), $(git rev-parse --short HEAD 2>/dev/null || echo '?'), $(date -u '+%Y-%m-%d %H:%M UTC'), $(chromium --version 2>/dev/null | head -1)"
dt=$(jq -r '.solver.dt' scenes/pbd_sphere.json)
# The kernels this copy has: the exercise path always; the batched kernels in the instructor's copy
# (solutions/kernels/, in the native programs and the page alike).
kernels=(exercise)
[[ -d solutions/kernels ]] && kernels+=(batched)
for kernel in "${kernels[@]}"; do
  # the native run's passes, one "NAME<tab>SECONDS" line each (its report's "passes that ran")
  "${CLOTHLAB_NATIVE:-$build/bin/clothlab}" run scenes/pbd_sphere.json --set cloth.nx=64 --set cloth.ny=64 --set solver.threads=1 \
      --set solver.kernel="$kernel" --steps "$steps" --quiet 2>&1 \
    | awk '/^passes that ran/ { on = 1; next } on && / s +[0-9]+ calls/ { for (i = 1; i <= NF; ++i) if ($(i + 1) == "s") break
          name = $1; for (j = 2; j < i; ++j) name = name " " $j; print name "\t" $i }' >"$tmp/native.tsv"
  native=$(awk -F'\t' '{ t += $2 } END { printf "%.3f", 1000 * t }' "$tmp/native.tsv")
  python3 tests/web/page_run.py "http://127.0.0.1:$port/index.html?scene=pbd_sphere&$set64&set=solver.kernel=$kernel&steps=$steps" \
    --seconds 300 --until-done >"$tmp/steps.json"
  web=$(jq -r --argjson n "$steps" '.app.runs[0].wall * 1000 | . * 1000 | round / 1000' "$tmp/steps.json")
  awk -v n="$steps" -v a="$native" -v b="$web" -v dt="$dt" -v k="$kernel" 'BEGIN {
    printf "pbd_sphere 64x64, %d steps, kernel %s: native %.2f ms per step (1 thread), browser %.2f ms per step, ratio %.2f\n", n, k, a / n, b / n, b / a
    printf "  simulation per 1/60 s frame (%.3f steps of dt = %g s; real time needs <= 16.7 ms): browser %.1f ms, native %.1f ms\n", 1 / (60 * dt), dt, b / n / (60 * dt), a / n / (60 * dt) }'
  # per pass: browser and native ms per step (the page's app.runs[0].passes, the same pass names)
  jq -r '.app.runs[0].passes | to_entries[] | "\(.key)\t\(.value)"' "$tmp/steps.json" >"$tmp/web.tsv"
  awk -F'\t' -v n="$steps" 'NR == FNR { native[$1] = $2; next }
      { printf "    %-32s browser %6.2f ms, native %6.2f ms per step\n", $1, 1000 * $2 / n, 1000 * native[$1] / n }' "$tmp/native.tsv" "$tmp/web.tsv"
done
python3 tests/web/page_run.py "http://127.0.0.1:$port/index.html?scene=pbd_sphere&$set64&set=solver.kernel=$kernel&timing=1" --seconds 10 >"$tmp/play.json"
jq -r --arg k "$kernel" '"pbd_sphere 64x64 playing 10 s, kernel \($k): simulation \(.app.timings_ms.simulate * 10 | round / 10) ms per frame, drawing \(.app.timings_ms.draw * 10 | round / 10) ms, panel \(.app.timings_ms.panel * 10 | round / 10) ms, \(1000 / .ms_per_frame * 10 | round / 10) frames per s (SwiftShader), \(.app.realtime * 100 | round / 100) x real time"' "$tmp/play.json"
