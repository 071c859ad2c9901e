#!/usr/bin/env bash
# Checks what the projector shows, in both editions (fast, text only; in ./lab test as
# slides.projected_text; slides/edition_text.sh gives each edition's text):
# - the introduction names every lab stage, exercises/NN_name;
# - no audience answer and no live-demo runbook on a projected slide: no "question? (answer)", no
#   "Answers"/"Point at"/"Run" blocks outside the speaker notes, and every live-demo slide has notes
#   with the run command, its duration "(about N min)" and the answers;
# - no text below body size (\tiny, \scriptsize, \footnotesize) in the decks and the preamble;
# - every slide title has both languages: as many `## ... {.en}` as `## ... {.de}` headings, none
#   without, and as many `::: en` as `::: de` blocks.
#   bash slides/check_text.sh        (exit 1 and what is wrong when something is)
set -uo pipefail
SRC=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
ROOT=$(cd "$SRC/.." && pwd)
bad=0
problem() { echo "$1: $2"; bad=$((bad + 1)); }
for lang in en de; do
  intro=$(bash "$SRC/edition_text.sh" "$lang" --projected "$SRC"/01_*.md)
  for d in "$ROOT"/exercises/[0-9][0-9]_*/; do
    stage=$(basename "$d")
    grep -qF -- "$stage" <<<"$intro" || problem "01_introduction.md ($lang)" "does not name the lab stage $stage"
  done
  for md in "$SRC"/[0-9][0-9]_*.md; do
    deck="$(basename "$md") ($lang)"
    shown=$(bash "$SRC/edition_text.sh" "$lang" --projected "$md")
    while IFS= read -r line; do
      [[ -n $line ]] && problem "$deck" "an answer on a projected slide: ${line:0:90}"
    done < <(grep -vE '^#' <<<"$shown" | grep -E '\? *\([^)]*\)')
    while IFS= read -r line; do
      [[ -n $line ]] && problem "$deck" "speaker-notes text on a projected slide: ${line:0:90}"
    done < <(grep -E '\*\*(Answers|Antworten|Point at|Zeigen|Run|Starten)\b|If the demo cannot run' <<<"$shown")
    # the live-demo slide's notes: the command, how long, the answers
    demo=$(bash "$SRC/edition_text.sh" "$lang" "$md" | awk '/^## /{p = ($0 ~ /^## Live[ -][Dd]emo/)} p')
    grep -qE '^::: notes' <<<"$demo" || problem "$deck" "the live-demo slide has no speaker notes"
    grep -qE '\((about|etwa) [0-9]+ min\): `\./lab gui ' <<<"$demo" \
      || problem "$deck" "the live-demo notes do not start the demo: **Run** (about N min): \`./lab gui ...\`"
    grep -qE '^\*\*(Answers|Antworten):\*\*' <<<"$demo" || problem "$deck" "the live-demo notes have no answers"
  done
done
for f in "$SRC"/[0-9][0-9]_*.md "$SRC/preamble.tex"; do
  while IFS= read -r line; do
    [[ -n $line ]] && problem "$(basename "$f")" "text below body size: $line"
  done < <(grep -nE '\\(tiny|scriptsize|footnotesize)\b' "$f")
done
for md in "$SRC"/[0-9][0-9]_*.md; do
  deck=$(basename "$md")
  en=$(grep -cE '^#+ .*\{\.en\} *$' "$md"); de=$(grep -cE '^#+ .*\{\.de\} *$' "$md")
  ((en == de)) || problem "$deck" "$en headings {.en} but $de headings {.de}"
  while IFS= read -r line; do
    [[ -n $line ]] && problem "$deck" "a heading in no language (add {.en} and a {.de} twin): $line"
  done < <(grep -E '^#+ ' "$md" | grep -vE '\{\.(en|de)\} *$')
  en=$(grep -cxE '::: *en *' "$md"); de=$(grep -cxE '::: *de *' "$md")
  ((en == de)) || problem "$deck" "$en '::: en' blocks but $de '::: de' blocks"
done
echo "projected text: $( ((bad == 0)) && echo "both editions clean" || echo "$bad problems")"
((bad == 0))
