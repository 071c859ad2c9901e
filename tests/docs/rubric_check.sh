#!/usr/bin/env bash
# The write-up's documents agree with the stages: for every stage folder exercises/NN_name/,
#  - docs/rubric.md has a section "## Stage NN";
#  - the sheet (README.md) ends with a "## Write-up" section naming `./lab report NN`, writeup.md and
#    the rubric's section (../../docs/rubric.md#stage-NN);
#  - writeup.md is a template: the sheet's "Questions to think about" as headings, word for word (stage
#    02's sheet has none, its template at least one question), the heading "Experiments: explain what
#    you measured", and no answer (nothing but headings and comments).
# The instructor's keys (docs/instructor/, not in the student copy) agree with them:
#  - docs/instructor/rubric_keys.md has a section "## Stage NN" per stage with one item per item of
#    rubric.md's section (- **Q1**: ..., - **Experiments**: ...), the same labels;
#  - docs/instructor/experiment_keys.md has a section "## Stage NN" per stage with a table row per field
#    of solutions/NN_name/answers.json, "| `field` | quantity | first principles | predicted | measured |
#    ...", whose predicted and measured cells are the reference's predict and measure values (to 4
#    significant digits), and it names the stage's tests/instructor/experiments/NN_name.cpp;
#  - docs/grading.md names docs/instructor/experiment_keys.md and docs/instructor/rubric_keys.md, and
#    docs/rubric.md names neither the keys' numbers nor their files' contents (it links no key file).
# The check fails on a copy with a rubric section removed, an answer planted in a template, a sheet's
# question changed, a rubric item without its key and a key number changed.
# Usage: rubric_check.sh SOURCE_DIR
set -u
src=$1
check() {  # check ROOT: prints one line per problem
  local root=$1 d n nn sheet tpl want got
  for d in "$root"/exercises/[0-9][0-9]_*/; do
    n=$(basename "$d") nn=${n:0:2} sheet=$d/README.md tpl=$d/writeup.md
    grep -qx "## Stage $nn" "$root/docs/rubric.md" || echo "docs/rubric.md: no section \"## Stage $nn\""
    [[ $(grep '^## ' "$sheet" | tail -1) == "## Write-up" ]] || echo "exercises/$n/README.md: the last section is not \"## Write-up\""
    local tail; tail=$(sed -n '/^## Write-up$/,$p' "$sheet")
    for want in "./lab report $nn" "exercises/$n/writeup.md" "../../docs/rubric.md#stage-$nn"; do
      grep -qF -- "$want" <<<"$tail" || echo "exercises/$n/README.md: the Write-up section does not name $want"
    done
    [[ -f $tpl ]] || { echo "exercises/$n/writeup.md: missing"; continue; }
    grep -qx '## Experiments: explain what you measured' "$tpl" || echo "exercises/$n/writeup.md: no heading \"Experiments: explain what you measured\""
    # the sheet's questions, each joined into one line, against the template's headings
    want=$(awk '/^## Questions to think about/ { f = 1; next } /^## / { f = 0 } f' "$sheet" \
           | awk '/^[0-9]+\. / { if (q != "") print q; q = $0; next } /^ +[^ ]/ { sub(/^ +/, " "); q = q $0 } END { if (q != "") print q }')
    got=$(sed -n 's/^### //p' "$tpl")
    [[ -n $got ]] || echo "exercises/$n/writeup.md: no question heading (### ...)"
    [[ -z $want || $want == "$got" ]] || echo "exercises/$n/writeup.md: its question headings are not the sheet's \"Questions to think about\": $(diff <(echo "$want") <(echo "$got") | head -3 | tr '\n' ' ')"
    perl -0pe 's/<!--.*?-->//gs' "$tpl" | grep -vE '^(#+ .*)?[[:space:]]*$' | head -1 | sed "s|^|exercises/$n/writeup.md: text that is not a heading (a template has no answers): |"
  done
}
# keys ROOT: one line per disagreement between the instructor's keys and the stages
keys() {
  local root=$1 d n nn want got answers sect f pv mv row
  local rk=$root/docs/instructor/rubric_keys.md ek=$root/docs/instructor/experiment_keys.md
  [[ -d $root/solutions ]] || return 0  # the student copy: no solutions/, no docs/instructor/
  [[ -f $rk && -f $ek ]] || { echo "docs/instructor/: rubric_keys.md or experiment_keys.md missing"; return; }
  for d in "$root"/exercises/[0-9][0-9]_*/; do
    n=$(basename "$d") nn=${n:0:2}
    want=$(sed -n "/^## Stage $nn\$/,/^## /p" "$root/docs/rubric.md" | sed -n 's/^- \*\*\([A-Za-z0-9]*\) ([0-9]*)\*\*:.*/\1/p' | paste -sd ' ')
    got=$(sed -n "/^## Stage $nn\$/,/^## /p" "$rk" | sed -n 's/^- \*\*\([A-Za-z0-9]*\)\*\*:.*/\1/p' | paste -sd ' ')
    [[ -n $want && $want == "$got" ]] || echo "docs/instructor/rubric_keys.md: stage $nn has the items '$got', docs/rubric.md '$want'"
    answers=$root/solutions/$n/answers.json
    [[ -f $answers ]] || continue  # the student copy has no solutions/ (and no docs/instructor/)
    sect=$(sed -n "/^## Stage $nn\$/,/^## /p" "$ek")
    grep -qF "tests/instructor/experiments/$n.cpp" <<<"$sect" || echo "docs/instructor/experiment_keys.md: stage $nn: names no tests/instructor/experiments/$n.cpp"
    for f in $(jq -r '[(.predict, .measure) | keys[]] | unique[]' "$answers"); do
      pv=$(jq -r --arg f "$f" '.predict[$f].value // empty' "$answers") mv=$(jq -r --arg f "$f" '.measure[$f].value // empty' "$answers")
      row=$(grep -F "| \`$f\` |" <<<"$sect" | head -1 | sed 's/\\|//g')  # (an escaped \| is no cell border)
      [[ -n $row ]] || { echo "docs/instructor/experiment_keys.md: stage $nn: no row for $f"; continue; }
      awk -F'|' -v p="$pv" -v m="$mv" -v f="$f" -v nn="$nn" '
        function same(cell, v,   x) { gsub(/−/, "-", cell); gsub(/ /, "", cell); x = cell + 0
                                    return v == "" || (cell ~ /^-?[0-9.]+(e-?[0-9]+)?$/ && (x - v) * (x - v) <= (5e-4 * v) * (5e-4 * v) + 1e-30) }
        function trim(c) { gsub(/^ +| +$/, "", c); return c }
        { if (!same($5, p)) printf "docs/instructor/experiment_keys.md: stage %s: %s: predicted %s, the reference predicts %s\n", nn, f, trim($5), p
          if (!same($6, m)) printf "docs/instructor/experiment_keys.md: stage %s: %s: measured %s, the reference measures %s\n", nn, f, trim($6), m }' <<<"$row"
    done
  done
  for k in docs/instructor/experiment_keys.md docs/instructor/rubric_keys.md; do
    grep -qF "${k#docs/}" "$root/docs/grading.md" || echo "docs/grading.md does not name $k"
    grep -qF "$(basename "$k")" "$root/docs/rubric.md" && echo "docs/rubric.md names $k (students get it; the keys stay with the instructor)"
  done
}
problems=$(check "$src"; keys "$src")
[[ -z $problems ]] || { printf 'FAIL: %s\n' "$problems"; exit 1; }
# The check can fail: a rubric without stage 03, a template with an answer, a sheet question changed.
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/docs" && cp -r "$src/exercises" "$tmp/" && sed '/^## Stage 03$/d' "$src/docs/rubric.md" >"$tmp/docs/rubric.md"
printf '\nExplicit Euler gains energy because ...\n' >>"$tmp/exercises/01_hooke/writeup.md"
sed -i 's/^1\. Why is k. needed at all?/1. Why is k prime needed?/' "$tmp/exercises/03_pbd_loop/README.md"
planted=$(check "$tmp")
grep -q 'no section "## Stage 03"' <<<"$planted" && grep -q '01_hooke/writeup.md: text that is not a heading' <<<"$planted" \
  && grep -q "03_pbd_loop/writeup.md: its question headings are not the sheet's" <<<"$planted" \
  || { echo "FAIL: the planted violations were not found: $planted"; exit 1; }
# ... and the keys: a rubric item without its key, a key number that is not the reference's
rm -rf "$tmp/exercises" "$tmp/docs" && mkdir -p "$tmp/docs/instructor" && cp -r "$src/exercises" "$src/solutions" "$tmp/"
cp "$src/docs/rubric.md" "$src/docs/grading.md" "$tmp/docs/"
sed '/^## Stage 05$/,/^## Stage 06$/{/^- \*\*Q2\*\*/d}' "$src/docs/instructor/rubric_keys.md" >"$tmp/docs/instructor/rubric_keys.md"
f=$(jq -r '.predict | keys[0]' "$src"/solutions/04_*/answers.json)
awk -v f="$f" 'index($0, "| `" f "` |") { n = split($0, c, "|"); c[5] = " 12345 "; $0 = c[1]; for (i = 2; i < n; i++) $0 = $0 "|" c[i]; $0 = $0 "|" } { print }' \
  "$src/docs/instructor/experiment_keys.md" >"$tmp/docs/instructor/experiment_keys.md"
planted=$(keys "$tmp")
grep -q "rubric_keys.md: stage 05 has the items 'Q1 Q3 Experiments'" <<<"$planted" && grep -q "stage 04: $f: predicted 12345" <<<"$planted" \
  || { echo "FAIL: the planted key violations were not found: $planted"; exit 1; }
echo "docs/rubric.md has a section for every stage, every sheet ends with its Write-up section, every writeup.md is a template of the sheet's questions without answers; the instructor's keys have every rubric item and the reference's numbers; planted violations are found"
