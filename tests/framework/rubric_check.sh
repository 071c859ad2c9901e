#!/usr/bin/env bash
# The write-up's documents agree with the stages: for every stage folder exercises/NN_name/,
#  - docs/rubric.md has a section "## Stage NN";
#  - the sheet (README.md) ends with a "## Write-up" section naming `./lab report NN`, writeup.md and
#    the rubric's section (../../docs/rubric.md#stage-NN);
#  - writeup.md is a template: the sheet's "Questions to think about" as headings, word for word (stage
#    02's sheet has none, its template at least one question), the heading "Experiments: explain what
#    you measured", and no answer (nothing but headings and comments).
# The check fails on a copy with a rubric section removed, an answer planted in a template and a sheet's
# question changed.
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
problems=$(check "$src")
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
echo "docs/rubric.md has a section for every stage, every sheet ends with its Write-up section, every writeup.md is a template of the sheet's questions without answers; planted violations are found"
