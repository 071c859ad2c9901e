#!/usr/bin/env bash
# The lecture plan, computed from the decks (English edition; slides/check_text.sh checks that both
# editions give each slide the same minutes and that slides/README.md shows this table):
# a slide takes the minutes its speaker notes give first, "(about N min)" (a derivation, a live demo,
# a phase of the PBD algorithm), else 2 minutes; a lecture is the sum of its chapters' slides.
# The grouping of the chapters into lectures is the LECTURES list below; chapter 10 is optional.
#   bash slides/lecture_plan.sh      (prints the Markdown table of slides/README.md, "Lecture plan")
set -euo pipefail
SRC=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# lecture<TAB>first chapter<TAB>last chapter
LECTURES=$'1\t1\t4\n2\t5\t7\n3\t8\t9\n4 (optional)\t10\t10'
echo "| lecture | chapters | slides | minutes |"
echo "|---|---|---|---|"
while IFS=$'\t' read -r lecture first last; do
  slides=0 minutes=0
  for ((c = first; c <= last; c++)); do
    md=$(printf '%s/%02d_' "$SRC" "$c")
    md=$(ls "$md"*.md)
    read -r n m < <(bash "$SRC/edition_text.sh" en "$md" | awk '
      function close_slide() {
        if (!open) return
        n++; m += match(text, /\(about +[0-9]+ +min\)/) ? minutes(substr(text, RSTART, RLENGTH)) : 2
      }
      function minutes(s) { gsub(/[^0-9]/, "", s); return s + 0 }
      /^## / { close_slide(); open = 1; text = ""; next }
      { text = text " " $0 }
      END { close_slide(); print n, m }')
    slides=$((slides + n)) minutes=$((minutes + m))
  done
  chapters=$first; ((last > first)) && chapters="$first–$last"
  echo "| $lecture | $chapters | $slides | $minutes |"
done <<<"$LECTURES"
