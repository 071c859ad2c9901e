#!/usr/bin/env bash
# Checks the citations of the decks (fast, text only; in ./lab test as slides.references_resolve), in
# both editions: every [Key] a deck cites has an entry in slides/references.yaml, every deck cites at
# least one source (its last slide, "References", lists them), every entry is cited somewhere, and a
# paper named in prose ("Teschner et al. 2003") carries its key on the same line.
#   bash slides/check_refs.sh        (exit 1 and what is wrong when something is)
set -uo pipefail
SRC=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
bad=0
problem() { echo "$1"; bad=$((bad + 1)); }
KEY='\[[A-Z][^][ ]*[0-9][0-9][a-z]?\]'  # [Waters87], [Müller07]: the same pattern as edition.lua
entries=$(sed -n 's/^  \([^ :#][^ :]*\):.*/\1/p' "$SRC/references.yaml" | sort -u)
[[ -n $entries ]] || problem "slides/references.yaml: no entries under 'sources:'"
cited=""
for lang in en de; do
  for md in "$SRC"/[0-9][0-9]_*.md; do
    deck="$(basename "$md") ($lang)"
    text=$(bash "$SRC/edition_text.sh" "$lang" "$md")
    keys=$(grep -oE "$KEY" <<<"$text" | tr -d '[]' | sort -u)
    [[ -n $keys ]] || problem "$deck: cites no source; its References slide would be empty"
    for k in $keys; do
      grep -qxF -- "$k" <<<"$entries" || problem "$deck: cites [$k], which has no entry in slides/references.yaml"
    done
    cited+="$keys"$'\n'
    # a paper named in prose must carry its key: "Baraff & Witkin 1998 [Baraff98]"
    while IFS= read -r line; do
      [[ -n $line ]] && problem "$deck: names a paper without its [Key]: ${line:0:100}"
    done < <(grep -E '(et al\.|& [A-Z][a-z]+),? (19|20)[0-9][0-9]' <<<"$text" | grep -vE "$KEY")
  done
done
for k in $entries; do
  grep -qxF -- "$k" <<<"$cited" || problem "slides/references.yaml: [$k] is cited by no deck"
done
n=$(wc -w <<<"$entries")
echo "references: $n sources; every citation of both editions has an entry: $( ((bad == 0)) && echo yes || echo "no, $bad problems")"
((bad == 0))
