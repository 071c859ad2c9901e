#!/usr/bin/env bash
# ./lab site: the static folder a lecturer publishes.
#   site_test.sh SOURCE_DIR BUILD_DIR TMP
# Runs ./lab site --out TMP/site (the app is built in BUILD_DIR/web) and checks: index.html links every
# scene of scenes/ as app/index.html?scene=NAME (with &set=solver.kernel=batched in the instructor's
# copy) and every stage's sheet, each sheet page exists with
# its headings, the app is there (index.html, clothlab.wasm), and no text file of the site holds a line
# of the reference source (solutions/*/*.cpp lines of 30 characters or more that the stubs do not
# have). Planted: a reference file copied into the site is caught.
set -uo pipefail
src=$1 build=$2 tmp=$3
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$tmp" && mkdir -p "$tmp"
site=$tmp/site
CLOTHLAB_BUILD=$build "$src/lab" site --out "$site" >"$tmp/site.log" 2>&1 || fail "./lab site failed: $(tail -5 "$tmp/site.log")"
[[ -f $site/index.html && -f $site/app/index.html && -f $site/app/clothlab.wasm ]] || fail "no index.html or app/ in $site"
# The instructor's copy: each link sets the batched kernel (its app links solutions/kernels/).
kernel=""
[[ -d $src/solutions/kernels ]] && kernel="&amp;set=solver.kernel=batched"
for s in "$src"/scenes/*.json; do
  n=$(basename "$s" .json)
  grep -qF "href=\"app/index.html?scene=$n$kernel\"" "$site/index.html" || fail "index.html: no link to the demo $n"
done
for d in "$src"/exercises/[0-9][0-9]_*/; do
  n=$(basename "$d")
  grep -qF "href=\"stages/$n.html\"" "$site/index.html" || fail "index.html: no link to the sheet of $n"
  grep -q '<h[12]' "$site/stages/$n.html" 2>/dev/null || fail "stages/$n.html: missing or without headings"
done

# The reference's own lines (not in the stubs).
for f in "$src"/solutions/[0-9][0-9]_*/*.cpp; do
  stub="$src/exercises/$(basename "$(dirname "$f")")/$(basename "$f")"
  sed 's/^[[:space:]]*//' "$f" | awk 'length >= 30' | grep -vxF -f <(sed 's/^[[:space:]]*//' "$stub" 2>/dev/null) || true
done | sort -u >"$tmp/reference_lines.txt"
[[ -s $tmp/reference_lines.txt ]] || fail "no reference lines found to look for (solutions/ missing?)"
leaks() { grep -rIlF -f "$tmp/reference_lines.txt" "$1" 2>/dev/null; }
[[ -z $(leaks "$site") ]] || fail "the site holds reference source: $(leaks "$site" | head -3)"
cp "$(ls "$src"/solutions/04_*/*.cpp | head -1)" "$tmp/planted" && mkdir -p "$tmp/planted_site" && cp "$tmp/planted" "$tmp/planted_site/notes.txt"
[[ -n $(leaks "$tmp/planted_site") ]] || fail "planted: a reference file in the site was not caught"
echo "ok: ./lab site: $(ls "$src"/scenes/*.json | wc -l) demo links, $(ls "$site"/stages/*.html | wc -l) sheets, the app; no line of the reference's $(wc -l <"$tmp/reference_lines.txt") (a planted copy is caught)"
