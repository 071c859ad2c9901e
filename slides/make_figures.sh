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
# still SCENE FRAMES NAME [gui options...]: the app (panel included) after FRAMES frames, offscreen:
# the live demo's picture for when the demo cannot run
still() {
  local scene=$1 frames=$2 name=$3; shift 3
  run ./lab gui "$scene" --screenshot "$FIG/$name" --frames "$frames" --size 960x540 "$@"
  echo "  $name"
}
# bigger GNUPLOT.gp: redraw a study's plot with every font doubled, readable from the back of a
# lecture hall (the study itself writes plots for the screen)
bigger() {
  perl -pi -e 's/font \x27,(\d+)\x27/"font \x27,".($1 * 2)."\x27"/ge' "$1"
  run gnuplot "$1"
}
# study KIND SCENE NAME PLOT [options...]: the PNG plot PLOT of a ./lab study run, fonts doubled
study() {
  local kind=$1 scene=$2 name=$3 plot=$4; shift 4
  run ./lab study "$kind" "$scene" "$@" --out "$tmp/$name"
  [[ -f $tmp/$name/$plot ]] || { echo "error: ./lab study $kind wrote no $plot (is gnuplot installed? apt-get install gnuplot-nox)" >&2; exit 1; }
  bigger "$tmp/$name/${plot%.png}.gp"
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
study sag scenes/pbd_curtain.json pbd_xpbd_sag.png sag.png \
  --set cloth.nx=11 --set cloth.ny=11 --set cloth.width=1 --set cloth.height=1 --set pbd.damping=0.05 \
  --iterations 1,2,5,10,20,50,100 --xpbd-substeps 1,10                                 # ch. 10

# ch. 4: the three spring types on a small grid, coloured by type (structural, shear, bending)
frame scenes/mfn_hanging.json 0.2 spring_types.png --edges \
  --set cloth.nx=7 --set cloth.ny=5 --set cloth.width=1.2 --set cloth.height=0.85
# ch. 8: the same drape at three bending stiffnesses (PBD k of the bending constraints)
for kb in 0.001 0.05 1; do
  frame scenes/pbd_sphere.json 2 "bending_k$kb.png" --set constraints.bending.stiffness=$kb
done
# ch. 5: super-elasticity, the largest edge strain over time without and with Provot's fix
run ./lab run scenes/mfn_hanging.json --seconds 3 --every 10 --quiet --out "$tmp/strain_plain"
run ./lab run scenes/mfn_provot.json --seconds 3 --every 10 --quiet --out "$tmp/strain_provot"
cat >"$tmp/strain.gp" <<GP
set terminal pngcairo size 800,450 font ',20'
set output '$FIG/provot_strain.png'
set datafile separator ','
set xlabel 'time t [s]'
set ylabel 'max edge strain'
set grid
set key top right
set yrange [0:*]
plot '$tmp/strain_plain/report.csv' using 't [s]':'max_strain [1]' with lines lw 3 title 'mfn\_hanging (no fix)', \
     '$tmp/strain_provot/report.csv' using 't [s]':'max_strain [1]' with lines lw 3 title "Provot, {/Symbol t} = 0.1"
GP
run gnuplot "$tmp/strain.gp"
echo "  provot_strain.png"

# the live demo of each chapter: the app after a few seconds, for when the demo cannot run
still scenes/pbd_sphere.json 150 demo_01.png
still scenes/spring.json 100 demo_02.png
still scenes/spring.json 240 demo_03.png --set solver.method=explicit_euler --set solver.dt=0.01
still scenes/mfn_hanging.json 120 demo_04.png --edges
still scenes/mfn_hanging.json 120 demo_05.png --strain
still scenes/pbd_curtain.json 150 demo_06.png
still scenes/pbd_hanging.json 200 demo_07.png --strain
still scenes/pbd_flag.json 150 demo_08.png
still scenes/pbd_ground.json 150 demo_09.png
still scenes/pbd_curtain.json 150 demo_10.png --set solver.method=xpbd --set constraints.distance.compliance=0.01
