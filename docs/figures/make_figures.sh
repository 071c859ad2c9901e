#!/usr/bin/env bash
# Regenerates the figures of docs/mfn.md, docs/pbd.md, docs/pbd_precision.md and docs/render.md
# with the project's own commands (needs ./lab build, gnuplot, and the renderer for `pictures`).
#   docs/figures/make_figures.sh [studies] [pbd] [pictures]   (no argument: all three)
# studies:  the stability and work-precision studies (./lab study ...), about a minute on 2 cores
# pbd:      docs/figures/make_pbd_figures.sh (XPBD sag, cloth on the sphere)
# pictures: app screenshots (./lab gui SCENE --screenshot ...) and one frame per demo clip (./lab render)
set -euo pipefail
cd "$(dirname "$0")/../.."
fig=docs/figures
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
parts=("$@"); ((${#parts[@]})) || parts=(studies pbd pictures)

studies() {
  local s=build/bin/clothlab
  # docs/mfn.md
  $s study stability scenes/spring.json --set 'spring.start=[0,-1.108,0]' --out "$tmp/stab_spring"
  cp "$tmp/stab_spring/stability.png" $fig/mfn_stability_spring.png
  $s study stability scenes/mfn_hanging.json --set cloth.nx=8 --set cloth.ny=8 --k-count 9 --dt-count 9 --steps 500 \
    --out "$tmp/stab_cloth"
  cp "$tmp/stab_cloth/stability.png" $fig/mfn_stability_cloth.png
  $s study precision scenes/spring.json --dt-min 1e-4 --dt-max 1e-2 --dt-count 7 --end-time 2 --out "$tmp/prec_spring"
  cp "$tmp/prec_spring/precision.png" $fig/mfn_precision_spring.png
  $s study precision scenes/mfn_hanging.json --set cloth.nx=8 --set cloth.ny=8 --set springs.structural.kd=0 \
    --set springs.shear.kd=0 --set forces.air_damping=0 --dt-min 1e-4 --dt-max 3e-3 --dt-count 6 --end-time 0.5 \
    --out "$tmp/prec_cloth"
  cp "$tmp/prec_cloth/precision.png" $fig/mfn_precision_cloth.png
  cp "$tmp/prec_cloth/convergence.png" $fig/mfn_convergence_cloth.png
  # docs/pbd_precision.md
  $s study precision scenes/pbd_hanging.json --out "$tmp/prec_pbd"
  cp "$tmp/prec_pbd/precision.png" $fig/pbd_precision_hanging.png
  $s study precision scenes/pbd_hanging.json --set constraints.distance.compliance=1e-3 --out "$tmp/prec_pbd_stretchy"
  cp "$tmp/prec_pbd_stretchy/precision.png" $fig/pbd_precision_stretchy.png
}

# frame SCENE SECONDS NAME [render options...]: the last frame of a 30 fps, 640x360 clip of SECONDS
frame() {
  local scene=$1 secs=$2 name=$3; shift 3
  rm -rf "$tmp/frames"
  build/bin/clothlab-render render "$scene" --seconds "$secs" --fps 30 --size 640x360 --out "$tmp/frames" --quiet "$@" >/dev/null
  cp "$(ls "$tmp"/frames/frame_*.png | tail -n 1)" "$fig/$name"
}

pictures() {
  local g=build/bin/clothlab-render
  # docs/render.md: the app (panel included), offscreen through OSMesa, 60 frames per simulated second
  $g gui scenes/spring.json --screenshot $fig/app_spring.png --frames 40 --size 1200x750
  $g gui scenes/pbd_sphere.json --screenshot $fig/app_pbd.png --frames 84 --size 1100x690
  $g gui scenes/mfn_hanging.json --screenshot $fig/app_mfn.png --frames 61 --size 1100x690 --strain
  # docs/render.md "Side by side": two runs in the app, and compare.png of ./lab run --compare
  $g gui scenes/pbd_sphere.json --compare pbd:iterations=3,pbd:iterations=30 --screenshot $fig/app_compare.png --frames 90
  build/bin/clothlab run scenes/pbd_hanging.json --compare pbd:iterations=5,pbd:iterations=50,xpbd --seconds 3 --out "$tmp/cmp" --quiet
  cp "$tmp/cmp/compare.png" $fig/compare_hanging.png
  # the demo reel (./lab demo renders these clips at 640x360, 30 fps) and the chain
  frame scenes/spring.json 0.4 demo_spring.png
  frame scenes/mfn_hanging.json 1.5 demo_mfn_hanging.png --strain
  frame scenes/pbd_sphere.json 2 demo_pbd_sphere.png
  frame scenes/chain.json 0.334 demo_chain.png
  frame scenes/pbd_tablecloth.json 3 demo_pbd_tablecloth.png
  frame scenes/pbd_hammock.json 4 demo_pbd_hammock.png
}

for p in "${parts[@]}"; do
  case $p in
    studies) studies ;;
    pbd) bash $fig/make_pbd_figures.sh ;;
    pictures) pictures ;;
    *) echo "unknown part '$p' (studies, pbd, pictures)" >&2; exit 1 ;;
  esac
done
echo "figures written to $fig/"
