#!/usr/bin/env bash
# The app in a real browser (./lab web's build): headless chromium (SwiftShader, no GPU) loads the page
# from a local server (python3's http.server), runs SCENE for exactly STEPS steps (?steps=N: then it
# pauses). The screenshot must show a scene (at least 2 % of the 3-D view not background,
# view_pixels.py) and the page's status (window.clothlab, mirrored as JSON into #clothlab-status):
# no console error, every step done, positions finite, the cloth moved (its centroid at least 1 cm
# from the scene's start), and the same centroid as the native run of the same scene and steps
# (clothlab run --steps N --dump) within TOL metres (default 1e-3 m = 1 mm). The screenshot is kept
# in TMP/page.png, the status in TMP/status.json.
#   browser_test.sh WEBDIR CLOTHLAB SCENES_DIR TMP SCENE STEPS [TOL]
# With PLANT (environment) set, a temp copy of the page is broken first: PLANT=console-error adds a
# console.error() to the page; PLANT=blank hides the canvas; PLANT=steps compares with the native run
# of STEPS + 1 steps (one step off). Then the script must fail with the check that PLANT names (the
# tests web.planted_*).
#   browser_test.sh --unknown-scene WEBDIR TMP: ?scene=no_such_scene shows the message, not a blank page.
# SETS (environment, e.g. "solver.kernel=batched"): KEY=VALUE settings, space-separated, for both runs
# (the page's ?set=KEY=VALUE, the native run's --set KEY=VALUE).
set -uo pipefail
fail() { echo "FAIL: $*" >&2; exit 1; }

unknown=0
[[ ${1:-} == --unknown-scene ]] && { unknown=1; shift; }
web=$1
if ((unknown)); then tmp=$2; else clothlab=$2 scenes=$3 tmp=$4 scene=$5 steps=$6 tol=${7:-1e-3}; fi
[[ -f $web/index.html && -f $web/clothlab.wasm ]] || fail "$web: no index.html and clothlab.wasm (build it: ./lab web --no-serve)"
command -v chromium >/dev/null || fail "chromium is not installed (./lab setup --web)"
rm -rf "$tmp" && mkdir -p "$tmp/site"
cp "$web"/index.html "$web"/clothlab.* "$tmp/site/"
if [[ ${PLANT:-} == console-error ]]; then
  sed -i 's|</body>|<script>console.error("planted console error")</script></body>|' "$tmp/site/index.html"
elif [[ ${PLANT:-} == blank ]]; then
  sed -i 's|</style>|canvas { visibility: hidden; }</style>|' "$tmp/site/index.html"
fi

# The page's own server on a free port.
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 -m http.server "$port" --bind 127.0.0.1 --directory "$tmp/site" >"$tmp/server.log" 2>&1 &
server=$!
trap 'kill $server 2>/dev/null' EXIT
for _ in $(seq 50); do python3 -c "import urllib.request; urllib.request.urlopen('http://127.0.0.1:$port/index.html')" 2>/dev/null && break; sleep 0.1; done

sets=() query=""
for kv in ${SETS:-}; do sets+=(--set "$kv"); query+="&set=$kv"; done
if ((unknown)); then url="http://127.0.0.1:$port/index.html?scene=no_such_scene"; else url="http://127.0.0.1:$port/index.html?scene=$scene&steps=$steps$query"; fi
# Real time, real frames: chromium driven over its DevTools pipe (page_run.py) until the page's status
# says done (or 5 s for the unknown scene), at most CLOTHLAB_WEB_SECONDS (default 120) s; a screenshot.
seconds=${CLOTHLAB_WEB_SECONDS:-120}
((unknown)) && seconds=5
timeout 300 python3 "$(dirname "$0")/page_run.py" "$url" --seconds "$seconds" --until-done --screenshot "$tmp/page.png" \
  >"$tmp/status.json" 2>"$tmp/page_run.log" || fail "page_run.py failed: $(tail -3 "$tmp/page_run.log")"
jq -e '.frames > 0' "$tmp/status.json" >/dev/null 2>&1 \
  || fail "the app did not start (no frame in window.clothlab): $(jq -c '.console_errors' "$tmp/status.json" 2>/dev/null | head -c 600)"
jq -e '.element_mirrors_status' "$tmp/status.json" >/dev/null || fail "#clothlab-status does not mirror window.clothlab"
# The screenshot: at least 2 % of the 3-D view (right of the panel) is not the background: a scene is drawn.
drawn=$(python3 "$(dirname "$0")/view_pixels.py" "$tmp/page.png" 0.3)
awk -v d="$drawn" 'BEGIN { exit !(d >= 0.02) }' || fail "screenshot: only $drawn of the view is not background ($tmp/page.png): a blank canvas"
errors=$(jq -r '.console_errors | length' "$tmp/status.json")
((errors == 0)) || fail "console error: $(jq -c '.console_errors' "$tmp/status.json" | head -c 600)"

if ((unknown)); then
  jq -e '.message | test("no scene \"no_such_scene\"")' "$tmp/status.json" >/dev/null \
    || fail "unknown scene: the status has no message naming it: $(jq -c .message "$tmp/status.json")"
  jq -e '.frames > 0 and (.app.runs | length) > 0' "$tmp/status.json" >/dev/null \
    || fail "unknown scene: no frame drawn, or no scene shown beside the message"
  echo "ok: ?scene=no_such_scene: $(jq -r .message "$tmp/status.json")"
  exit 0
fi

jq -e --argjson n "$steps" '.done and .step == $n' "$tmp/status.json" >/dev/null \
  || fail "steps: the page did not finish $steps steps: step $(jq .step "$tmp/status.json"), message $(jq -c .message "$tmp/status.json")"
jq -e '.finite and (.centroid | all(. != null))' "$tmp/status.json" >/dev/null || fail "finite: a position or velocity is not finite"

# The native run of the same scene: its start and its state after the same steps (CSV i,x,y,z,...).
native_steps=$steps
[[ ${PLANT:-} == steps ]] && native_steps=$((steps + 1))
"$clothlab" run "$scenes/$scene.json" "${sets[@]}" --steps 0 --dump "$tmp/start.csv" --quiet >/dev/null || fail "native run (0 steps) failed"
"$clothlab" run "$scenes/$scene.json" "${sets[@]}" --steps "$native_steps" --dump "$tmp/native.csv" --quiet >/dev/null || fail "native run failed"
centroid() { awk -F, 'NR > 1 && $1 ~ /^[0-9]+$/ { x += $2; y += $3; z += $4; n++ } END { printf "%.9f %.9f %.9f\n", x / n, y / n, z / n }' "$1"; }
read -r sx sy sz <<<"$(centroid "$tmp/start.csv")"
read -r nx ny nz <<<"$(centroid "$tmp/native.csv")"
read -r wx wy wz <<<"$(jq -r '.centroid | map(tostring) | join(" ")' "$tmp/status.json")"
moved=$(awk -v a="$wx $wy $wz" -v b="$sx $sy $sz" 'BEGIN { split(a, p, " "); split(b, q, " "); print sqrt((p[1]-q[1])^2 + (p[2]-q[2])^2 + (p[3]-q[3])^2) }')
diff=$(awk -v a="$wx $wy $wz" -v b="$nx $ny $nz" 'BEGIN { split(a, p, " "); split(b, q, " "); print sqrt((p[1]-q[1])^2 + (p[2]-q[2])^2 + (p[3]-q[3])^2) }')
awk -v m="$moved" 'BEGIN { exit !(m >= 0.01) }' || fail "moves: the centroid moved only $moved m in $steps steps"
awk -v d="$diff" -v t="$tol" 'BEGIN { exit !(d <= t) }' \
  || fail "matches native: the browser's centroid ($wx $wy $wz) is $diff m from the native run's ($nx $ny $nz) after $steps steps (tolerance $tol m)"
echo "ok: $scene${SETS:+ (${SETS})}, $steps steps in the browser: centroid moved $moved m, $diff m from the native run (tolerance $tol m), $(jq -r '.ms_per_frame | floor' "$tmp/status.json") ms per frame (SwiftShader, 10 steps per frame), no console error"
