#!/usr/bin/env bash
# The data figures of the slides, made with the lab's own commands (./lab render, ./lab study).
#   bash slides/make_figures.sh [FIG_DIR]      (default: out/slides/figures/)
# Needs the clothlab build (./lab builds what is missing) with the renderer, and gnuplot for the
# study plots. Writes only into FIG_DIR (and a temporary folder); about a minute on 2 cores.
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
FIG=${1:-$ROOT/out/slides/figures}
mkdir -p "$FIG"
FIG=$(cd "$FIG" && pwd)
cd "$ROOT"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
log=$FIG/make_figures.log; : >"$log"

run() {  # run CMD...: quiet unless it fails
  if ! "$@" >>"$log" 2>&1; then tail -n 20 "$log" >&2; echo "error: '$*' failed (log: $log)" >&2; exit 1; fi
}
# frame SCENE SECONDS NAME [render options...]: the last frame of a 640x360, 30 fps clip
frame() {
  local scene=$1 secs=$2 name=$3; shift 3
  rm -rf "$tmp/frames"
  run ./lab render "$scene" --seconds "$secs" --fps 30 --size 640x360 --out "$tmp/frames" "$@"
  cp "$(ls "$tmp"/frames/frame_*.png | tail -n 1)" "$FIG/$name"
  echo "  $name"
}
# study KIND SCENE NAME PLOT [options...]: the PNG plot PLOT of a ./lab study run
study() {
  local kind=$1 scene=$2 name=$3 plot=$4; shift 4
  run ./lab study "$kind" "$scene" "$@" --out "$tmp/$name"
  [[ -f $tmp/$name/$plot ]] || { echo "error: ./lab study $kind wrote no $plot (is gnuplot installed? apt-get install gnuplot-nox)" >&2; exit 1; }
  cp "$tmp/$name/$plot" "$FIG/$name"
  echo "  $name"
}

echo "slides: figures into $FIG"
frame scenes/spring.json 0.4 spring.png                     # ch. 2
frame scenes/mfn_hanging.json 1.5 mfn_hanging.png --strain  # ch. 4, 5
frame scenes/pbd_hanging.json 3 pbd_hanging.png             # ch. 7
frame scenes/pbd_flag.json 2 pbd_flag.png                   # ch. 8
frame scenes/pbd_sphere.json 2 pbd_sphere.png               # ch. 1, 9
study precision scenes/spring.json spring_precision.png precision.png \
  --dt-min 1e-4 --dt-max 1e-2 --dt-count 7 --end-time 2     # ch. 3
study stability scenes/spring.json spring_stability.png stability.png \
  --set 'spring.start=[0,-1.108,0]'                         # ch. 3
study precision scenes/pbd_hanging.json pbd_precision.png precision.png \
  --set cloth.nx=12 --set cloth.ny=12 --budgets 1,2,5,10,20,50 --reference-substeps 400   # ch. 10
