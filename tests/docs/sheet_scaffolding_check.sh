#!/usr/bin/env bash
# Every task sheet (exercises/NN_name/README.md) opens its work with "## Before you start": 3 to 5
# learning objectives ("**You will:**" and a list), the prerequisites and a time estimate. Then it
# proves it fails on a sheet without them.
# Usage: sheet_scaffolding_check.sh SOURCE_DIR
set -u
root=$1
check() {  # check SHEET: one line per problem
  local f=$1 sec n
  sec=$(sed -n '/^## Before you start/,/^## /p' "$f")
  [[ -n $sec ]] || { echo "$f: no '## Before you start' section"; return 1; }
  n=$(sed -n '/^\*\*You will:\*\*/,/^$/p' <<<"$sec" | grep -c '^- ')
  ((n >= 3 && n <= 5)) || { echo "$f: $n learning objectives under **You will:** (want 3 to 5)"; return 1; }
  grep -q '^\*\*Prerequisites:\*\* .' <<<"$sec" || { echo "$f: no **Prerequisites:** line"; return 1; }
  grep -qE '^\*\*Time:\*\* .*[0-9]+.*hours?' <<<"$sec" || { echo "$f: no **Time:** estimate in hours"; return 1; }
}
bad=0 sheets=0
for f in "$root"/exercises/[0-9][0-9]_*/README.md; do
  sheets=$((sheets + 1)); check "$f" || bad=1
done
((sheets >= 7)) || { echo "FAIL: only $sheets task sheets found"; exit 1; }
((bad == 0)) || { echo "FAIL: a task sheet lacks its objectives, prerequisites or time"; exit 1; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
printf '# Stage 99\n\n## Notation\n' >"$tmp/README.md"
check "$tmp/README.md" >/dev/null && { echo "FAIL: a sheet without the section passes"; exit 1; }
echo "all $sheets task sheets state their objectives, prerequisites and time (and a bare sheet is caught)"
