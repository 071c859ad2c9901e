#!/usr/bin/env bash
# Checks the deck sources (fast, text only; in ./lab test as slides.demo_clips_linked), in both
# editions (slides/edition_text.sh): every deck has a live-demo slide ("## Live demo", "## Live-Demo"),
# that slide links a pre-rendered clip as run:clips/NN_name.mp4, and slides/make_figures.sh makes that
# clip (a `clip SCENE SECONDS NAME` line) from the scene the slide (or its speaker notes) names. That
# the clips are real videos is checked by slides.build_every_deck (label heavy).
#   bash slides/check_clips.sh        (exit 1 and what is wrong when something is)
set -uo pipefail
SRC=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
bad=0 n=0
problem() { echo "$1: $2"; bad=$((bad + 1)); }
# the clips make_figures.sh makes: NAME SCENE, one a line
made=$(awk '$1 == "clip" && NF >= 4 { print $4, $2 }' "$SRC/make_figures.sh")
for lang in en de; do
for md in "$SRC"/[0-9][0-9]_*.md; do
  deck="$(basename "$md") ($lang)"
  n=$((n + 1))
  # the live-demo slide: from its "## " heading to the next one
  demo=$(bash "$SRC/edition_text.sh" "$lang" "$md" | awk '/^## /{p = ($0 ~ /^## Live[ -][Dd]emo/)} p')
  if [[ -z $demo ]]; then problem "$deck" "no '## Live demo' slide"; continue; fi
  links=$(grep -o 'run:clips/[A-Za-z0-9_]*\.mp4' <<<"$demo" | sed 's|^run:clips/||' | sort -u)
  if [[ -z $links ]]; then problem "$deck" "the live-demo slide links no clip ([...](run:clips/NN_name.mp4))"; continue; fi
  for c in $links; do
    scene=$(awk -v c="$c" '$1 == c { print $2 }' <<<"$made")
    if [[ -z $scene ]]; then
      problem "$deck" "links clips/$c, but slides/make_figures.sh makes no such clip (clip SCENE SECONDS $c)"
    elif ! grep -qF -- "$scene" <<<"$demo"; then
      problem "$deck" "clips/$c is rendered from $scene, which the live-demo slide does not name"
    fi
  done
done
done
echo "live-demo clips: $((n - bad)) of $n decks (both editions) link a clip that slides/make_figures.sh makes"
((bad == 0))
