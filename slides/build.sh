#!/usr/bin/env bash
# Builds the lecture slides: one PDF per chapter (slides/NN_*.md) and the whole course.
#   bash slides/build.sh [OUT_DIR]     (default: out/slides/)
# Regenerates the data figures and the live-demo clips first (slides/make_figures.sh into
# OUT_DIR/figures and OUT_DIR/clips; SLIDES_FIGURES=skip reuses those). Writes only into OUT_DIR,
# never into the source tree.
# Needs the Debian packages pandoc texlive-latex-recommended texlive-latex-extra
# texlive-fonts-recommended lmodern (and gnuplot-nox, ffmpeg + the clothlab build for the figures).
set -euo pipefail
SRC=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
ROOT=$(cd "$SRC/.." && pwd)
OUT=${1:-$ROOT/out/slides}
mkdir -p "$OUT"
OUT=$(cd "$OUT" && pwd)

die() { printf 'error: %s\n' "$*" >&2; exit 1; }
need() {  # need COMMAND PACKAGE: a clear message naming the Debian package
  command -v "$1" >/dev/null || die "$1 is not installed; install it with: sudo apt-get install -y $2"
}
need pandoc pandoc
need pdflatex texlive-latex-recommended
for f in beamer.cls:texlive-latex-recommended tikz.sty:texlive-pictures lmodern.sty:lmodern \
         ptmr8t.tfm:texlive-fonts-recommended pbox.sty:texlive-latex-extra; do
  kpsewhich "${f%%:*}" >/dev/null || die "LaTeX file ${f%%:*} is missing; install it with: sudo apt-get install -y ${f##*:}"
done

if [[ ${SLIDES_FIGURES:-} != skip ]]; then
  t_fig=$SECONDS
  bash "$SRC/make_figures.sh" "$OUT/figures" "$OUT/clips"
  echo "figures and clips: $((SECONDS - t_fig)) s"
fi

decks=("$SRC"/[0-9][0-9]_*.md)
# every figure a deck names must have been made (pandoc would only warn and drop it)
for f in $(grep -ho 'figures/[A-Za-z0-9_]*\.png' "${decks[@]}" | sort -u); do
  [[ -f $OUT/$f ]] || die "$OUT/$f is missing: slides/make_figures.sh must make every figure the decks name"
done
# every clip a live-demo slide links (run:clips/NN_name.mp4, relative to the PDFs in OUT_DIR)
for f in $(grep -ho 'run:clips/[A-Za-z0-9_]*\.mp4' "${decks[@]}" | sed 's/^run://' | sort -u); do
  [[ -s $OUT/$f ]] || die "$OUT/$f is missing: slides/make_figures.sh must make every clip the decks link"
done
opts=(-t beamer --slide-level=2 -H "$SRC/preamble.tex" --resource-path="$OUT:$SRC"
      -V aspectratio=169 -V theme=Madrid -V fontsize=10pt
      -V "institute=clothlab -- after \"Advanced Game Physics -- Stoffsimulation\" (FAU, WS 2015/16)"
      -V author=clothlab)
t0=$SECONDS
for md in "${decks[@]}"; do
  name=$(basename "$md" .md)
  title=$(sed -n 's/^# //p' "$md" | head -n 1)
  nn=$((10#${name%%_*}))
  pandoc "${opts[@]}" -V section-titles=false -M "title=Chapter $nn: $title" \
    -M "subtitle=Cloth simulation (Stoffsimulation)" "$md" -o "$OUT/$name.pdf" \
    || die "pandoc failed on $md"
  echo "wrote $OUT/$name.pdf"
done
# the whole course: an overview slide (made from the decks' titles, in OUT_DIR), then every deck
{
  echo "## The ten chapters"
  echo
  for md in "${decks[@]}"; do echo "1. $(sed -n 's/^# //p' "$md" | head -n 1)"; done
} >"$OUT/course_overview.md"
pandoc "${opts[@]}" -M "title=Cloth simulation (Stoffsimulation)" \
  -M "subtitle=Mass-spring systems, mass-spring networks, Position Based Dynamics" \
  "$OUT/course_overview.md" "${decks[@]}" -o "$OUT/course.pdf" || die "pandoc failed on the whole course"
echo "wrote $OUT/course.pdf ($((SECONDS - t0)) s for the PDFs)"
