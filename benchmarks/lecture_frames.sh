#!/usr/bin/env bash
# The app's frame on every lecture scene (scenes/*.json) at 1280x800, offscreen (OSMesa, else EGL;
# llvmpipe), as on a 30 fps display. Per scene, twice:
#   real time: every frame steps its 1/30 s of simulated time in full (the default offscreen): the wall time per
#     frame (it grows with what else the machine runs: the load is printed first) and the CPU time per
#     frame of every thread of the process (the simulation's and llvmpipe's), which grows much less with
#     the load: on an idle 2-core machine a frame takes at most its CPU time;
#   the app: the window's stepping budget (--app-budget: what is left of 33 ms after the rest of the
#     frame; what a step overran is paid back from the next frames' budgets): the wall time per frame and
#     how fast the simulation then runs against real time (1 = real time).
# Then two 64 x 64 cloths side by side, the same way (docs/performance.md).
#   bash benchmarks/lecture_frames.sh [BUILD_DIR] [FRAMES] [--side-by-side] [--set KEY=VALUE ...]   (about 4 minutes on an idle machine)
# --side-by-side: every scene as two runs side by side (--compare), PBD against XPBD for the PBD
# scenes, symplectic against implicit Euler for the mass-spring ones.
# The --set options go to every run, e.g. --set solver.kernel=batched: the lecturer's copy with the
# batched sweeps (solutions/kernels/, not in the student copy; mass-spring scenes ignore the key).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build} frames=${2:-90}
shift $(($# < 2 ? $# : 2))
extra=() side=0
for a in "$@"; do if [[ $a == --side-by-side ]]; then side=1; else extra+=("$a"); fi; done
exe=$build/bin/clothlab-render
[[ -x $exe ]] || exe=$build/bin/clothlab-render-egl
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
echo "load: $(cut -d' ' -f1-3 /proc/loadavg) ($(nproc) cores), $(git rev-parse --short HEAD 2>/dev/null || echo '?'), $(date -u '+%Y-%m-%d %H:%M UTC')${extra[*]:+, ${extra[*]}}"
printf '%-24s | %-32s | %-30s\n' "" "real time: wall, CPU per frame" "the app's budget: wall, x real time"
row() {  # row NAME ARGS...: one line of the table
  local name=$1 full app rt; shift
  set -- "$@" "${extra[@]}"
  full=$("$exe" gui "$@" --display-fps 30 --screenshot "$tmp/f.png" --frames "$frames" 2>&1 | grep 'ms per frame')
  app=$("$exe" gui "$@" --display-fps 30 --app-budget --screenshot "$tmp/f.png" --status "$tmp/s.json" --frames "$frames" 2>&1 | grep 'ms per frame')
  rt=$(jq -r '.realtime' "$tmp/s.json")
  awk -v n="$name" -v full="$full" -v app="$app" -v rt="$rt" 'function wall(l,  a) { split(l, a, ": "); return a[2] + 0 }
      function cpu(l,  a) { split(l, a, "CPU time "); return a[2] + 0 }
      BEGIN { printf "%-24s | %6.1f ms %5.1f fps, %5.1f ms | %6.1f ms %5.1f fps, %4.2f x\n", n, wall(full), 1000 / wall(full), cpu(full),
              wall(app), 1000 / wall(app), rt }'
}
for s in scenes/*.json; do
  if ((side == 0)); then row "$(basename "$s" .json)" "$s"
  elif [[ $(jq -r '.solver.method // ""' "$s") == *pbd ]]; then row "$(basename "$s" .json) x 2" "$s" --compare pbd,xpbd
  else row "$(basename "$s" .json) x 2" "$s" --compare symplectic_euler,implicit_euler
  fi
done
row "pbd_sphere 64² x 2" scenes/pbd_sphere.json --set cloth.nx=64 --set cloth.ny=64 --compare pbd,xpbd
