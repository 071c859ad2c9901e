#!/usr/bin/env bash
# Builds the lecture slides from the bilingual decks slides/NN_*.md, per language (en: English, de:
# German) into OUT_DIR/LANG/: one PDF per chapter, the whole course (course.pdf), the lecturer's copy
# with the speaker notes beside each slide (course_notes.pdf) and the students' handout, two slides
# per A4 page without notes (course_handout.pdf); each PDF's .tex and pdflatex .log stay beside it.
#   bash slides/build.sh [OUT_DIR] [--lang en|de|all]     (default: out/slides/, all)
# Regenerates the data figures and the live-demo clips first (slides/make_figures.sh into
# OUT_DIR/figures and OUT_DIR/clips, shared by both languages; SLIDES_FIGURES=skip reuses those).
# Writes only into OUT_DIR, never into the source tree.
# Needs the Debian packages pandoc texlive-latex-recommended texlive-latex-extra
# texlive-fonts-recommended texlive-lang-german lmodern (and gnuplot-nox, ffmpeg + the clothlab build
# for the figures).
set -euo pipefail
SRC=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
ROOT=$(cd "$SRC/.." && pwd)
die() { printf 'error: %s\n' "$*" >&2; exit 1; }
OUT="" langs=(en de)
while (($#)); do
  case $1 in
    --lang) case ${2:-} in en|de) langs=("$2") ;; all) langs=(en de) ;; *) die "--lang en, de or all" ;; esac; shift 2 ;;
    -*) die "unknown option $1 (bash slides/build.sh [OUT_DIR] [--lang en|de|all])" ;;
    *) OUT=$1; shift ;;
  esac
done
OUT=${OUT:-$ROOT/out/slides}
mkdir -p "$OUT"
OUT=$(cd "$OUT" && pwd)

need() {  # need COMMAND PACKAGE: a clear message naming the Debian package
  command -v "$1" >/dev/null || die "$1 is not installed; install it with: sudo apt-get install -y $2"
}
need pandoc pandoc
need pdflatex texlive-latex-recommended
for f in beamer.cls:texlive-latex-recommended tikz.sty:texlive-pictures lmodern.sty:lmodern \
         ptmr8t.tfm:texlive-fonts-recommended pbox.sty:texlive-latex-extra csquotes.sty:texlive-latex-extra \
         hyph-de-1996.tex:texlive-lang-german; do
  kpsewhich "${f%%:*}" >/dev/null || die "LaTeX file ${f%%:*} is missing; install it with: sudo apt-get install -y ${f##*:}"
done

if [[ ${SLIDES_FIGURES:-} != skip ]]; then
  t_fig=$SECONDS
  bash "$SRC/make_figures.sh" "$OUT/figures" "$OUT/clips"
  echo "figures and clips: $((SECONDS - t_fig)) s"
fi

decks=("$SRC"/[0-9][0-9]_*.md)
# every figure a deck names must have been made (pandoc would only warn and drop it)
for f in $(grep -ho 'figures/[A-Za-z0-9_.]*\.png' "${decks[@]}" | sort -u); do
  [[ -f $OUT/$f ]] || die "$OUT/$f is missing: slides/make_figures.sh must make every figure the decks name"
done
# every clip a live-demo slide links (run:clips/NN_name.mp4; the PDFs in OUT_DIR/LANG link ../clips/)
for f in $(grep -ho 'run:clips/[A-Za-z0-9_]*\.mp4' "${decks[@]}" | sed 's/^run://' | sort -u); do
  [[ -s $OUT/$f ]] || die "$OUT/$f is missing: slides/make_figures.sh must make every clip the decks link"
done

# pdf LANG NAME: OUT_DIR/LANG/NAME.tex -> NAME.pdf; pdflatex runs in OUT_DIR (figures/ is relative to
# it), twice for the page totals; NAME.log is kept for the overfull-box check (slides_build_test.sh)
pdf() {
  local i
  for i in 1 2; do
    (cd "$OUT" && pdflatex -interaction=nonstopmode -halt-on-error -output-directory="$1" "$1/$2.tex" >/dev/null) || {
      grep -A3 '^!' "$OUT/$1/$2.log" | head -n 12 >&2; die "pdflatex failed on $1/$2.tex (log: $OUT/$1/$2.log)"; }
  done
  rm -f "$OUT/$1/$2".{aux,nav,out,snm,toc,vrb}
  echo "wrote $OUT/$1/$2.pdf ($(sed -n 's/^Output written on .*(\([0-9]*\) pages.*/\1/p' "$OUT/$1/$2.log") pages)"
}
opts=(-t beamer -s --slide-level=2 -H "$SRC/preamble.tex" -L "$SRC/edition.lua"
      --metadata-file="$SRC/references.yaml" -M clips=../clips
      -V aspectratio=169 -V theme=Madrid -V fontsize=10pt -V author=clothlab -V csquotes=true)
for lang in "${langs[@]}"; do
  t0=$SECONDS
  mkdir -p "$OUT/$lang"
  for md in "${decks[@]}"; do
    name=$(basename "$md" .md)
    pandoc "${opts[@]}" -M lang="$lang" -M chapter=$((10#${name%%_*})) -M section-titles=false \
      "$md" -o "$OUT/$lang/$name.tex" || die "pandoc failed on $md ($lang)"
    pdf "$lang" "$name"
  done
  # the whole course, the lecturer's copy with the notes, the students' handout
  pandoc "${opts[@]}" -M lang="$lang" -M course=true "${decks[@]}" -o "$OUT/$lang/course.tex" \
    || die "pandoc failed on the whole course ($lang)"
  pdf "$lang" course
  pandoc "${opts[@]}" -H "$SRC/notes.tex" -M lang="$lang" -M course=true "${decks[@]}" \
    -o "$OUT/$lang/course_notes.tex" || die "pandoc failed on the notes ($lang)"
  pdf "$lang" course_notes
  pandoc "${opts[@]}" -H "$SRC/handout.tex" -V classoption=handout -M lang="$lang" -M course=true \
    "${decks[@]}" -o "$OUT/$lang/course_handout.tex" || die "pandoc failed on the handout ($lang)"
  pdf "$lang" course_handout
  echo "$lang: $((SECONDS - t0)) s for the PDFs"
done
# the widest overfull box LaTeX reported (slides_build_test.sh fails above 5 pt)
max=$(for lang in "${langs[@]}"; do cat "$OUT/$lang"/*.log; done | sed -n 's/^Overfull \\[hv]box (\([0-9.]*\)pt.*/\1/p' | sort -g | tail -n 1)
echo "overfull boxes: widest ${max:-0} pt"
