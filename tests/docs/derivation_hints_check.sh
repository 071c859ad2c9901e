#!/usr/bin/env bash
# Derivation tasks state the principle, not the formula; hints nudge first. Checked on exercises/,
# the lecture decks slides/*.md (both editions, speaker notes included) and docs/*.md:
#   1. no task sheet (NN_*/README.md), stub (NN_*/*.cpp) or level-1/2 hint (NN_*/hints.json) contains a
#      key expression of a derivation task's answer (tests/instructor/keys/derivations.tsv: regexes, spacing-tolerant, matched
#      after Unicode subscripts, superscripts, bold and the signs − · × are written plainly);
#      only the level-3 hint may give the formula;
#   2. no deck or doc contains one either (their LaTeX and Markdown written plainly first: \frac{a}{b}
#      is a/(b), \vb{p}_1 is p1, \sum is Σ), except the original slides' own formulas: the allow-list
#      tests/instructor/keys/derivations_allowed.tsv, each entry exactly as the decks set it;
#   3. every level-1 hint is a question (ends with "?") that names a slide ("slide 22", "slides 17-21",
#      "slide 'Title'").
# The lists are live: each task's level-3 hint and the reference (solutions/, when present) contain one
# of its key expressions; each allow-list entry is in a deck. Then the check must fail on copies with a
# key expression planted into a sheet, a stub, a level-2 hint, a slide deck and a doc, and with a
# level-1 hint that is no question or names no slide.
# Usage: derivation_hints_check.sh SOURCE_DIR
set -u
export LC_ALL=C.UTF-8
root=$1
[[ -d $root/exercises ]] || { echo "error: $root/exercises: no such folder"; exit 2; }

# The keys, instructor-only (the student copy has no tests/instructor/): TASK<TAB>REGEX (Perl), matched
# after normalising: "w₁" is "w1", "Δt²" is "Δt^2", "−" is "-", "·" is "*", "×" is " x ", "**p**" is "p",
# whitespace is one space; and the allow-list of the original slides' own formulas, TASK<TAB>FORMULA.
keys_dir=$root/tests/instructor/keys
for f in derivations.tsv derivations_allowed.tsv; do
  [[ -f $keys_dir/$f ]] || { echo "error: $keys_dir/$f: no such file (the instructor's keys; this check runs in the instructor's tree)"; exit 2; }
done
KEYS=$(grep -vE '^(#|$)' "$keys_dir/derivations.tsv")
ALLOW=$(grep -vE '^(#|$)' "$keys_dir/derivations_allowed.tsv")
SLIDE="(?i)\bslides?\s+([0-9]|'|‘)"

work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
printf '%s\n' "$KEYS" >"$work/keys"
printf '%s\n' "$ALLOW" >"$work/allow"
# hint_levels FILE FIRST LAST: the hints of levels FIRST..LAST, one per line, as TASK<TAB>TEXT.
hint_levels() { jq -r --argjson a "$2" --argjson b "$3" 'to_entries[] | .key as $k | .value[$a - 1:$b][] | "\($k)\t\(.)"' "$1"; }
# gives_away LABEL FILE [KEYFILE [ALLOWFILE]]: one line per key expression (default: all) found in
# FILE, after normalising its text to the plain notation of the keys; status 1 if any. With ALLOWFILE
# (decks, docs): LaTeX and Markdown are written plainly too, and the allowed formulas are cut first.
gives_away() {
  perl -CSD "$(dirname "${BASH_SOURCE[0]}")/../release/key_expressions.pl" "$1" "$2" "${3:-$work/keys}" ${4:+"$4"}
}

# unchanged TREE FILE: TREE is a planted copy and FILE is as in the source tree (checked there already).
unchanged() { [[ $1 != "$root" ]] && cmp -s "$2" "$root/${2#"$1"/}"; }
# check TREE: one line per violation, status 1 if any. In a planted copy only the files that differ.
check() {
  local tree=$1 bad=0 f dir task text
  for f in "$tree"/exercises/[0-9][0-9]_*/README.md "$tree"/exercises/[0-9][0-9]_*/*.cpp; do
    unchanged "$tree" "$f" && continue
    gives_away "${f#"$tree"/}" "$f" || bad=1
  done
  : >"$work/framework_list"  # the framework ships in the student copy, sources and all
  for f in $(find "$tree/framework/include" "$tree/framework/src" \( -name '*.h' -o -name '*.cpp' \) 2>/dev/null | sort); do
    unchanged "$tree" "$f" || printf '%s\t%s\n' "${f#"$tree"/}" "$f" >>"$work/framework_list"
  done
  [[ -s $work/framework_list ]] && { gives_away - "@$work/framework_list" || bad=1; }
  for f in "$tree"/slides/*.md "$tree"/docs/*.md; do
    [[ -f $f ]] || continue
    unchanged "$tree" "$f" && continue
    gives_away "${f#"$tree"/}" "$f" "$work/keys" "$work/allow" || bad=1
  done
  for f in "$tree"/exercises/[0-9][0-9]_*/hints.json; do
    unchanged "$tree" "$f" && continue
    dir=${f%/hints.json}; dir=${dir#"$tree"/}
    hint_levels "$f" 1 2 >"$work/levels12"
    gives_away "$dir/hints.json (levels 1-2)" "$work/levels12" || bad=1
    while IFS=$'\t' read -r task text; do
      [[ $text =~ \?[[:space:]]*$ ]] || { echo "$dir/hints.json: level 1 of $task is not a question (must end with '?')"; bad=1; }
      grep -qP -- "$SLIDE" <<<"$text" || { echo "$dir/hints.json: level 1 of $task names no slide ('slide 22', 'slide 'Title'')"; bad=1; }
    done < <(hint_levels "$f" 1 1)
  done
  return $bad
}

# The list is live: each task's key expressions find its level-3 hint, and the reference.
fail=0
for task in $(cut -f1 <<<"$KEYS" | sort -u); do
  nn=0${task%%.*}
  grep -F "$task	" "$work/keys" >"$work/task_keys"
  jq -r --arg t "$task" '.[$t][2] // empty' "$root"/exercises/"$nn"_*/hints.json >"$work/level3"
  gives_away x "$work/level3" "$work/task_keys" >/dev/null \
    && { echo "FAIL: no key expression of task $task matches its level-3 hint (a stale tests/instructor/keys/derivations.tsv, or the formula left level 3)"; fail=1; }
  if [[ -d $root/solutions ]]; then
    sed -E 's://.*$::' "$root"/solutions/"$nn"_*/*.cpp >"$work/reference"
    gives_away x "$work/reference" "$work/task_keys" >/dev/null \
      && { echo "FAIL: no key expression of task $task matches the reference solutions/${nn}_*/ (update tests/instructor/keys/derivations.tsv)"; fail=1; }
  fi
done
# The allow-list is live: each entry is, as written, on a slide (else it is stale: update it with the deck).
if [[ -d $root/slides ]]; then
  while IFS=$'\t' read -r task formula; do
    cat "$root"/slides/*.md | grep -qF -- "$formula" \
      || { echo "FAIL: the allowed seed formula of task $task is in no deck as written (update tests/instructor/keys/derivations_allowed.tsv): $formula"; fail=1; }
  done <"$work/allow"
fi
check "$root" || { echo "FAIL: a sheet, stub, level-1/2 hint, deck or doc prints a derivation's answer, or a level-1 hint is no question naming a slide (lines above)"; exit 1; }
((fail == 0)) || exit 1

# The check fails on planted violations, each in a fresh copy of exercises/, slides/*.md and docs/*.md.
fresh() {
  rm -rf "$work/t" && mkdir -p "$work/t/slides" "$work/t/docs" && cp -r "$root/exercises" "$work/t/" \
    && cp "$root"/slides/*.md "$work/t/slides/" && cp "$root"/docs/*.md "$work/t/docs/"
}  # (the framework: only the file a plant goes into, below)
replace_line() {  # replace_line FILE LINE NEW: in the copy, the line LINE (exactly) of FILE becomes NEW
  OLD=$2 NEW=$3 perl -pi -e 's/^\Q$ENV{OLD}\E$/$ENV{NEW}/' "$work/t/$1"
  cmp -s "$root/$1" "$work/t/$1" && { echo "FAIL: could not plant into $1, no line '$2' (update this test)"; exit 1; }
  return 0
}
json_set() {  # json_set FILE TASK LEVEL TEXT
  jq --arg t "$2" --argjson l "$3" --arg s "$4" '.[$t][$l] = $s' "$1" >"$1.new" && mv "$1.new" "$1"
}
expect_caught() {  # expect_caught WHAT PATTERN
  local out
  if out=$(check "$work/t"); then echo "FAIL: the check misses a planted violation: $1"; exit 1; fi
  grep -qE -- "$2" <<<"$out" || { echo "FAIL: planted $1, but the report does not name it: $out"; exit 1; }
}
fresh; printf '\nΔ**p**₁ = −w₁/(w₁ + w₂) · C · **n**\n' >>"$work/t/exercises/04_distance/README.md"
expect_caught "the slide's Δp1 in sheet 04" '04_distance/README\.md: prints the answer of derivation task 4\.3'
fresh; sed -i "s|// TODO 3.2: |// TODO 3.2: k' = 1 - (1 - k)^(1/n), |" "$work/t/exercises/03_pbd_loop/pbd_loop.cpp"
cmp -s "$root/exercises/03_pbd_loop/pbd_loop.cpp" "$work/t/exercises/03_pbd_loop/pbd_loop.cpp" && { echo "FAIL: could not plant into the stub of 3.2 (update this test)"; exit 1; }
expect_caught "k' in the stub of 3.2" '03_pbd_loop/pbd_loop\.cpp: prints the answer of derivation task 3\.2'
fresh; json_set "$work/t/exercises/05_bending/hints.json" 5.2 1 "s = k sin(phi) C / sum_j w_j |q_j|^2, then move each p_i by s w_i q_i."
expect_caught "the bending correction in a level-2 hint" '05_bending/hints\.json \(levels 1-2\): prints the answer of derivation task 5\.2'
fresh; json_set "$work/t/exercises/06_collision/hints.json" 6.2 0 "Slide 24, 'Kollisions-Konstraint': find the entry point."
expect_caught "a level-1 hint that is no question" 'level 1 of 6\.2 is not a question'
fresh; json_set "$work/t/exercises/01_hooke/hints.json" 1.5 0 "Which velocity does the drift use?"
expect_caught "a level-1 hint without a slide" 'level 1 of 1\.5 names no slide'
# decks and docs: k' solved on the slide of chapter 6, the general recipe beside the seed's Δp1, Δp2 in
# chapter 7, the sign-fixed bending correction in the German edition of chapter 8, k' in a doc
fresh; replace_line slides/06_pbd.md "\$\$(1 - k')^n = 1 - k\$\$" "\$\$(1 - k')^n = 1 - k \\;\\Rightarrow\\; k' = 1 - (1 - k)^{1/n}\$\$"
expect_caught "k' on the slide 'Stiffness per iteration'" 'slides/06_pbd\.md: prints the answer of derivation task 3\.2'
fresh; printf '%s\n' '$$s = \frac{C}{\sum_j w_j |\nabla_{\vb{p}_j} C|^2}, \qquad \Delta\vb{p}_i = -k\,s\, w_i \nabla_{\vb{p}_i} C$$' >>"$work/t/slides/07_distance.md"
expect_caught "the general recipe in chapter 7" 'slides/07_distance\.md: prints the answer of derivation task 4\.3'
fresh; printf '%s\n' '::: de' '$$\Delta\vb{p}_i = +\,\frac{w_i\,\sin\varphi\,\bigl(\varphi - \varphi_0\bigr)}{\sum_j w_j |\vb{q}_j|^2}\,\vb{q}_i$$' ':::' >>"$work/t/slides/08_bending.md"
expect_caught "the sign-fixed bending correction in chapter 8 (German)" 'slides/08_bending\.md: prints the answer of derivation task 5\.2'
fresh; printf '\nThe study uses k_sub = 1 − (1 − k)^(1/substeps).\n' >>"$work/t/docs/pbd_precision.md"
expect_caught "k' in docs/pbd_precision.md" 'docs/pbd_precision\.md: prints the answer of derivation task 3\.2'
fresh; mkdir -p "$work/t/framework/src/study" && cp "$root/framework/src/study/precision.cpp" "$work/t/framework/src/study/"
printf '\ndouble perSubstep(double k, int n) { return 1.0 - std::pow(1.0 - k, 1.0 / n); }\n' >>"$work/t/framework/src/study/precision.cpp"
expect_caught "k' computed in the framework" 'framework/src/study/precision\.cpp: prints the answer of derivation task 3\.2'

echo "derivation tasks $(cut -f1 <<<"$KEYS" | sort -u | tr '\n' ' ')state principles: $(grep -c . <<<"$KEYS") key expressions, none in a sheet, stub, level-1/2 hint, framework source, deck or doc (but $(grep -c . <<<"$ALLOW") seed formulas in the decks), each task's in its level-3 hint$([[ -d $root/solutions ]] && echo ' and the reference'); every level-1 hint a question naming a slide; 10 planted violations caught"
