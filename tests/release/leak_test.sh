#!/usr/bin/env bash
# What students get gives no answer away. A fresh student copy (./lab release, made from
# tools/student_copy.txt) and the text of the handout (the decks' projected slides, both editions:
# slides/edition_text.sh --projected) are searched, every text file of them, for
#  - the reference: windows of its function bodies and every statement of them that computes
#    (clothlab-leak-check reads solutions/ now, so an edited reference is covered at once);
#  - the instructor's keys, gathered now from where the instructor keeps them: the answers in the
#    decks' speaker notes (**Answers:** / **Antworten:**), the instructor's docs (docs/instructor/*.md),
#    the reference's answers.json (its explanations; its numbers in the stage's own sheet, stub, hints,
#    template and header), the notation keys (tests/instructor/keys/notation.txt) and the derivation
#    keys (tests/instructor/keys/derivations.tsv, through key_expressions.pl);
# and none may be found. Then leaks are planted, one at a time, into a copy of what students get: a
# script that quotes a reference line, the decks with their notes, a line of the instructor's docs,
# a notation key in a sheet, an experiment's number in its sheet, a note's answer on a projected slide,
# a derivation's formula in a doc, and a new file holding a reference body; each must be reported,
# naming the planted file.
#   leak_test.sh SOURCE_ROOT LEAK_CHECK
set -u -o pipefail
export LC_ALL=C.UTF-8
root=$1 check=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
[[ -x $check ]] || fail "$check: not built (target clothlab-leak-check)"

# ---- what students get
students=$tmp/students
"$root/lab" release "$students" --no-reference-objects >"$tmp/release.log" 2>&1 || { cat "$tmp/release.log"; fail "./lab release"; }
# Level 3 of each hint is the formula, the free help the course gives on request (./lab hint N.M 3):
# searched are levels 1 and 2 (what the sheet's "stuck?" leads to first).
for f in "$students"/exercises/[0-9][0-9]_*/hints.json; do
  jq 'map_values(.[0:2])' "$f" >"$f.12" && mv "$f.12" "$f" || fail "$f: (JSON): cannot read the hints"
done
for lang in en de; do
  mkdir -p "$students/handout/$lang"
  for md in "$root"/slides/[0-9][0-9]_*.md; do
    bash "$root/slides/edition_text.sh" "$lang" --projected "$md" >"$students/handout/$lang/$(basename "$md")" \
      || fail "slides/edition_text.sh $lang --projected $md"
  done
done

# ---- the instructor's keys: SOURCE<TAB>SCOPE<TAB>KIND<TAB>TEXT (clothlab-leak-check --keys)
keys=$tmp/keys.tsv
: >"$keys"
# notation keys: in the sheets, stubs, hints and templates (elsewhere some are the seed's own formulas,
# e.g. line (13) of the algorithm, v = (p - x) / dt, which the graded tests may use)
grep -vE '^(#|$)' "$root/tests/instructor/keys/notation.txt" \
  | awk '{ st = $1; sub(/^[^ ]+ /, ""); printf "tests/instructor/keys/notation.txt (stage %s)\texercises/\ttokens\t%s\n", st, $0 }' >>"$keys"
# the answers of the speaker notes: each **Answers:** / **Antworten:** paragraph, one line, its prose
# (formulas in $...$ are the decks' own notation, which the projected slides share)
for md in "$root"/slides/[0-9][0-9]_*.md; do
  awk -v src="slides/$(basename "$md") (notes)" '
    /^\*\*(Answers|Antworten):\*\*/ { p = 1; t = "" }
    p && /^(:::|$)/ { printf "%s\t*\twords\t%s\n", src, t; p = 0 }
    p { sub(/^\*\*(Answers|Antworten):\*\* */, ""); gsub(/\$[^$]*\$/, " "); t = t " " $0 }
    END { if (p) printf "%s\t*\twords\t%s\n", src, t }' "$md" >>"$keys"
done
# the instructor's docs: each paragraph or list item, one line
for md in "$root"/docs/instructor/*.md; do
  [[ -f $md ]] || continue
  awk -v src="docs/instructor/$(basename "$md")" '
    function flush() { if (t != "") printf "%s\t*\twords\t%s\n", src, t; t = "" }
    /^```/ { flush(); code = !code; next }
    code || /^#/ || /^\|/ { flush(); next }
    /^ *$/ { flush(); next }
    /^ *([-*]|[0-9]+\.) / { flush() }
    { t = t " " $0 }
    END { flush() }' "$md" >>"$keys"
done
# the reference's answers.json: its explanations anywhere; its numbers (of 2 or more significant digits)
# in the stage's own files, where a number could only mean this one
for a in "$root"/solutions/[0-9][0-9]_*/answers.json; do
  stage=$(basename "$(dirname "$a")") nn=${stage:0:2}
  jq -r --arg s "solutions/$stage/answers.json" \
    '.. | objects | to_entries[] | select(.key == "explain" or .key == "explanation") | .value | strings | select(length > 0)
     | "\($s)\t*\twords\t\(gsub("[\t\n]"; " "))"' "$a" >>"$keys"
  for scope in "exercises/$stage/" "framework/include/clothlab/exercise/$stage.h"; do
    jq -r --arg s "solutions/$stage/answers.json" --arg scope "$scope" \
      '.. | objects | select(has("value")) | .value | numbers | tostring
       | select(gsub("[-.0]|e.*$"; "") | length >= 2) | "\($s) (a number)\t\($scope)\ttokens\t\(.)"' "$a" >>"$keys"
  done
done
[[ $(wc -l <"$keys") -gt 50 ]] || fail "only $(wc -l <"$keys") keys gathered (the notes, docs/instructor, answers.json, notation.txt): this test is stale"

# ---- the search
# search DIR: everything it finds, one line each; status 1 if anything
search() {
  local dir=$1 bad=0 f list=$tmp/list
  "$check" "$root" "$dir" --keys "$keys" >"$tmp/found" 2>&1 || bad=1
  grep '^leak:' "$tmp/found"
  grep -q '^\(ok\|FAIL\): ' "$tmp/found" || { cat "$tmp/found"; return 2; }
  # the derivation keys: Markdown (the docs and the handout) with its LaTeX written plainly and the
  # original slides' own formulas allowed, every other text file as it is
  : >"$list.md"; : >"$list.txt"
  while IFS= read -r -d '' f; do
    grep -qI . "$f" 2>/dev/null || continue  # binary or empty
    case $f in
      "$dir"/docs/*.md|"$dir"/handout/*) printf '%s\t%s\n' "${f#"$dir"/}" "$f" >>"$list.md" ;;
      *) printf '%s\t%s\n' "${f#"$dir"/}" "$f" >>"$list.txt" ;;
    esac
  done < <(find "$dir" -type f -print0 | sort -z)
  perl -CSD "$root/tests/release/key_expressions.pl" - "@$list.txt" "$root/tests/instructor/keys/derivations.tsv" \
    | sed 's/^/leak: /' || bad=1
  perl -CSD "$root/tests/release/key_expressions.pl" - "@$list.md" "$root/tests/instructor/keys/derivations.tsv" \
    "$root/tests/instructor/keys/derivations_allowed.tsv" | sed 's/^/leak: /' || bad=1
  return $bad
}
search "$students" >"$tmp/real" || { cat "$tmp/real"; tail -1 "$tmp/found"; fail "what students get gives answers away (lines above: where, and what)"; }
summary=$(tail -1 "$tmp/found")

# ---- planted leaks, each in a fresh copy of what students get
planted=0
plant() {  # plant WHAT PATTERN: the search of $tmp/p fails and names PATTERN (file and kind)
  local out
  out=$(search "$tmp/p") && fail "a planted leak is not found: $1"
  grep -qE -- "$2" <<<"$out" || fail "planted $1, but the report does not name it: $(head -5 <<<"$out")"
  planted=$((planted + 1))
}
fresh() { rm -rf "$tmp/p" && cp -a "$students" "$tmp/p"; }
# a script quoting one line of the reference (the first statement with std::pow in stage 03)
line=$(grep -m1 'std::pow' "$root"/solutions/03_*/*.cpp | sed 's|//.*||; s/^ *//')
[[ -n $line ]] || fail "no std::pow line in solutions/03_*/ to plant (update this test)"
fresh; mkdir -p "$tmp/p/tools" && printf '#!/bin/sh\n# the per-iteration stiffness\nK=$(echo "%s" | bc)\n' "$line" >"$tmp/p/tools/check_k.sh"
plant "a script with a reference line" '^leak: tools/check_k\.sh:3: statement of the reference'
# the decks with their speaker notes (as if tools/student_copy.txt listed slides/)
fresh; cp -r "$root/slides" "$tmp/p/"
plant "the decks with their notes" '^leak: slides/[0-9]+_[a-z_]+\.md:[0-9]+: key of slides/.* \(notes\)'
# a line of the instructor's docs in a doc students get (else a notes answer)
src=$(awk -F'\t' '$1 ~ /^docs\/instructor\// && $3 == "words" { print $4; exit }' "$keys")
[[ -n $src ]] || src=$(awk -F'\t' '$1 ~ /\(notes\)$/ { print $4; exit }' "$keys")
fresh; printf '\n%s\n' "$src" >>"$tmp/p/docs/rubric.md"
plant "an instructor's answer in docs/rubric.md" '^leak: docs/rubric\.md:[0-9]+: key of (docs/instructor|slides)/'
# a notation key in a task sheet
key=$(awk -F'\t' '$1 ~ /notation/ && $4 ~ /w1/ { print $4; exit }' "$keys")
fresh; printf '\nHint: the share is %s.\n' "$key" >>"$tmp/p/exercises/04_distance/README.md"
plant "a notation key in sheet 04" '^leak: exercises/04_distance/README\.md:[0-9]+: key of tests/instructor/keys/notation\.txt'
# an experiment's predicted number in its sheet
num=$(jq -r '.predict | to_entries[0].value.value' "$root"/solutions/04_*/answers.json)
fresh; printf '\n(You should get about %s m.)\n' "$num" >>"$tmp/p/exercises/04_distance/README.md"
plant "an experiment's number in sheet 04" '^leak: exercises/04_distance/README\.md:[0-9]+: key of solutions/04_[a-z_]+/answers\.json \(a number\)'
# a note's answer on a projected slide (the handout)
ans=$(awk -F'\t' '$1 ~ /08_bending\.md \(notes\)$/ { print $4; exit }' "$keys")
[[ -n $ans ]] || fail "no answer in the notes of slides/08_bending.md (update this test)"
fresh; printf '\n- %s\n' "$ans" >>"$tmp/p/handout/en/08_bending.md"
plant "a notes answer on a projected slide" '^leak: handout/en/08_bending\.md:[0-9]+: key of slides/08_bending\.md \(notes\)'
# a derivation's answer (k' solved) in a doc
fresh; printf '\nEach substep uses $k_s = 1 - (1 - k)^{1/n}$.\n' >>"$tmp/p/docs/scenes.md"
plant "k' in docs/scenes.md" "^leak: docs/scenes\.md: prints the answer of derivation task 3\.2"
# a new file anywhere holding a reference body, renamed and reformatted
body=$(awk '/^[A-Za-z].*projectDistanceConstraint\(/ { p = 1 } p { print } p && /^}/ { exit }' "$root"/solutions/04_*/*.cpp | sed '1d;$d')
[[ -n $body ]] || fail "no projectDistanceConstraint in solutions/04_*/ (update this test)"
fresh; mkdir -p "$tmp/p/notes" && printf 'auto corr = [&] {\n%s\n};\n' "$(sed 's|//.*||' <<<"$body" | tr -s ' \n' ' ')" >"$tmp/p/notes/mine.txt"
plant "a reference body in a new file" '^leak: notes/mine\.txt:[0-9]+: (statement of|[0-9]+ windows of [0-9]+ tokens from) the reference'
# Bad input to the search: one error line naming what is wrong, exit 2.
bad_input() {  # bad_input PATTERN ARGS...
  local pattern=$1 code; shift
  "$check" "$@" >"$tmp/out" 2>&1; code=$?
  [[ $code -eq 2 && $(grep -c '^error: ' "$tmp/out") -eq 1 ]] && grep -qE -- "$pattern" "$tmp/out" \
    || fail "clothlab-leak-check $*: exit $code (want 2 and one error line matching $pattern): $(cat "$tmp/out")"
}
bad_input "^error: command line: $tmp/nope: \(folder\)" "$root" "$tmp/nope"
bad_input '^error: command line: --window' "$root" "$students" --window x
printf 'only one field\n' >"$tmp/bad_keys"
bad_input "^error: command line: $tmp/bad_keys:1: expects SOURCE<TAB>SCOPE<TAB>KIND<TAB>TEXT" "$root" "$students" --keys "$tmp/bad_keys"
printf 'src\t*\tregex\tx\n' >"$tmp/bad_keys"
bad_input "^error: command line: $tmp/bad_keys:1: KIND must be tokens or words" "$root" "$students" --keys "$tmp/bad_keys"
echo "what students get gives nothing away: ${summary#ok: }; the derivation keys in none of its files; $planted planted leaks found"
