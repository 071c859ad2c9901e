#!/usr/bin/env bash
# The source text of one edition, for the fast checks (no pandoc, no LaTeX): what slides/edition.lua
# keeps of the bilingual decks, line by line.
#   bash slides/edition_text.sh en|de [--projected] FILE...
# Keeps the lines shared by both languages and those of LANG: drops `::: xx` blocks (to their closing
# `:::`) and `# ... {.xx}` headings of the other language, unwraps the own ones (the fence lines go,
# " {.LANG}" is cut from headings; other classes stay: "## Title {.en .derivation}" becomes
# "## Title {.derivation}", as edition.lua keeps them). --projected: also drops the speaker notes (`::: notes` blocks), so
# what is left is what the projector shows.
set -euo pipefail
lang=$1; shift
notes=keep
[[ ${1:-} == --projected ]] && { notes=drop; shift; }
[[ $lang == en || $lang == de ]] || { echo "edition_text.sh: language en or de, not '$lang'" >&2; exit 2; }
other=$([[ $lang == en ]] && echo de || echo en)
awk -v lang="$lang" -v other="$other" -v notes="$notes" '
  # a fence that opens a div has something after the colons (a class or {attributes}); a bare one closes
  function opener(l) { return l ~ /^:::+ *[^: ]/ }
  function closer(l) { return l ~ /^:::+ *$/ }
  function dropped() { return drop > 0 }
  FNR == 1 { depth = 0; drop = 0; delete kind }
  opener($0) {
    depth++
    k = $0; sub(/^:::+ */, "", k); sub(/ *$/, "", k)
    kind[depth] = (k == other || (k == "notes" && notes == "drop")) ? "drop" : (k == lang ? "own" : "div")
    if (kind[depth] == "drop") drop++
    if (kind[depth] == "div" && !dropped()) print
    next
  }
  closer($0) && depth > 0 {
    if (kind[depth] == "drop") drop--
    else if (kind[depth] == "div" && !dropped()) print
    depth--
    next
  }
  dropped() { next }
  # a heading of one language: "## Title {.en}", or with more classes "## Title {.en .derivation}"
  /^#+ .*\{\.(en|de)( +\.[A-Za-z-]+)*\} *$/ {
    if ($0 ~ ("\\{\\." other "( +\\.[A-Za-z-]+)*\\} *$")) next
    if ($0 ~ /\{\.(en|de)\} *$/) sub(/ *\{\.(en|de)\} *$/, "")
    else sub(/\{\.(en|de) +/, "{")
  }
  { print }
' "$@"
