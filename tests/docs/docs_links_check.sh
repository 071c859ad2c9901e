#!/usr/bin/env bash
# Every file the README and docs/*.md point to exists: markdown links [text](path) and paths in
# backticks under the repository's top folders (framework/, tests/, scenes/, docs/, exercises/,
# solutions/, cmake/, benchmarks/, slides/). Placeholders (NN, 0N, *, <...>, {a,b}) are skipped.
# And the README stays under 12 KB; the student copy's README (README.student.md) has the README's stage
# table and an example grade of stage 01 that counts the tests and points tests/01_hooke.points.json has
# in the student copy; docs/grading.md's stage totals are the points files'.
# Usage: docs_links_check.sh SOURCE_DIR   (then proves it fails on a copy with a broken link planted)
set -u
root=$1

check() {  # check TREE
  local tree=$1 bad=0 f dir ref path
  for f in "$tree/README.md" "$tree/README.student.md" "$tree"/docs/*.md "$tree"/docs/instructor/*.md "$tree"/exercises/*/README.md "$tree/slides/README.md"; do
    [[ -f $f ]] || continue
    dir=$(dirname "$f")
    # markdown links, relative to the file
    while IFS= read -r ref; do
      path=${ref%%#*}
      [[ -z $path || $path == http* || $path == mailto:* ]] && continue
      [[ -e $dir/$path ]] || { echo "${f#$tree/}: link to a missing file: $ref"; bad=1; }
    done < <(grep -oE '\]\([^)[:space:]]+\)' "$f" | sed -E 's/^\]\((.*)\)$/\1/')
    # repository paths in backticks, relative to the tree's root
    while IFS= read -r ref; do
      [[ $ref =~ (NN|0N|\*|<|\{|\.\.\.|…|\$) ]] && continue
      path=${ref%%:*}
      [[ -e $tree/$path ]] || { echo "${f#$tree/}: names a missing file: $ref"; bad=1; }
    done < <(grep -oE '`(framework|tests|scenes|docs|exercises|solutions|cmake|benchmarks|slides)/[^` ]+`' "$f" | tr -d '`' | sed -E 's/[),.;]+$//')
  done
  return $bad
}

check "$root" || { echo "FAIL: the docs point to files that do not exist"; exit 1; }
size=$(wc -c <"$root/README.md")
((size < 12 * 1024)) || { echo "FAIL: README.md is $size bytes; keep it under 12 KB (one screen per audience, details in docs/)"; exit 1; }
# What a student sees: the points file as ./lab release leaves it (tools/student_points.jq; the copy's own
# file passes through it unchanged).
student=$(jq -c -f "$root/tools/student_points.jq" "$root/tests/01_hooke.points.json") || { echo "FAIL: tools/student_points.jq"; exit 1; }
tests=$(jq '.tests | length' <<<"$student") points=$(jq '[.tests[]] | add' <<<"$student")
row=$(grep -E '^ *01 +Hooke' "$root/README.student.md")
[[ $row =~ [0-9]+\ /\ ([0-9]+)\ +[0-9.]+\ /\ ([0-9.]+) && ${BASH_REMATCH[1]} == "$tests" && ${BASH_REMATCH[2]} == "$points.0" ]] \
  || { echo "FAIL: README.student.md's example grade of stage 01 ('$row') must show / $tests tests and / $points.0 points (tests/01_hooke.points.json as the student copy has it)"; exit 1; }
# The stage table is in both READMEs (the student copy's README is README.student.md): the same rows.
stage_rows() { grep -E '^\| \[0[1-9]\]\(exercises/' "$1"; }
[[ -n $(stage_rows "$root/README.md") && $(stage_rows "$root/README.md") == "$(stage_rows "$root/README.student.md")" ]] \
  || { echo "FAIL: the stage tables of README.md and README.student.md differ: $(diff <(stage_rows "$root/README.md") <(stage_rows "$root/README.student.md") | head -4 | tr '\n' ' ')"; exit 1; }
# docs/grading.md's stage totals ("the stage totals are A–B (stage 01 has N task tests)") are the points files'.
totals() {  # the sentence as the points files make it
  local lo hi n
  read -r lo hi < <(jq -s '[.[] | [.tests[]] | add] | "\(min) \(max)"' -r "$root"/tests/[0-9][0-9]_*.points.json)
  n=$(jq '[.tests | keys[] | select(startswith("Task"))] | length' "$root/tests/01_hooke.points.json")
  echo "the stage totals are $lo–$hi (stage 01 has $n task tests)"
}
sentence=$(totals)
grep -qF "$sentence" "$root/docs/grading.md" \
  || { echo "FAIL: docs/grading.md must say '$sentence' (the points files' totals; recipe in docs/maintaining.md)"; exit 1; }
sed 's/stage 01 has [0-9]* task tests/stage 01 has 999 task tests/' "$root/docs/grading.md" | grep -qF "$sentence" \
  && { echo "FAIL: the stage-totals check misses a planted wrong count"; exit 1; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/t/docs" && cp "$root/README.md" "$tmp/t/" && cp "$root"/docs/*.md "$tmp/t/docs/"
echo 'See [the scenes](docs/no_such_file.md) and `framework/src/sim/no_such_file.cpp`.' >> "$tmp/t/README.md"
out=$(check "$tmp/t")
grep -q "docs/no_such_file.md" <<<"$out" && grep -q "framework/src/sim/no_such_file.cpp" <<<"$out" \
  || { echo "FAIL: the check misses a planted broken link"; exit 1; }
echo "every file the README and docs point to exists (and a planted broken link is caught)"
