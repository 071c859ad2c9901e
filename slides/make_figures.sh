#!/usr/bin/env bash
# The data figures of the slides, made with the lab's own commands (./lab render, ./lab study),
# and the pre-rendered clips of the live demos.
#   bash slides/make_figures.sh [FIG_DIR [CLIP_DIR]]
#     FIG_DIR default out/slides/figures/, CLIP_DIR default FIG_DIR/../clips (next to the PDFs, which
#     link clips/NN_name.mp4 relative to themselves)
# Needs the clothlab build (./lab builds what is missing) with the renderer, gnuplot for the study
# plots and ffmpeg for the clips. Writes only into FIG_DIR, CLIP_DIR (and a temporary folder).
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
FIG=${1:-$ROOT/out/slides/figures}
mkdir -p "$FIG"
FIG=$(cd "$FIG" && pwd)
CLIPS=${2:-$(dirname "$FIG")/clips}
mkdir -p "$CLIPS"
CLIPS=$(cd "$CLIPS" && pwd)
command -v ffmpeg >/dev/null || { echo "error: ffmpeg is not installed (the live-demo clips); install it with: sudo apt-get install -y ffmpeg" >&2; exit 1; }
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
# clip SCENE SECONDS NAME [render options...]: the live demo as a short video, 640x360 at 25 fps,
# CLIP_DIR/NAME (H.264, ./lab render --video); the frames go to the temporary folder
clip() {
  local scene=$1 secs=$2 name=$3; shift 3
  rm -rf "$tmp/clip"
  run ./lab render "$scene" --seconds "$secs" --fps 25 --size 640x360 --quiet --out "$tmp/clip" \
    --video "$CLIPS/$name" "$@"
  [[ -s $CLIPS/$name ]] || { echo "error: ./lab render wrote no $CLIPS/$name (log: $log)" >&2; exit 1; }
  echo "  clips/$name"
}
# study KIND SCENE NAME [options...]: a ./lab study run; its data (CSV, .dat) stays in $tmp/NAME for
# the slide plots below, drawn from that data with fonts readable from the back of a lecture hall
study() {
  local kind=$1 scene=$2 name=$3; shift 3
  run ./lab study "$kind" "$scene" "$@" --out "$tmp/$name"
}
# plot NAME.png: gnuplot (script on stdin) draws FIG/NAME.png, 1000x560 pixels, 20-point fonts
plot() {
  { echo "set terminal pngcairo size 1000,560 font ',20' linewidth 2"
    echo "set output '$FIG/$1'"
    echo "set grid; set logscale xy; set format x '10^{%L}'; set format y '10^{%L}'"
    cat; } >"$tmp/${1%.png}.gp"
  run gnuplot "$tmp/${1%.png}.gp"
  echo "  $1"
}

echo "slides: figures into $FIG"
frame scenes/spring.json 0.4 spring.png                     # ch. 2
frame scenes/mfn_hanging.json 1.5 mfn_hanging.png --strain  # ch. 4, 5
frame scenes/pbd_hanging.json 3 pbd_hanging.png             # ch. 7
frame scenes/pbd_flag.json 2 pbd_flag.png                   # ch. 8
frame scenes/pbd_sphere.json 2 pbd_sphere.png               # ch. 1, 9
study precision scenes/spring.json spring_precision \
  --dt-min 1e-4 --dt-max 1e-2 --dt-count 7 --end-time 2     # ch. 3
d=$tmp/spring_precision
plot spring_precision.png <<GP
set xlabel 'wall time [s]'; set ylabel 'error at T = 2 s [m]'; set key outside right
plot '$d/precision_explicit_euler.dat' u 3:2 w lp pt 5 t 'explicit Euler', \
     '$d/precision_symplectic_euler.dat' u 3:2 w lp pt 7 t 'symplectic Euler', \
     '$d/precision_velocity_verlet.dat' u 3:2 w lp pt 9 t 'velocity Verlet', \
     '$d/precision_rk4.dat' u 3:2 w lp pt 11 t 'RK4', \
     '$d/precision_implicit_euler.dat' u 3:2 w lp pt 13 t 'implicit Euler'
GP
study stability scenes/spring.json spring_stability --methods symplectic_euler \
  --set 'spring.start=[0,-1.108,0]'                         # ch. 3
d=$tmp/spring_stability
plot spring_stability.png <<GP
set xlabel 'stiffness k [N/m]'; set ylabel 'time step {/Symbol D}t [s]'; set key outside right
set xtics 100; set title 'symplectic Euler, m = 1 kg'
$(grep '^w(k)' "$d/stability.gp")
plot '$d/stability_symplectic_euler.dat' u 1:(\$3 > 0 ? \$2 : 1/0) w p pt 7 ps 1.2 lc rgb '#2a9d3a' t 'stable', \
     '$d/stability_symplectic_euler.dat' u 1:(\$3 > 0 ? 1/0 : \$2) w p pt 5 ps 1.2 lc rgb '#d62728' t 'unstable', \
     2 / w(x) w l lw 2 lc rgb 'black' t '{/Symbol w}{/Symbol D}t = 2', \
     pi / w(x) w l lw 2 dt 2 lc rgb '#1f5fbf' t 'Provot: {/Symbol w}{/Symbol D}t = {/Symbol p}'
GP
study precision scenes/pbd_hanging.json pbd_precision \
  --set cloth.nx=12 --set cloth.ny=12 --budgets 1,2,5,10,20,50 --reference-substeps 400   # ch. 10
d=$tmp/pbd_precision
plot pbd_precision.png <<GP
set xlabel 'constraint projections per simulated second'; set ylabel 'RMS position error [m]'
set key outside right
plot '$d/precision_pbd_iterations.dat' u 4:2 w lp pt 5 t 'PBD, iterations', \
     '$d/precision_pbd_substeps.dat' u 4:2 w lp pt 7 t 'PBD, substeps', \
     '$d/precision_xpbd_iterations.dat' u 4:2 w lp pt 9 dt 2 t 'XPBD, iterations', \
     '$d/precision_xpbd_substeps.dat' u 4:2 w lp pt 11 dt 2 t 'XPBD, substeps'
GP
study sag scenes/pbd_curtain.json pbd_xpbd_sag \
  --set cloth.nx=11 --set cloth.ny=11 --set cloth.width=1 --set cloth.height=1 --set pbd.damping=0.05 \
  --iterations 1,2,5,10,20,50,100 --xpbd-substeps 1,10                                 # ch. 10
d=$tmp/pbd_xpbd_sag
plot pbd_xpbd_sag.png <<GP
set datafile separator ','; set xlabel 'solver iterations per step'; set ylabel 'sag [m]'
set format x '%g'; set key outside right
plot '$d/sag.csv' u 1:2 every ::1 w lp pt 7 t 'PBD, k = 1', \
     '$d/sag.csv' u 1:3 every ::1 w lp pt 5 t 'XPBD, 1 substep', \
     '$d/sag.csv' u 1:4 every ::1 w lp pt 9 t 'XPBD, 10 substeps'
GP

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
plot provot_strain.png <<GP
unset logscale; set format x '%g'; set format y '%g'; set yrange [0:*]
set xlabel 'time t [s]'; set ylabel 'max edge strain'; set datafile separator ','; set key top right
plot '$tmp/strain_plain/report.csv' using 't [s]':'max_strain [1]' w l lw 2 t 'without Provot', \
     '$tmp/strain_provot/report.csv' using 't [s]':'max_strain [1]' w l lw 2 t "Provot, {/Symbol t} = 0.1"
GP

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

# the same live demos as short clips (the command each slide names), linked from the live-demo
# slides as clips/NN_name.mp4 for when the demo cannot run; slides/check_clips.sh checks the links
echo "slides: live-demo clips into $CLIPS"
t_clips=$SECONDS
clip scenes/pbd_sphere.json 4 01_pbd_sphere.mp4
clip scenes/spring.json 3 02_spring.mp4
clip scenes/spring.json 4 03_spring_explicit_euler.mp4 --set solver.method=explicit_euler --set solver.dt=0.01
clip scenes/mfn_hanging.json 3 04_mfn_hanging_edges.mp4 --edges
clip scenes/mfn_hanging.json 3 05_mfn_hanging_strain.mp4 --strain
clip scenes/pbd_curtain.json 4 06_pbd_curtain.mp4
clip scenes/pbd_hanging.json 4 07_pbd_hanging_strain.mp4 --strain
clip scenes/pbd_flag.json 4 08_pbd_flag.mp4
clip scenes/pbd_ground.json 4 09_pbd_ground.mp4
clip scenes/pbd_curtain.json 4 10_pbd_curtain_xpbd.mp4 --set solver.method=xpbd --set constraints.distance.compliance=0.01
echo "  (clips: $((SECONDS - t_clips)) s)"
