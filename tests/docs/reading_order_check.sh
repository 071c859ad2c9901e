#!/usr/bin/env bash
# docs/grading.md's reading order (the files and functions a new instructor reads to follow one
# submission from unpacking to its points) names code that exists, gives each row its true line
# count, and stays at most 600 lines. A function's lines: from the line that starts its definition
# (the name followed by "(" at the start of a declaration, not a line ending in ";") to its closing
# "}" at the definition's indentation; "(whole file)": every line of the file.
# Planted: a row whose count is off by one must fail (checked on a temp copy of the page).
# Usage: reading_order_check.sh SOURCE_DIR
set -u
root=$1
fail() { echo "FAIL: $*"; exit 1; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

# lines FILE FUNCTION: the lines of FUNCTION's definition in FILE (0 when not found).
lines() {
  awk -v f="$2" '
    !start && $0 ~ "^[A-Za-z].*[ :*&]" f "\\(" && $0 !~ /;[ \t]*$/ { start = NR; indent = "" }
    start && NR >= start && /^}/ { print NR - start + 1; found = 1; exit }
    END { if (!found) print 0 }' "$1"
}

# check PAGE: prints "total N" and every problem; exit 1 on a problem.
check() {
  local page=$1 sum=0 bad=0 file funcs claimed got f n total
  awk '/^## Reading order/ { on = 1; next } on && /^## / { exit } on && /^\| `framework\// { print }' "$page" >"$tmp/rows"
  [[ -s $tmp/rows ]] || { echo "no rows under '## Reading order' in $page"; return 1; }
  while IFS='|' read -r _ file funcs claimed _; do
    file=$(echo "$file" | tr -d ' `') claimed=$(echo "$claimed" | tr -d ' ')
    [[ -f $root/$file ]] || { echo "$file: no such file"; bad=1; continue; }
    got=0
    if [[ $funcs == *"(whole file)"* ]]; then
      got=$(wc -l <"$root/$file")
    else
      for f in $(echo "$funcs" | grep -o '`[A-Za-z_:]*`' | tr -d '`'); do
        n=$(lines "$root/$file" "$f")
        ((n > 0)) || { echo "$file: no function $f"; bad=1; }
        got=$((got + n))
      done
    fi
    [[ $got == "$claimed" ]] || { echo "$file: the page says $claimed lines, the code has $got"; bad=1; }
    sum=$((sum + got))
  done <"$tmp/rows"
  total=$(awk '/^## Reading order/ { on = 1; next } on && /^## / { exit } on && /^\| \*\*total\*\*/ { gsub(/[^0-9]/, "", $0); print; exit }' "$page")
  [[ $total == "$sum" ]] || { echo "the page's total is ${total:-missing}, its rows add up to $sum"; bad=1; }
  ((sum <= 600)) || { echo "the reading order is $sum lines, more than 600"; bad=1; }
  echo "total $sum"
  return $bad
}

out=$(check "$root/docs/grading.md") || fail "docs/grading.md, reading order: $out"
# The planted case: the first row's count off by one.
awk '/^## Reading order/ { on = 1 } on && /^\| `framework\// && !done { n = split($0, c, "|"); c[4] = " " (c[4] + 1) " "; s = c[1]
       for (i = 2; i <= n; i++) s = s "|" c[i]; $0 = s; done = 1 } { print }' "$root/docs/grading.md" >"$tmp/planted.md"
check "$tmp/planted.md" >/dev/null && fail "a row whose count is off by one was accepted (planted)"
echo "docs/grading.md's reading order: ${out##*total } lines of code, each row's count as the code has it (a planted wrong count is caught)"
