#!/usr/bin/env bash
# Derivation tasks state the principle, not the formula; hints nudge first. Checked on exercises/:
#   1. no task sheet (NN_*/README.md), stub (NN_*/*.cpp) or level-1/2 hint (NN_*/hints.json) contains a
#      key expression of a derivation task's answer (list below: regexes, spacing-tolerant, matched
#      after Unicode subscripts, superscripts, bold and the signs − · × are written plainly);
#      only the level-3 hint may give the formula;
#   2. every level-1 hint is a question (ends with "?") that names a slide ("slide 22", "slides 17-21",
#      "slide 'Title'").
# The list is live: each task's level-3 hint and the reference (solutions/, when present) contain one
# of its key expressions. Then the check must fail on copies with a key expression planted into a
# sheet, a stub and a level-2 hint, and with a level-1 hint that is no question or names no slide.
# Usage: derivation_hints_check.sh SOURCE_DIR
set -u
export LC_ALL=C.UTF-8
root=$1
[[ -d $root/exercises ]] || { echo "error: $root/exercises: no such folder"; exit 2; }

# TASK<TAB>REGEX (Perl). After normalising: "w₁" is "w1", "Δt²" is "Δt^2", "−" is "-", "·" is "*",
# "×" is " x ", "**p**" is "p", whitespace is one space.
KEYS=$(cat <<'EOF'
1.5	(?i)kick[- ]drift[- ]kick|half[- ]kick
1.5	v(_|\^)?\{?(half|n\s*\+\s*1/2)
1.5	(dt|Δt)\s*/\s*2\s*\*?\s*(a|w)(?![a-z(])
1.5	0\.5\s*\*\s*dt\s*\*\s*\(\s*f\s*\*\s*w\.asDiagonal
3.2	\(\s*1\s*-\s*k\s*\)\s*(\^|\*\*)\s*\(?\s*1\s*/
3.2	pow\s*\(\s*1(\.0)?\s*-\s*k\b
3.2	(?i)\bn-?th\s+root|\^n\s*√
4.3	w\w{0,3}\s*/\s*\(\s*w\w{0,3}\s*\+\s*w\w{0,3}\s*\)
4.3	C\s*/\s*\(\s*w1\s*\+\s*w2\s*\)
4.3	\bs\s*=\s*(k\s*\*?\s*)?C\s*/\s*\(?\s*(Σ|sum)
4.3	λ_?\w?\s*=\s*-\s*s\s*\*?\s*w
4.3	-\s*(k\s*\*?\s*)?s\s*\*?\s*w_?\w?\s*\*?\s*(∇|grad)
4.3	k\s*\*\s*\(\s*len\s*-\s*d\s*\)\s*/\s*\(\s*wsum|\{\s*-\s*w1\s*\*\s*s\s*,\s*w2\s*\*\s*s\s*\}
5.1	n_?2\s*x\s*p_?2\s*\+\s*\(?\s*p_?2\s*x\s*n_?1
5.1	n_?1\s*x\s*p_?2\s*\+\s*\(?\s*p_?2\s*x\s*n_?2
5.1	q_?2\s*=\s*\(?\s*p_?3\s*x\s*n_?2
5.1	n2\.cross\(\s*p2\s*\)\s*\+\s*p2\.cross\(\s*n1\s*\)
5.1	(?i)swap(ping)?\s+(the\s+order\s+of\s+)?(each|every)\s+cross\s+product
5.2	sin\s*\(?\s*(φ|phi)\s*\)?[^/]{0,40}/\s*\(?\s*(Σ|sum)
5.2	\+\s*(k\s*\*?\s*)?w_?i\s*\*?\s*sin
5.2	k\s*\*\s*g\.sinPhi\s*\*\s*C\s*/\s*sumWq2
6.2	\|\s*u\s*\|\s*\^2\s*\*?\s*t\s*\^2
6.2	\|\s*f\s*\|\s*\^2\s*-\s*R_?h\s*\^2
6.2	-\s*\(?\s*u\s*[.*]\s*f\s*\)?\s*-\s*(√|sqrt)|-\s*B\s*-\s*(std::)?sqrt|B\s*\*\s*B\s*-\s*A\s*\*\s*Cq
6.2	\(\s*f\s*\+\s*t\s*\*?\s*u\s*\)\s*/
6.3	(Δ|d)p\s*=\s*-\s*C\s*\*?\s*n|-\s*C\s*\*\s*c\.n\b
6.4	max\s*\(\s*v_?n\s*,\s*-\s*(e|c\.restitution)
6.4	min\s*\(\s*\|?\s*v_?tL?e?n?\s*\|?\s*,\s*(mu|μ|c\.friction)
EOF
)
SLIDE="(?i)\bslides?\s+([0-9]|'|‘)"

work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
printf '%s\n' "$KEYS" >"$work/keys"
# hint_levels FILE FIRST LAST: the hints of levels FIRST..LAST, one per line, as TASK<TAB>TEXT.
hint_levels() { jq -r --argjson a "$2" --argjson b "$3" 'to_entries[] | .key as $k | .value[$a - 1:$b][] | "\($k)\t\(.)"' "$1"; }
# gives_away LABEL FILE [KEYFILE]: one line per key expression (default: all) found in FILE, after
# normalising its text to the plain notation of the keys; status 1 if any.
gives_away() {
  perl -CSD -Mutf8 -e '
    my ($label, $file, $keys) = @ARGV;
    local $/; open(my $f, "<", $file) or die "$file: $!"; my $t = <$f>;
    $t =~ s/\*\*//g; $t =~ tr/₀₁₂₃₄₅₆₇₈₉ᵢⱼₕₛ/0123456789ijhs/; $t =~ s/²/^2/g; $t =~ s/ⁿ/^n/g; $t =~ s/½/1\/2/g;
    $t =~ s/−/-/g; $t =~ s/·/*/g; $t =~ s/×/ x /g; $t =~ s/\s+/ /g;
    open(my $k, "<", $keys) or die "$keys: $!"; my $bad = 0;
    for (split /\n/, <$k>) {
      my ($task, $re) = split /\t/, $_, 2;
      if ($t =~ /$re/) { print "$label: prints the answer of derivation task $task (\x27$&\x27, key /$re/)\n"; $bad = 1 }
    }
    exit $bad' "$1" "$2" "${3:-$work/keys}"
}

# check TREE: one line per violation, status 1 if any.
check() {
  local tree=$1 bad=0 f dir task text
  for f in "$tree"/exercises/[0-9][0-9]_*/README.md "$tree"/exercises/[0-9][0-9]_*/*.cpp; do
    gives_away "${f#"$tree"/}" "$f" || bad=1
  done
  for f in "$tree"/exercises/[0-9][0-9]_*/hints.json; do
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
    && { echo "FAIL: no key expression of task $task matches its level-3 hint (a stale list, or the formula left level 3)"; fail=1; }
  if [[ -d $root/solutions ]]; then
    sed -E 's://.*$::' "$root"/solutions/"$nn"_*/*.cpp >"$work/reference"
    gives_away x "$work/reference" "$work/task_keys" >/dev/null \
      && { echo "FAIL: no key expression of task $task matches the reference solutions/${nn}_*/ (update the list in $0)"; fail=1; }
  fi
done
check "$root" || { echo "FAIL: a sheet, stub or level-1/2 hint prints a derivation's answer, or a level-1 hint is no question naming a slide (lines above)"; exit 1; }
((fail == 0)) || exit 1

# The check fails on planted violations, each in a fresh copy of exercises/.
fresh() { rm -rf "$work/t" && mkdir -p "$work/t" && cp -r "$root/exercises" "$work/t/"; }
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

echo "derivation tasks $(cut -f1 <<<"$KEYS" | sort -u | tr '\n' ' ')state principles: $(grep -c . <<<"$KEYS") key expressions, none in a sheet, stub or level-1/2 hint, each task's in its level-3 hint$([[ -d $root/solutions ]] && echo ' and the reference'); every level-1 hint a question naming a slide; 5 planted violations caught"
