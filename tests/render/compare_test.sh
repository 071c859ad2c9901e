#!/usr/bin/env bash
# Methods side by side, offscreen: `gui SCENE --compare a,b --screenshot F --status F.json` draws each run
# in its own view with its label (checked from the pixels and from the app's status JSON: render_test
# --check-compare-screenshot), at the default size and at 1024x768, with no text cut off; each check is
# shown to fail on a planted case (a view with no cloth, a label where it is not drawn, a wrong label,
# a window too small for the plots' labels). Usage: compare_test.sh RENDER_EXE RENDER_TEST SOURCE_DIR TMP
set -u
exe=$1; check=$2; root=$3; tmp=$4
rm -rf "$tmp"; mkdir -p "$tmp"
fail=0
bad() { echo "FAIL: $*"; fail=1; }

shot() {  # shot NAME ARGS...: the app offscreen, its picture and status in $tmp/NAME.{png,json}
  local name=$1; shift
  "$exe" gui "$@" --screenshot "$tmp/$name.png" --status "$tmp/$name.json" >"$tmp/$name.out" 2>&1 \
    || bad "$name: gui failed: $(tail -3 "$tmp/$name.out")"
}
shot two "$root/scenes/pbd_sphere.json" --compare pbd:iterations=3,pbd:iterations=30 --frames 40
"$check" --check-compare-screenshot "$tmp/two.png" "$tmp/two.json" || bad "two runs at 1280x800"
shot small "$root/scenes/pbd_hanging.json" --compare pbd,xpbd,pbd:substeps=4 --frames 30 --size 1024x768
"$check" --check-compare-screenshot "$tmp/small.png" "$tmp/small.json" || bad "three runs at 1024x768"
shot four "$root/scenes/spring.json" --compare explicit_euler,symplectic_euler,velocity_verlet,implicit_euler --frames 30 --size 1024x768
[[ $(jq '.runs | length' "$tmp/four.json") == 4 ]] || bad "four runs: $(jq -c '.runs | length' "$tmp/four.json")"
[[ $(jq -r '.measure.name' "$tmp/four.json") == error ]] || bad "the spring's measure is its analytic error: $(jq -c .measure "$tmp/four.json")"

# Planted: the checker fails when a run is not drawn where the status says, or its label is not there.
jq '.runs[1].viewport = [360, 600, 300, 150] | .runs[1].label_box = [368, 608, 100, 30]' "$tmp/two.json" >"$tmp/noview.json"
"$check" --check-compare-screenshot "$tmp/two.png" "$tmp/noview.json" >/dev/null 2>&1 && bad "planted: a view without cloth passed"
jq '.runs[0].label_box = (.runs[0].viewport | [.[0] + .[2] - 120, .[1] + .[3] - 60, 100, 40])' "$tmp/two.json" >"$tmp/nolabel.json"
"$check" --check-compare-screenshot "$tmp/two.png" "$tmp/nolabel.json" >/dev/null 2>&1 && bad "planted: a label box with no label drawn passed"
jq '.runs[0].label_text = "another"' "$tmp/two.json" >"$tmp/wronglabel.json"
"$check" --check-compare-screenshot "$tmp/two.png" "$tmp/wronglabel.json" >/dev/null 2>&1 && bad "planted: a wrong label passed"
# Planted: in a window too small for them the plots' labels are cut off, and the status says so.
shot cut "$root/scenes/pbd_sphere.json" --compare pbd,xpbd --frames 5 --size 700x500
[[ $(jq '.plots.cut_text | length' "$tmp/cut.json") -gt 0 ]] || bad "planted: at 700x500 no cut text was seen in the plots"
"$check" --check-compare-screenshot "$tmp/cut.png" "$tmp/cut.json" >/dev/null 2>&1 && bad "planted: the checker passed cut text"

# Bad input: one error line.
"$exe" gui "$root/scenes/pbd_sphere.json" --compare pbd --screenshot "$tmp/x.png" >"$tmp/out" 2>"$tmp/err"; code=$?
[[ $code -ne 0 && $code -lt 128 && $(grep -c '^error: ' "$tmp/err") -eq 1 ]] && grep -q "error: command line: --compare: expected 2 to 4 runs" "$tmp/err" \
  || bad "--compare pbd: want one error line, got ($code): $(cat "$tmp/err")"
[[ $fail -eq 0 ]] && echo "ok: runs side by side drawn and labelled (1280x800, 1024x768), no text cut off; each check fails when planted"
exit $fail
