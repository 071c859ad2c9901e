#!/usr/bin/env bash
# Regenerates the figures of docs/pbd.md (needs ./lab build and gnuplot):
#   docs/figures/pbd_xpbd_sag.png  static sag of a hanging 11x11 cloth against the solver iteration
#                                  count, PBD (k = 1) versus XPBD (compliance 0.01 m/N, 1 and 10 substeps)
#   docs/figures/pbd_sphere.png    the lecture demo scenes/pbd_sphere.json after 3 s
set -euo pipefail
cd "$(dirname "$0")/../.."
exe=build/bin/clothlab
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
sag() {  # sag of the lowest particle below its rest height y = 1 after 3 s
  "$exe" run scenes/pbd_curtain.json --set cloth.nx=11 --set cloth.ny=11 --set cloth.width=1 --set cloth.height=1 \
    --set pbd.damping=0.05 --steps 300 --quiet --dump "$tmp/d.csv" "$@" >/dev/null
  awk -F, 'NR==2{m=$3} NR>1 && $3<m {m=$3} END{printf "%.6f", 1-m}' "$tmp/d.csv"
}
xp=(--set solver.method=xpbd --set constraints.distance.compliance=0.01)
{
  echo "# iterations pbd_k1 xpbd_sub1 xpbd_sub10"
  for it in 1 2 3 5 7 10 20 30 50 100 200; do
    echo "$it $(sag --set solver.iterations=$it) $(sag "${xp[@]}" --set solver.iterations=$it) $(sag "${xp[@]}" --set solver.substeps=10 --set solver.iterations=$it)"
  done
} >"$tmp/sag.dat"
cat "$tmp/sag.dat"
gnuplot <<GP
set terminal pngcairo size 720,440 font "sans,10"
set output "docs/figures/pbd_xpbd_sag.png"
set logscale xy
set xlabel "solver iterations per step"
set ylabel "static sag of the lowest particle [m]"
set title "Hanging 11x11 cloth (dt = 0.01 s): PBD stiffness depends on the iteration count, XPBD's does not"
set key bottom left
set grid
plot "$tmp/sag.dat" u 1:2 w lp pt 7 t "PBD, k = 1", \
     "" u 1:3 w lp pt 5 t "XPBD, compliance 0.01 m/N", \
     "" u 1:4 w lp pt 9 t "XPBD, compliance 0.01 m/N, 10 substeps"
GP
echo "wrote docs/figures/pbd_xpbd_sag.png"

"$exe" run scenes/pbd_sphere.json --quiet --dump "$tmp/sphere.csv" >/dev/null
awk -F, 'NR>1 { printf "%s %s %s\n", $2, $4, $3; if (($1+1) % 30 == 0) print "" }' "$tmp/sphere.csv" >"$tmp/sphere.dat"
gnuplot <<GP
set terminal pngcairo size 640,480 font "sans,10" noenhanced
set output "docs/figures/pbd_sphere.png"
set title "scenes/pbd_sphere.json after 3 s (PBD, 30x30, distance + bending + sphere collider)"
set view 62, 30
set xyplane at 0
unset key
set parametric
set isosamples 24, 12
set urange [0:2*pi]
set vrange [-pi/2:pi/2]
set xrange [-1:1]; set yrange [-1:1]; set zrange [0:1.3]
set xlabel "x"; set ylabel "z"; set zlabel "y"
splot 0.4*cos(u)*cos(v), 0.4*sin(u)*cos(v), 0.5+0.4*sin(v) lc rgb "#bbbbbb", \\
      "$tmp/sphere.dat" u 1:2:3 w lines lc rgb "#1f5fbf"
GP
echo "wrote docs/figures/pbd_sphere.png"
