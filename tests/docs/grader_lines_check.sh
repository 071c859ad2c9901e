#!/usr/bin/env bash
# docs/maintaining.md, "Where the grader's lines are": every row's count is the `wc -l` of the files it
# names (paths below framework/grading/, globs allowed), every file of framework/grading/ is in exactly
# one row, and the page's total is the sum and the folder's line count.
# Planted: a row whose count is off by one must fail (checked on a temp copy of the page).
# Usage: grader_lines_check.sh SOURCE_DIR
set -u
root=$1
dir=$root/framework/grading
fail() { echo "FAIL: $*"; exit 1; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

# check PAGE: prints "total N" and every problem; exit 1 on a problem.
check() {
  local page=$1 sum=0 bad=0 part claimed got f list n total
  awk '/^## Where the grader.s lines are/ { on = 1; next } on && /^## / { exit } on && /^\| `/ { print }' "$page" >"$tmp/rows"
  [[ -s $tmp/rows ]] || { echo "no rows under \"## Where the grader's lines are\" in $page"; return 1; }
  : >"$tmp/named"
  while IFS='|' read -r _ part claimed _; do
    claimed=$(echo "$claimed" | tr -d ' ,')
    got=0
    for f in $(echo "$part" | grep -o '`[^`]*`' | tr -d '`'); do
      list=$( (cd "$dir" && compgen -G "$f") | while read -r p; do find "$dir/$p" -type f; done)  # a folder: its files
      [[ -n $list ]] || { echo "$f: names no file of framework/grading/"; bad=1; continue; }
      echo "$list" >>"$tmp/named"
      got=$((got + $(echo "$list" | xargs cat | wc -l)))
    done
    part=$(echo "${part//\`/}" | xargs)
    [[ $got == "$claimed" ]] || { echo "$part: the page says $claimed lines, the files have $got"; bad=1; }
    sum=$((sum + got))
  done <"$tmp/rows"
  sort "$tmp/named" | uniq -d | sed 's/^/in two rows: /' | grep . && bad=1
  find "$dir" -type f | sort | comm -23 - <(sort -u "$tmp/named") | sed 's/^/in no row: /' | grep . && bad=1
  total=$(grep -o '`framework/grading/` is [0-9,]* lines' "$page" | tr -dc '0-9')
  [[ $total == "$sum" ]] || { echo "the page's total is ${total:-missing}, its rows add up to $sum"; bad=1; }
  n=$(find "$dir" -type f -exec cat {} + | wc -l)
  [[ $sum == "$n" ]] || { echo "the rows add up to $sum, framework/grading/ has $n lines"; bad=1; }
  echo "total $sum"
  return $bad
}

out=$(check "$root/docs/maintaining.md") || fail "docs/maintaining.md, the grader's lines: $out"
# The planted case: the first row's count off by one.
awk '/^## Where the grader.s lines are/ { on = 1 } on && /^\| `/ && !done { n = split($0, c, "|"); c[3] = " " (c[3] + 1) " "; s = c[1]
       for (i = 2; i <= n; i++) s = s "|" c[i]; $0 = s; done = 1 } { print }' "$root/docs/maintaining.md" >"$tmp/planted.md"
check "$tmp/planted.md" >/dev/null && fail "a row whose count is off by one was accepted (planted)"
echo "docs/maintaining.md: framework/grading/ is ${out##*total } lines, each row's count as the files have it (a planted wrong count is caught)"
