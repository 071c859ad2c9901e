#!/usr/bin/env bash
# ./lab report NN (tools/report.sh): the write-up of a stage as one self-contained HTML file.
#  1. On a temporary copy of the tree (exercises/ and scenes/; a student's copy holds the student's code
#     there) with stage 01's answers.json filled in (one field as {predict, predicted, measure, measured,
#     explanation}, one as {value, how}; the sections format {predict, measure, explain} below) and a written writeup.md, the report
#     of stage 01 has its three figures as PNG data: URIs, each with its command, the answers table
#     with every number and text, the write-up rendered (formulas as MathML, comments gone, raw HTML
#     escaped), and no link to any other file. The figures come from this build's command line, which
#     in the instructor's tree runs solutions/: a finished student's exercises/. With a stand-in command
#     line that stops at `not implemented`, the report is still written and each figure's place says
#     why; with one whose runs warn (a pinned particle moved), each figure repeats the warning (its
#     numbers are no result) and so does the terminal; a build that takes the reported stage from the
#     reference is refused.
#  2. Bad input: an unknown stage, broken JSON, a field of the wrong type, a missing answers.json or
#     writeup.md, no pandoc: each one `error:` line naming the file, field or tool, exit 1, no HTML written; the same
#     through ./lab report for an unknown stage and an unknown option.
# fast: part 2 only (no pandoc needed: ./lab test); the whole test needs pandoc (./lab test --heavy
# installs it with the slides' packages).
# Writes only into a temporary folder. Usage: report_test.sh SOURCE_DIR BUILD_DIR [fast]
set -u
src=$1 build=$2 mode=${3:-full}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }
tree=$tmp/tree
mkdir -p "$tree"
cp -r "$src/exercises" "$src/scenes" "$tree/"
ex=$tree/exercises/01_hooke

if [[ $mode != fast ]]; then
# ---- 1. a stage-01 report from a filled-in copy
cat >"$ex/answers.json" <<'JSON'
{
  "symplectic_euler_order": {"predict": "Which order do you expect for symplectic Euler?", "predicted": 1,
    "measure": "./lab study precision scenes/spring.json --methods symplectic_euler,velocity_verlet", "measured": 1.02,
    "explanation": "The local error is O(dt^2) per step & there are 1/dt steps <so> order 1."},
  "velocity_verlet_order": {"value": 2.0, "how": "the fitted order of velocity_verlet"}
}
JSON
perl -0pi -e 's/<!-- your answer -->/Explicit Euler takes the old velocity: MARKER_Q1, \$E_{n+1} = (1 + \\omega^2 \\Delta t^2) E_n\$. <script>alert(1)<\/script>/;
              s/<!-- your answer -->/MARKER_Q2: \$\\omega \\Delta t = 1\$ is below 2./' "$ex/writeup.md"
printf '\nThe measured order was MARKER_EXP because the fit spans a finite range of time steps.\n' >>"$ex/writeup.md"
start=$SECONDS
bash "$src/tools/report.sh" --root "$tree" --build "$build" 01 --out "$tmp/out" >"$tmp/log" 2>&1 || fail "the report of stage 01 failed: $(tail -5 "$tmp/log")"
html=$tmp/out/01_hooke.html
if [[ -s $html ]]; then
  [[ $(grep -o 'src="data:image/png;base64,iVBOR' "$html" | wc -l) -eq 3 ]] || fail "expected 3 PNG figures as data: URIs, found $(grep -o 'data:image/png' "$html" | wc -l)"
  grep -q 'No figure' "$html" && fail "a figure is missing: $(grep -o 'No figure[^<]*' "$html" | head -1)"
  for want in './lab study precision scenes/spring.json --methods symplectic_euler,velocity_verlet' \
              './lab run scenes/spring.json --set solver.method=explicit_euler' 'measured order' \
              '<code>symplectic_euler_order</code>' '<td class="num">1.02</td>' '<td class="num">2</td>' \
              'Which order do you expect for symplectic Euler?' 'per step &amp; there are 1/dt steps &lt;so&gt; order 1.' \
              '<th>explanation</th>' '<th>value</th>' 'MARKER_Q1' 'MARKER_Q2' 'MARKER_EXP' '<math' \
              'Why does explicit Euler gain energy' 'Experiments: explain what you measured' '&lt;script&gt;'; do
    grep -qF -- "$want" "$html" || fail "the report lacks: $want"
  done
  grep -qi '<script' "$html" && fail "the report has a <script> element (raw HTML from writeup.md must be escaped)"
  grep -q 'your answer' "$html" && fail "the template's comments are in the report"
  grep -qE '(src|href)="[^d#]' "$html" && fail "the report links another file: $(grep -oE '(src|href)="[^d#][^"]*"' "$html" | head -1)"
  grep -q 'wrote .*01_hooke.html (3 of 3 figures' "$tmp/log" || fail "no summary line: $(tail -1 "$tmp/log")"
  grep -q '^==> report 01: ./lab study precision' "$tmp/log" || fail "no progress line per command: $(head -3 "$tmp/log")"
  ! grep -E '^(jq|pandoc|gnuplot|error)[: ]|: error' "$tmp/log" || fail "a tool's error in the log of a report that worked (lines above)"
else
  fail "no $html"
fi
echo "stage-01 report: $((SECONDS - start)) s"

# ---- a student's build whose stage 01 is not done (a stand-in command line that says so): the report
# is written, each figure's place says why, with a warning; a build that takes stage 01 from the reference
# is refused (the figures must come from the student's code)
mkdir -p "$tmp/stub/bin"
printf '#!/bin/sh\necho "error: not implemented: exercise 1.4 symplecticEulerStep" >&2\nexit 1\n' >"$tmp/stub/bin/clothlab"
chmod +x "$tmp/stub/bin/clothlab"
printf 'CLOTHLAB_CODE:STRING=exercises\nCLOTHLAB_REFERENCE_STAGES:STRING=05;06\n' >"$tmp/stub/CMakeCache.txt"
# (with answers.json in the sections format: predict and measure, each FIELD: {value, what|how}, and explain)
jq '.predict.energy_drift_dt_1ms.value = 1 | .measure.energy_drift_dt_0_5ms.value = 1.98 | .explain = "Verlet is MARKER_EXPLAIN <b>"' \
  "$src/exercises/01_hooke/answers.json" >"$tmp/sections.json" && cp "$ex/answers.json" "$tmp/fields.json" && cp "$tmp/sections.json" "$ex/answers.json"
bash "$src/tools/report.sh" --root "$tree" --build "$tmp/stub" 01 --out "$tmp/stubout" >"$tmp/stub.log" 2>&1 || fail "the report of an unfinished stage failed: $(tail -3 "$tmp/stub.log")"
for want in '<h3>Predict (from theory, before running)</h3>' '<h3>Measure (your code, the command in how)</h3>' '<th>what to predict</th>' \
            '<td class="num">1.98</td>' '<p>Verlet is MARKER_EXPLAIN &lt;b&gt;</p>'; do
  grep -qF -- "$want" "$tmp/stubout/01_hooke.html" || fail "the sections format: the report lacks $want"
done
cp "$tmp/fields.json" "$ex/answers.json"
[[ $(grep -o 'No figure: [^<]*not implemented: exercise 1.4' "$tmp/stubout/01_hooke.html" 2>/dev/null | wc -l) -eq 3 ]] \
  && grep -q 'Figures made by your code in exercises/, the reference for stage 05,06' "$tmp/stubout/01_hooke.html" \
  && [[ $(grep -c '^==> warning: report 01: figure' "$tmp/stub.log") -eq 3 ]] && grep -q '(0 of 3 figures; 3 could not be made' "$tmp/stub.log" \
  || fail "an unfinished stage's report: $(tail -3 "$tmp/stub.log")"
# a run that warned: its numbers are no result, so the report repeats its warning beside the figure and on
# the terminal (a stand-in command line whose runs end with a warning, as ./lab run prints it)
mkdir -p "$tmp/warn/bin" && cp "$tmp/stub/CMakeCache.txt" "$tmp/warn/"
printf '#!/bin/sh\necho "summary: 10 steps"\necho "warnings (1): do not trust the numbers above; each warning says why and what would help"\necho "  warning: MARKER_WARN a pinned particle (0) moved in the pass constraints: distance"\nexit 0\n' >"$tmp/warn/bin/clothlab"
chmod +x "$tmp/warn/bin/clothlab"
bash "$src/tools/report.sh" --root "$tree" --build "$tmp/warn" 01 --out "$tmp/warnout" >"$tmp/warn.log" 2>&1 || fail "the report of runs that warned failed: $(tail -3 "$tmp/warn.log")"
[[ $(grep -c 'class="fail">Warning: a run of this figure warned' "$tmp/warnout/01_hooke.html" 2>/dev/null) -eq 3 ]] \
  && grep -q 'warning: MARKER_WARN a pinned particle (0) moved' "$tmp/warnout/01_hooke.html" \
  && grep -q '^==> warning: report 01: figure 1 (.*): a run warned, its numbers are no result: ./lab run scenes/spring.json .*MARKER_WARN' "$tmp/warn.log" \
  && grep -q 'runs warned: their numbers are no result' "$tmp/warn.log" \
  || fail "a run that warned: the report does not repeat its warning beside each figure and on the terminal: $(grep -i warn "$tmp/warn.log" | head -5)"
sed -i 's/^CLOTHLAB_REFERENCE_STAGES:STRING=.*/CLOTHLAB_REFERENCE_STAGES:STRING=01;02/' "$tmp/stub/CMakeCache.txt"
bash "$src/tools/report.sh" --root "$tree" --build "$tmp/stub" 01 --out "$tmp/refout" >"$tmp/ref.log" 2>&1 && fail "a report of stage 01 from the reference was made"
grep -q '^error: report: this build takes stage 01 from the reference' "$tmp/ref.log" && [[ ! -e $tmp/refout/01_hooke.html ]] \
  || fail "a build with stage 01 from the reference: $(cat "$tmp/ref.log")"

fi  # mode != fast

# ---- 2. bad input: one error line naming the file (and field), exit 1, no HTML
bad() {  # bad WHAT EXPECTED_REGEX ARGS...
  local what=$1 want=$2; shift 2
  rm -rf "$tmp/bad"
  bash "$src/tools/report.sh" --root "$tree" --build "$build" "$@" --out "$tmp/bad" >"$tmp/bad.log" 2>&1
  local rc=$?
  [[ $rc -eq 1 ]] || fail "$what: exit $rc, expected 1"
  [[ $(grep -c . "$tmp/bad.log") -eq 1 ]] && grep -qE "^error: $want" "$tmp/bad.log" || fail "$what: $(cat "$tmp/bad.log")"
  [[ ! -e $tmp/bad ]] || fail "$what: wrote $(ls "$tmp/bad")"
}
bad "unknown stage" 'exercises/09_\*: \(folder\): there is no stage 09 \(the stages: 01 02' 09
bad "not a stage number" "report: 'x' is not a stage number" x
cp "$ex/answers.json" "$tmp/answers.json"
echo '{"symplectic_euler_order": {"value": 1.0,}' >"$ex/answers.json"
bad "broken answers.json" 'exercises/01_hooke/answers.json: \(JSON\): not valid JSON: .*line 1' 01
echo '{"symplectic_euler_order": {"measured": "one"}}' >"$ex/answers.json"
bad "a number that is text" 'exercises/01_hooke/answers.json: symplectic_euler_order.measured: expected a number or null, got "one"' 01
echo '{"predict": {"symplectic_euler_order": {"value": [1]}}, "explain": ""}' >"$ex/answers.json"
bad "a number that is a list (sections format)" 'exercises/01_hooke/answers.json: predict.symplectic_euler_order.value: expected a number or null, got \[1\]' 01
echo '{"symplectic_euler_order": [1.0]}' >"$ex/answers.json"
bad "a field that is a list" 'exercises/01_hooke/answers.json: symplectic_euler_order: expected an object, text or a number, got an array' 01
rm "$ex/answers.json"
bad "no answers.json" 'exercises/01_hooke/answers.json: \(file\): not found' 1
cp "$tmp/answers.json" "$ex/answers.json"
mv "$ex/writeup.md" "$tmp/writeup.md"
bad "no writeup.md" 'exercises/01_hooke/writeup.md: \(file\): not found' 01
# without pandoc: one line naming it and the package
mv "$tmp/writeup.md" "$ex/writeup.md"
mkdir -p "$tmp/bin"
for t in bash jq sed grep awk ls cut paste head tail rm cat wc dirname gnuplot base64 perl mktemp; do ln -s "$(command -v $t)" "$tmp/bin/$t"; done
PATH=$tmp/bin bad "no pandoc" 'report: pandoc is not installed; .*: sudo apt-get install pandoc' 01
# through ./lab (before any build): an unknown stage and an unknown option
CLOTHLAB_NO_BUILD=1 CLOTHLAB_BUILD=$build "$src/lab" report 42 >"$tmp/lab.log" 2>&1 && fail "./lab report 42 succeeded"
grep -qx 'error: exercises/42_\*: (folder): there is no stage 42 (the stages: 01 02 03 04 05 06 07)' "$tmp/lab.log" || fail "./lab report 42: $(cat "$tmp/lab.log")"
CLOTHLAB_NO_BUILD=1 CLOTHLAB_BUILD=$build "$src/lab" report 01 --bogus >"$tmp/lab.log" 2>&1 && fail "./lab report 01 --bogus succeeded"
grep -q '^error: report: unknown option --bogus' "$tmp/lab.log" || fail "./lab report 01 --bogus: $(cat "$tmp/lab.log")"

((fails == 0)) || exit 1
echo "the stage-01 report has its 3 figures with their commands, the answers table (new and old format) and the write-up in one file; bad input is one error line naming the file"
