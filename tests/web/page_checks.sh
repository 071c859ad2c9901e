#!/usr/bin/env bash
# What the native app does, in the browser (./lab web's build, headless chromium, one browser per test:
# page_run.py with several pages). Every failure names its scene or setting.
#   page_checks.sh scenes  WEBDIR CLOTHLAB SCENES_DIR TMP [SECONDS]
#     every scene of SCENES_DIR (or those of $SCENES, space-separated), playing as a user opens it
#     (?scene=NAME) for SECONDS (default 5) of wall time: it starts, has stepped, no message, no console
#     error, every position finite, the cloth moved (centroid at least 0.01 mm from the native run's
#     start, clothlab run --steps 0) and is where the native run of the same steps has it (within 1 cm),
#     a scene drawn (view_pixels.py).
#   page_checks.sh mouse   WEBDIR CLOTHLAB SCENES_DIR TMP
#     pbd_hanging paused (?steps=0), the mouse through the page's probe (page_run.py --mouse): the left
#     button drags the probe particle (at least 5 cm, held: inverse mass 0 while held, its mass back on
#     release), then a right click pins it (one pinned particle more); finite, drawn, no console error.
#   page_checks.sh sliders WEBDIR CLOTHLAB SCENES_DIR TMP
#     each slider of the panel's Parameters at both ends of its range, set with ?set=KEY=VALUE (as
#     ./lab gui --set), 20 steps: either every position finite after the 20 steps, or a message in the
#     status (the page's, or a run's: "unstable at step N ...", shown in the panel); never a blank
#     canvas, no console error.
#   page_checks.sh controls WEBDIR CLOTHLAB SCENES_DIR TMP
#     pbd_hanging playing 3 s, then the panel's buttons clicked where the page says it drew them and the
#     keys pressed (page_run.py --controls): Pause stops the steps, Step and the key S step once each,
#     space plays and pauses, Reset goes back to t = 0, the method combo switches to xpbd (which then
#     plays, finite), "Save PNG" and "Export CSV + PNG" download a PNG of the view and the comparison's CSV,
#     "+ compare" runs a copy side by side (two runs, each stepping, each labelled in its view) with the
#     comparison's plots below the views (drawn, no text cut, samples of both runs).
# With PLANT (environment) set the page or the run is broken first and the check that PLANT names must
# fail (tests web.planted_*): PLANT=still runs the scenes paused (?steps=0: "moves" fails); PLANT=no-pointer
# makes the canvas ignore the mouse (CSS pointer-events: none: "grab" and "pause" fail).
set -uo pipefail
fail() { echo "FAIL: $*" >&2; exit 1; }
mode=$1 web=$2 clothlab=$3 scenes=$4 tmp=$5 seconds=${6:-5}
here=$(cd "$(dirname "$0")" && pwd)
[[ -f $web/index.html && -f $web/clothlab.wasm ]] || fail "$web: no index.html and clothlab.wasm (build it: ./lab web --no-serve)"
command -v chromium >/dev/null || fail "chromium is not installed (./lab setup --web)"
rm -rf "$tmp" && mkdir -p "$tmp/site"
cp "$web"/index.html "$web"/clothlab.* "$tmp/site/"
[[ ${PLANT:-} == no-pointer ]] && sed -i 's|</style>|canvas { pointer-events: none; }</style>|' "$tmp/site/index.html"

# drawn PNG: the fraction of the 3-D view (right of the panel) that is not background
drawn_ok() { awk -v d="$(python3 "$here/view_pixels.py" "$1" 0.3)" 'BEGIN { exit !(d >= 0.02) }'; }
centroid() { awk -F, 'NR > 1 && $1 ~ /^[0-9]+$/ { x += $2; y += $3; z += $4; n++ } END { printf "%.9f %.9f %.9f\n", x / n, y / n, z / n }' "$1"; }
dist() { awk -v a="$1" -v b="$2" 'BEGIN { split(a, p, " "); split(b, q, " "); print sqrt((p[1]-q[1])^2 + (p[2]-q[2])^2 + (p[3]-q[3])^2) }'; }
# common NAME JSON PNG: started, mirrored, no console error, drawn
common() {
  local name=$1 st=$2 png=$3
  jq -e '.frames > 0' <<<"$st" >/dev/null 2>&1 || fail "$name: the app did not start (no frame): $(jq -c '.console_errors' <<<"$st" | head -c 400)"
  jq -e '.element_mirrors_status' <<<"$st" >/dev/null || fail "$name: #clothlab-status does not mirror window.clothlab"
  jq -e '.console_errors | length == 0' <<<"$st" >/dev/null || fail "$name: console error: $(jq -c '.console_errors' <<<"$st" | head -c 400)"
  drawn_ok "$png" || fail "$name: screenshot: a blank canvas ($png)"
}

case $mode in
scenes)
  names=(${SCENES:-$(cd "$scenes" && ls *.json | sed 's/\.json$//')})
  urls=()
  for n in "${names[@]}"; do
    u="index.html?scene=$n"
    [[ ${PLANT:-} == still ]] && u+="&steps=0"
    urls+=("$u")
  done
  timeout $((60 + ${#names[@]} * (seconds + 30))) python3 "$here/page_run.py" --serve "$tmp/site" --seconds "$seconds" \
    --screenshot "$tmp/page.png" "${urls[@]}" >"$tmp/status.jsonl" 2>"$tmp/page_run.log" || fail "page_run.py failed: $(tail -3 "$tmp/page_run.log")"
  i=0
  for n in "${names[@]}"; do
    st=$(sed -n "$((i + 1))p" "$tmp/status.jsonl")
    png=$tmp/page.png
    ((${#names[@]} > 1)) && png=$tmp/page-$i.png
    common "$n" "$st" "$png"
    jq -e '.message == ""' <<<"$st" >/dev/null || fail "$n: a message: $(jq -c .message <<<"$st")"
    jq -e '.finite and (.centroid | all(. != null))' <<<"$st" >/dev/null || fail "$n: finite: a position or velocity is not finite (step $(jq .step <<<"$st"))"
    step=$(jq .step <<<"$st")
    wc=$(jq -r '.centroid | map(tostring) | join(" ")' <<<"$st")
    "$clothlab" run "$scenes/$n.json" --steps 0 --dump "$tmp/$n.start.csv" --quiet >/dev/null || fail "$n: native run (0 steps) failed"
    moved=$(dist "$wc" "$(centroid "$tmp/$n.start.csv")")
    awk -v m="$moved" 'BEGIN { exit !(m >= 1e-5) }' \
      || fail "$n: moves: the centroid moved $moved m in $seconds s (step $step, t $(jq .t <<<"$st") s)"
    # the same steps natively (the page stepped a whole number of steps): the same centroid within 1 cm
    "$clothlab" run "$scenes/$n.json" --steps "$step" --dump "$tmp/$n.native.csv" --quiet >/dev/null || fail "$n: native run ($step steps) failed"
    diff=$(dist "$wc" "$(centroid "$tmp/$n.native.csv")")
    awk -v d="$diff" 'BEGIN { exit !(d <= 1e-2) }' \
      || fail "$n: matches native: the browser's centroid after $step steps is $diff m from the native run's (tolerance 0.01 m)"
    echo "ok: $n: step $step, t $(jq '.t * 1000 | round / 1000' <<<"$st") s after ${seconds} s, moved $moved m, $diff m from native, finite, drawn"
    i=$((i + 1))
  done
  ;;
mouse)
  timeout 300 python3 "$here/page_run.py" --serve "$tmp/site" --seconds 60 --until-done --mouse --screenshot "$tmp/page.png" \
    "index.html?scene=pbd_hanging&steps=0" >"$tmp/status.json" 2>"$tmp/page_run.log" || fail "page_run.py failed: $(tail -3 "$tmp/page_run.log")"
  st=$(cat "$tmp/status.json")
  common pbd_hanging "$st" "$tmp/page.png"
  jq -e '.mouse.before.probe.px | all(. != null)' <<<"$st" >/dev/null || fail "probe: no probe particle in the status: $(jq -c .mouse <<<"$st")"
  jq -e '.mouse.before.probe.pinned == false' <<<"$st" >/dev/null || fail "probe: the probe particle is pinned before the mouse: $(jq -c .mouse.before <<<"$st")"
  xyz() { jq -r ".mouse.$1.probe.x | map(tostring) | join(\" \")" <<<"$st"; }
  dragged=$(dist "$(xyz during)" "$(xyz before)")
  awk -v d="$dragged" 'BEGIN { exit !(d >= 0.05) }' && jq -e '.mouse.during.probe.pinned' <<<"$st" >/dev/null \
    || fail "grab: the left button dragged 120 px over the probe particle moved it $dragged m (held: $(jq .mouse.during.probe.pinned <<<"$st")): $(jq -c .mouse <<<"$st" | head -c 600)"
  jq -e '.mouse.after.probe.pinned == false' <<<"$st" >/dev/null || fail "grab: the particle stays held after the release: $(jq -c .mouse.after <<<"$st")"
  jq -e '.mouse.pin.probe.pinned and .mouse.pin.pinned == .mouse.before.pinned + 1' <<<"$st" >/dev/null \
    || fail "pin toggle: a right click on the particle did not pin it: before $(jq -c .mouse.before <<<"$st"), after $(jq -c .mouse.pin <<<"$st")"
  jq -e '.finite' <<<"$st" >/dev/null || fail "finite: not finite after the mouse"
  echo "ok: pbd_hanging: the left button dragged particle $(jq .mouse.before.probe.index <<<"$st") by $dragged m (held while dragged, released after), a right click pinned it ($(jq .mouse.before.pinned <<<"$st") -> $(jq .mouse.pin.pinned <<<"$st") pinned); finite, drawn"
  ;;
sliders)
  # scene<TAB>KEY=VALUE: the panel's sliders (framework/src/gui/app.cpp, App::panelParameters) at both ends
  sets=$(cat <<'LIST'
pbd_hanging	solver.dt=1e-5
pbd_hanging	solver.dt=0.05
pbd_hanging	solver.iterations=1
pbd_hanging	solver.iterations=100
pbd_hanging	solver.substeps=50
pbd_hanging	constraints.distance.stiffness=0
pbd_hanging	forces.air_damping=5
pbd_hanging	pbd.damping=1
pbd_hanging	forces.wind=[20,20,20]
pbd_hanging	forces.wind=[-20,-20,-20]
pbd_self_collision	self_collision.thickness=0.002
pbd_self_collision	self_collision.thickness=0.1
mfn_hanging	springs.structural.k=1
mfn_hanging	springs.structural.k=1e5
mfn_hanging	springs.bending.k=1e5
mfn_hanging	provot.max_strain=0.001
mfn_hanging	solver.dt=0.05
spring	spring.k=1e4
spring	spring.kd=10
chain	chain.k=1e5
chain	chain.kd=10
LIST
)
  names=() urls=()
  while IFS=$'\t' read -r scene set; do
    names+=("$scene $set")
    urls+=("index.html?scene=$scene&steps=20&set=$(python3 -c 'import sys, urllib.parse; print(urllib.parse.quote(sys.argv[1], safe="=."))' "$set")")
  done <<<"$sets"
  timeout $((60 + ${#urls[@]} * 60)) python3 "$here/page_run.py" --serve "$tmp/site" --seconds 40 --until-done \
    --screenshot "$tmp/page.png" "${urls[@]}" >"$tmp/status.jsonl" 2>"$tmp/page_run.log" || fail "page_run.py failed: $(tail -3 "$tmp/page_run.log")"
  i=0
  for n in "${names[@]}"; do
    st=$(sed -n "$((i + 1))p" "$tmp/status.jsonl")
    common "$n" "$st" "$tmp/page-$i.png"
    # the page's message, or a run's (a run stopped as unstable says so in the panel's Runs)
    msg=$(jq -r '[.message, ((.app.runs // [])[] | .message)] | map(select(. != null and . != "")) | first // ""' <<<"$st")
    if [[ -n $msg ]]; then
      echo "ok: $n: a message: ${msg:0:160}"
    else
      jq -e '.done and .finite and (.centroid | all(. != null))' <<<"$st" >/dev/null \
        || fail "$n: neither a message nor finite after 20 steps: step $(jq .step <<<"$st"), finite $(jq .finite <<<"$st")"
      echo "ok: $n: 20 steps, finite$(jq -r 'if (.warnings | length) > 0 then ", warnings: " + (.warnings | join("; ")) else "" end' <<<"$st" | head -c 160)"
    fi
    i=$((i + 1))
  done
  ;;
controls)
  mkdir -p "$tmp/downloads"
  timeout 300 python3 "$here/page_run.py" --serve "$tmp/site" --seconds 3 --controls --downloads "$tmp/downloads" \
    --screenshot "$tmp/page.png" "index.html?scene=pbd_hanging" >"$tmp/status.json" 2>"$tmp/page_run.log" || fail "page_run.py failed: $(tail -3 "$tmp/page_run.log")"
  st=$(cat "$tmp/status.json")
  common pbd_hanging "$st" "$tmp/page.png"
  c() { jq -c ".controls.$1" <<<"$st"; }
  is() { jq -e ".controls | $1" <<<"$st" >/dev/null; }
  is '.playing.playing and .playing.step > 0' || fail "play: the scene does not play on opening: $(c playing)"
  is '.paused.playing == false and .paused_later.step == .paused.step' \
    || fail "pause: the Pause button did not stop the steps: after the click $(c paused), a second later $(c paused_later)"
  is '.stepped.step == .paused_later.step + 1 and .stepped.playing == false' || fail "step: the Step button did not make exactly one step: $(c paused_later) -> $(c stepped)"
  is '.key_s.step == .stepped.step + 1' || fail "key S: not one step: $(c stepped) -> $(c key_s)"
  is '.key_space.playing and .key_space.step > .key_s.step and .key_space_again.playing == false' \
    || fail "key space: play then pause: $(c key_s) -> $(c key_space) -> $(c key_space_again)"
  is '.reset.t == 0 and .reset.step == 0 and .reset.message == ""' || fail "reset: not back at t = 0: $(c reset)"
  is '.missing | length == 0' || fail "controls: the panel drew no $(jq -r '.controls.missing | join(", ")' <<<"$st") (status app.controls: $(jq -c '.app.controls | keys' <<<"$st"))"
  is '.method.method == "xpbd" and .method_plays.method == "xpbd" and .method_plays.playing and .method_plays.step > .method.step and .method_plays.finite' \
    || fail "method: the combo's xpbd did not switch the run or it does not play finite: $(c method) -> $(c method_plays)"
  for f in clothlab_view_1.png clothlab_compare_1_compare.csv; do
    is ".downloads | index(\"$f\") != null" || fail "download: the page did not offer $f (offered: $(c downloads))"
    [[ -s $tmp/downloads/$f ]] || fail "download: chromium saved no $f in $tmp/downloads (saved: $(c saved))"
  done
  [[ $(head -c 8 "$tmp/downloads/clothlab_view_1.png" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]] \
    || fail "save png: clothlab_view_1.png is not a PNG file"
  drawn_ok "$tmp/downloads/clothlab_view_1.png" || fail "save png: the saved view is blank"
  csv=$tmp/downloads/clothlab_compare_1_compare.csv
  head -1 "$csv" | grep -q 'method' && grep -q 'xpbd' "$csv" || fail "export: $csv has no header with method or no row of xpbd: $(head -3 "$csv")"
  jq -e '.app.platform_note | test("one thread")' <<<"$st" >/dev/null || fail "threads: the panel does not say the page runs on one thread: $(jq -c .app.platform_note <<<"$st")"
  is '.side_by_side.runs | length == 2 and all(.steps > 0 and (.label // "") != "")' \
    || fail "side by side: \"+ compare\" did not give two labelled runs that step: $(c side_by_side)"
  jq -e '.app.compare and .app.plots.rect[2] > 100 and .app.plots.rect[3] > 100 and (.app.plots.cut_text | length == 0) and all(.app.runs[]; .samples > 1)' <<<"$st" >/dev/null \
    || fail "plots: side by side, the plots window is not drawn whole with the runs' samples: $(jq -c '{plots: .app.plots, samples: [.app.runs[].samples]}' <<<"$st")"
  echo "ok: pbd_hanging: Pause held step $(jq .controls.paused.step <<<"$st") for 1 s, Step and S one step each, space played and paused, Reset to t = 0, the method combo switched to xpbd (plays, finite), downloaded clothlab_view_1.png and $(($(wc -l <"$csv") - 1)) rows of compare.csv, \"+ compare\" ran two labelled runs ($(jq -c '[.controls.side_by_side.runs[].label]' <<<"$st")) with their plots"
  ;;
*) fail "page_checks.sh: unknown mode $mode (scenes, mouse, sliders or controls)" ;;
esac
