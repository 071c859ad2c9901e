#!/usr/bin/env bash
# What ./lab release writes for the systems instructors use, from the committed tree (git archive HEAD):
#  - the student copy's GitHub Actions self-grade .github/workflows/grade.yml (from docs/ci/grade.yml),
#    parsed as YAML (python3-yaml; a structural grep without it): a plain job that uses no action but checkout and upload-artifact; it
#    runs ./lab setup and ./lab grade --json grade.json with a Markdown table, appends the table to
#    $GITHUB_STEP_SUMMARY and uploads grade.json with actions/upload-artifact@v4.
#  - ./lab release --gradescope: Gradescope's autograder bundle (https://gradescope-autograders.readthedocs.io
#    /en/latest/specs/: setup.sh and run_autograder at the root of the zip), both executable and
#    `bash -n` clean, the student copy beside them; run_autograder, tried in a scratch /autograder with
#    this build's grader, writes results.json for a submission with a broken stage and for one without stages.
# Usage: release_exports_test.sh SOURCE_DIR BUILD_DIR
set -u
root=$1 build=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

CLOTHLAB_BUILD=$build "$root/lab" release "$tmp/gs" --gradescope --no-reference-objects >"$tmp/release.log" 2>&1 \
  || { cat "$tmp/release.log"; fail "./lab release --gradescope"; }
for f in setup.sh run_autograder; do
  [[ -f $tmp/gs/$f && -x $tmp/gs/$f ]] || fail "the bundle's $f is missing or not executable"
  bash -n "$tmp/gs/$f" || fail "the bundle's $f: bash -n"
  head -1 "$tmp/gs/$f" | grep -q '^#!/usr/bin/env bash$' || fail "the bundle's $f has no #! line"
done
copy=$tmp/gs/clothlab
[[ -x $copy/lab && -d $copy/exercises && ! -e $copy/solutions && $(ls "$copy/tests/instructor") == experiments ]] \
  || fail "the bundle's clothlab/ is not the student copy with the instructor's experiments (tests/instructor/experiments only)"
# The bundle grades the experiments' numbers (students never see it): the points of every experiment test.
jq -e '.tests | has("Experiments.AnswerFileIsComplete") and (keys | map(select(startswith("Experiments."))) | length > 1)' \
  "$copy/tests/01_hooke.points.json" >/dev/null || fail "the bundle's points files lack the instructor's experiment tests"
if command -v zip >/dev/null; then
  [[ -f $tmp/gs/autograder.zip ]] || fail "zip is installed but there is no autograder.zip"
  unzip -Z1 "$tmp/gs/autograder.zip" >"$tmp/zip.txt" || fail "autograder.zip does not unzip"
  grep -qx setup.sh "$tmp/zip.txt" && grep -qx run_autograder "$tmp/zip.txt" && grep -qx clothlab/lab "$tmp/zip.txt" \
    || fail "autograder.zip lacks setup.sh, run_autograder at its root or clothlab/lab: $(head -5 "$tmp/zip.txt" | tr '\n' ' ')"
  unzip -Z "$tmp/gs/autograder.zip" run_autograder | grep -q '^-rwx' || fail "run_autograder is not executable in the zip"
  grep -q "autograder.zip" "$tmp/release.log" || fail "the release does not name the zip: $(tail -1 "$tmp/release.log")"
fi

# The workflow in the copy: what it runs and uses.
wf=$copy/.github/workflows/grade.yml
[[ -f $wf ]] || fail "the copy has no .github/workflows/grade.yml"
[[ $(ls "$copy/.github/workflows") == grade.yml ]] || fail "the copy has other workflows: $(ls "$copy/.github/workflows" | tr '\n' ' ')"
cmp -s "$wf" "$root/docs/ci/grade.yml" || fail "grade.yml is not docs/ci/grade.yml (commit it)"
if /usr/bin/python3 -c 'import yaml' 2>/dev/null; then
  /usr/bin/python3 - "$wf" >"$tmp/steps.txt" <<'PY' || fail "$wf: $(cat "$tmp/steps.txt")"
import sys, yaml
wf = yaml.safe_load(open(sys.argv[1]))
on = wf.get("on", wf.get(True))  # YAML 1.1 reads the key on as true
assert on is not None and "push" in on, "not run on push"
jobs = wf["jobs"]
assert len(jobs) == 1, "not one job"
steps = next(iter(jobs.values()))["steps"]
for s in steps:
    if "uses" in s:
        print("uses", s["uses"], "path=" + str(s.get("with", {}).get("path", "")))
    else:
        print("run", s["run"].replace("\n", " ; "))
PY
else  # structurally: the uses: and run: lines (a run: | block joined with " ; ")
  awk 'function flush() { if (inblk) print "run " blk; inblk = 0; blk = "" }
       inblk { match($0, /^ */); if (RLENGTH > ind || $0 ~ /^ *$/) { sub(/^ +/, ""); if ($0 != "") blk = blk (blk == "" ? "" : " ; ") $0; next } flush() }
       /^ *(- )?run: [|]/ { match($0, /^ */); ind = RLENGTH; inblk = 1; next }
       /^ *(- )?run: / { sub(/^ *(- )?run: /, ""); print "run " $0; next }
       /^ *(- )?uses: / { sub(/^ *(- )?uses: /, ""); print "uses " $0 }
       END { flush() }' "$wf" >"$tmp/steps.txt"
  grep -q '^ *path: grade.json$' "$wf" && sed -i 's|^uses actions/upload-artifact@v4$|& path=grade.json|' "$tmp/steps.txt"
fi
grep -q '^uses actions/checkout@v4' "$tmp/steps.txt" || fail "no checkout step"
grep -q '^run \./lab setup' "$tmp/steps.txt" || fail "no ./lab setup step: $(cat "$tmp/steps.txt")"
grep -E '^run .*\./lab grade .*--json grade\.json' "$tmp/steps.txt" | grep -q -- '--markdown grade\.md' || fail "no ./lab grade --json grade.json --markdown grade.md step"
grep -q '^run .*cat grade\.md.*>> "\$GITHUB_STEP_SUMMARY"' "$tmp/steps.txt" || fail "the table is not appended to \$GITHUB_STEP_SUMMARY: $(cat "$tmp/steps.txt")"
grep -qx 'uses actions/upload-artifact@v4 path=grade.json' "$tmp/steps.txt" || fail "grade.json is not uploaded with actions/upload-artifact@v4: $(cat "$tmp/steps.txt")"
[[ $(grep -c '^uses ' "$tmp/steps.txt") -eq 2 ]] || fail "actions other than checkout and upload-artifact: $(grep '^uses ' "$tmp/steps.txt")"

# run_autograder in a scratch /autograder (the bundle as its source), with this build's grader and kit:
# a submission whose stage 01 does not compile gets results.json with the compiler's message on stage
# 01's tests and the other stages not submitted; one without any stage folder gets results.json that
# says why.
[[ -f $build/grade-kit/kit.json ]] || fail "no $build/grade-kit/kit.json (build clothlab-grade-kit first)"
ag=$tmp/autograder; mkdir -p "$ag/submission/my-repo/exercises/01_hooke"; ln -s "$tmp/gs" "$ag/source"
cp "$root"/exercises/01_hooke/*.cpp "$ag/submission/my-repo/exercises/01_hooke/"
echo 'this line is not C++ ;' >>"$ag/submission/my-repo/exercises/01_hooke/hooke.cpp"
AUTOGRADER_ROOT=$ag CLOTHLAB_BUILD=$build "$tmp/gs/run_autograder" >"$tmp/run.log" 2>&1
jq -e '.score == 0 and (.tests | length) > 0
       and all(.tests[] | select(.name | startswith("stage 01: ")); .status == "failed" and (.output | test("hooke[.]cpp:[0-9]+:[0-9]+: error")))
       and all(.tests[] | select(.name | startswith("stage 01: ") | not); .status == "failed" and (.output | contains("not submitted")))' \
  "$ag/results/results.json" >/dev/null || { tail "$tmp/run.log"; fail "run_autograder on a broken stage 01: $(head -c 400 "$ag/results/results.json")"; }
rm -rf "$ag/submission/my-repo" "$ag/results"
AUTOGRADER_ROOT=$ag CLOTHLAB_BUILD=$build "$tmp/gs/run_autograder" >"$tmp/run.log" 2>&1
jq -e '.score == 0 and .tests == [] and (.output | test("could not grade this submission:\nerror: .*submission: [(]layout[)]: no stage folder found"))' \
  "$ag/results/results.json" >/dev/null || { tail "$tmp/run.log"; fail "run_autograder without stage folders: $(head -c 400 "$ag/results/results.json")"; }
echo "the copy's workflow grades, summarises and uploads grade.json (no other action); the Gradescope bundle has executable, bash -n clean setup.sh and run_autograder, and run_autograder writes results.json"
