#!/usr/bin/env bash
# The write-up (Ausarbeitung) of one stage as ONE self-contained HTML file: the stage's figures, made
# by running the stage's commands through this copy's build (your code in exercises/, as ./lab run
# uses it), each with the command under it; the numbers of exercises/NN_name/answers.json as a table;
# and exercises/NN_name/writeup.md rendered by pandoc. Figures are PNG data: URIs, so the file stands
# alone. `./lab report NN [--out DIR]` calls it (docs/student_copy.md "The write-up").
#
#   tools/report.sh [--check] [--root DIR] [--build DIR] NN [--out DIR]
#     --check   only validate the input (stage, answers.json, writeup.md) and exit
#     --root    the tree with exercises/ and scenes/ (default: this script's tree)
#     --build   the build whose bin/clothlab runs the figures (default: ROOT/build)
# Bad input: one line `error: FILE: FIELD: ...` and exit 1. A figure command that fails (e.g. a task
# not done: `not implemented`) puts its message into the report in place of the figure, with a warning.
set -uo pipefail
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)  # tools/: answers.jq beside this script
ROOT=$(dirname "$HERE")
BUILD="" check=0 stage="" out="" usage="usage: ./lab report NN [--out DIR]"
die() { printf 'error: %s\n' "$*" >&2; exit 1; }
say() { printf '==> %s\n' "$*" >&2; }
while (($#)); do
  case $1 in
    --check) check=1; shift ;;
    --root|--build|--out)
      (($# >= 2)) || die "report: $1 needs a folder ($usage)"
      case $1 in --root) ROOT=$2 ;; --build) BUILD=$2 ;; --out) out=$2 ;; esac; shift 2 ;;
    -*) die "report: unknown option $1 ($usage)" ;;
    *) [[ -z $stage ]] || die "report: one stage at a time ($usage)"; stage=$1; shift ;;
  esac
done
[[ -n $stage ]] || die "report: which stage? ($usage)"
BUILD=${BUILD:-$ROOT/build}
[[ -d $BUILD ]] && BUILD=$(cd "$BUILD" && pwd)  # the figures run in ROOT
stages=$(cd "$ROOT/exercises" 2>/dev/null && ls -d [0-9][0-9]_* 2>/dev/null | cut -c1-2 | paste -sd ' ')
[[ $stage =~ ^[0-9]{1,2}$ ]] || die "report: '$stage' is not a stage number (the stages: ${stages:-none})"
nn=$(printf '%02d' $((10#$stage)))
name=$(cd "$ROOT/exercises" 2>/dev/null && compgen -G "${nn}_*" | head -1) || name=""
[[ -n $name ]] || die "exercises/${nn}_*: (folder): there is no stage $nn (the stages: ${stages:-none})"
ex="exercises/$name"

# ---- the input: answers.json, in any of its formats (tools/answers.jq)
answers="$ROOT/$ex/answers.json"
[[ -f $answers ]] || die "$ex/answers.json: (file): not found; the report shows your experiment numbers from it"
command -v jq >/dev/null || die "report: jq is not installed (apt-get install jq)"
msg=$(jq empty "$answers" 2>&1) || die "$ex/answers.json: (JSON): not valid JSON: $(printf '%s' "$msg" | head -1 | sed 's/^jq: error[^:]*: //')"
problem=$(jq -r -L "$HERE" 'include "answers"; problems' "$answers" | head -1) || die "$HERE/answers.jq: (file): jq cannot use it"
[[ -z $problem ]] || die "$ex/answers.json: $problem"
writeup="$ROOT/$ex/writeup.md"
[[ -f $writeup ]] || die "$ex/writeup.md: (file): not found; it holds your answers to the sheet's questions (the template: git checkout $ex/writeup.md)"
((check)) && exit 0
# (./lab report installs pandoc through ./lab setup first, as root; this says what is missing otherwise)
for t in pandoc gnuplot base64 perl; do
  command -v $t >/dev/null || die "report: $t is not installed; the report needs it$([[ $t == pandoc ]] && echo " to render writeup.md (Markdown) to HTML"): sudo apt-get install $t"
done

# ---- the build: whose code makes the figures
clothlab="$BUILD/bin/clothlab"
[[ -x $clothlab ]] || die "$clothlab: (file): not built (./lab build)"
code=$(sed -n 's/^CLOTHLAB_CODE:STRING=//p' "$BUILD/CMakeCache.txt" 2>/dev/null)
refs=$(sed -n 's/^CLOTHLAB_REFERENCE_STAGES:STRING=//p' "$BUILD/CMakeCache.txt" 2>/dev/null | tr ';' ',')
if [[ $code == solutions ]]; then
  made_by="solutions/ (the reference: this is the instructor's tree)"
else
  [[ ,$refs, == *,$nn,* || ,$refs, == *,all,* ]] \
    && die "report: this build takes stage $nn from the reference (./lab build --reference $refs); the figures must come from your code: ./lab build (without $nn) first"
  made_by="your code in exercises/${refs:+, the reference for stage $refs (./lab build --reference $refs)}"
fi

out=${out:-$ROOT/out/report}
mkdir -p "$out" || die "$out: (folder): cannot create it"
html="$out/$name.html"
work=$(mktemp -d "${TMPDIR:-/tmp}/clothlab-report.XXXXXX") || die "report: cannot make a temporary folder"
trap 'rm -rf "$work"' EXIT
esc() { sed -e 's/&/\&amp;/g' -e 's/</\&lt;/g' -e 's/>/\&gt;/g'; }
figs="$work/figures.html" nfig=0 nfail=0 nwarn=0 fail=""
: >"$figs"

# run SHOWN ARGS...: one command of a figure through this build (cwd: the tree, as ./lab runs it);
# SHOWN is how the student types it. Its output goes to $work/last.log; it is listed under the figure.
# A run that warned (its summary's "warning:" lines: a pinned particle moved, not converged, ...) is no
# result: its warnings are repeated beside the figure and on the terminal.
shown=() warned=()
run() {
  local s=$1 w; shift
  shown+=("$s")
  say "report $nn: $s"
  (cd "$ROOT" && "$clothlab" "$@") >"$work/last.log" 2>&1 && {
    while IFS= read -r w; do warned+=("$s: ${w#"${w%%[! ]*}"}"); done < <(grep -E '^ *warning: ' "$work/last.log")
    return 0
  }
  fail="$s: $(grep -m1 '^error' "$work/last.log" || tail -1 "$work/last.log")"
  return 1
}
# figure TITLE PNG [EXCERPT_FILE]: the PNG as a data: URI with the commands that made it (or why not).
figure() {
  local title=$1 png=$2 ex=${3:-}
  nfig=$((nfig + 1))
  { printf '<figure>\n<h3>Figure %d. %s</h3>\n' "$nfig" "$(printf '%s' "$title" | esc)"
    if [[ -z ${fail:-} && -s $png ]]; then
      printf '<img alt="%s" src="data:image/png;base64,' "$(printf '%s' "$title" | esc)"; base64 -w0 "$png"; printf '">\n'
    else
      printf '<p class="fail">No figure: %s</p>\n' "$(printf '%s' "${fail:-the plot was not written}" | esc)"
    fi
    if ((${#warned[@]})); then
      printf '<p class="fail">Warning: a run of this figure warned, so its numbers are no result (fix what the warning names, then run ./lab report %s again):</p><pre class="fail">' "$nn"
      printf '%s\n' "${warned[@]}" | esc; printf '</pre>\n'
    fi
    printf '<figcaption>made by:<pre>'; printf '%s\n' "${shown[@]}" | esc; printf '</pre>'
    [[ -n $ex && -s $ex ]] && { printf 'its output:<pre>'; esc <"$ex"; printf '</pre>'; }
    printf '</figcaption>\n</figure>\n'; } >>"$figs"
  [[ -z ${fail:-} && -s $png ]] || { nfail=$((nfail + 1)); say "warning: report $nn: figure $nfig ($title): ${fail:-no plot}"; }
  local w
  for w in "${warned[@]}"; do say "warning: report $nn: figure $nfig ($title): a run warned, its numbers are no result: $w"; nwarn=$((nwarn + 1)); done
  shown=() fail="" warned=()
}
# window DIR METRIC STAT: the metric's min, mean or max over the run's --window (summary.json).
window() { jq -r ".window.metrics.$2.$3 // empty" "$1/summary.json" 2>/dev/null; }
# over_time PNG TITLE METRIC KEY "V1 V2 ..." SHOWN ARGS...: the experiment's runs, one per value V of the
# scene field KEY (--set KEY=V, --every 1; SHOWN and ARGS: the rest of the command as typed and as run),
# METRIC [unit] of each against time in one plot.
over_time() {
  local png=$1 title=$2 metric=$3 key=$4 values=$5 shown=$6 v; shift 6
  local -a curves=()
  for v in $values; do
    run "./lab run $shown --set $key=$v --every 1 --out DIR" run "$@" --set "$key=$v" --every 1 --quiet --out "$w/o$v" \
      && series "$w/o$v/report.csv" "t [s]" "$metric" >"$w/o$v.dat"
    curves+=("$w/o$v.dat:$key = $v")
  done
  plot "$png" "$title (report.csv of each run)" "t [s]" "$metric" "" "${curves[@]}"
}
# series CSV XNAME YNAME [SCALE OFFSET] > DAT: two columns of a report.csv, by header name (y*SCALE+OFFSET).
series() {
  awk -F, -v xn="$2" -v yn="$3" -v s="${4:-1}" -v o="${5:-0}" \
    'NR == 1 { for (i = 1; i <= NF; i++) { if ($i == xn) x = i; if ($i == yn) y = i }; next }
     x && y { print $x, $y * s + o }' "$1"
}
metric() { jq -r ".metrics.$2.value // empty" "$1/summary.json" 2>/dev/null; }
# plot PNG TITLE XLABEL YLABEL LOG DAT:LEGEND... (LOG: "", x, y or xy); lines with points for sweeps.
plot() {
  local png=$1 title=$2 xl=$3 yl=$4 log=$5 s sep="" style="lines lw 2"; shift 5
  for s in "$@"; do [[ -s ${s%%:*} ]] || fail=${fail:-"no data for \"${s#*:}\" (a run it needs failed)"}; done
  [[ $# -gt 0 && -s ${1%%:*} ]] && (($(wc -l <"${1%%:*}") < 20)) && style="linespoints lw 2 pt 7"
  { echo "set terminal pngcairo size 760,440 font ',10'"; echo "set output '$png'"
    echo "set title \"$title\" noenhanced"; echo "set xlabel \"$xl\" noenhanced"; echo "set ylabel \"$yl\" noenhanced"
    echo "set grid; set key outside right top noenhanced"
    [[ -n $log ]] && echo "set logscale $log"
    printf 'plot '
    for s in "$@"; do printf '%s"%s" using 1:2 with %s title "%s"' "$sep" "${s%%:*}" "$style" "${s#*:}"; sep=", "; done
    echo; } >"$png.gp"
  [[ -n ${fail:-} ]] || gnuplot "$png.gp" >"$png.log" 2>&1 || fail="gnuplot: $(head -1 "$png.log")"
}

# ---- the figures of each stage (what the sheet's experiments and questions are about)
w=$work
say "report $nn: the figures, made by $made_by"
case $nn in
  01)
    over_time "$w/drift.png" "Energy drift E - E(0) of the spring with explicit Euler" "energy_drift [J]" solver.dt "0.001 0.0005" \
      "scenes/spring.json --set solver.method=explicit_euler --seconds 1" scenes/spring.json --set solver.method=explicit_euler --seconds 1
    figure "The experiment: explicit Euler's energy drift at two time steps" "$w/drift.png"
    set -- ; for m in explicit_euler symplectic_euler velocity_verlet; do
      run "./lab run scenes/spring.json --set solver.method=$m --every 10 --out DIR" \
        run scenes/spring.json --set solver.method=$m --every 10 --quiet --out "$w/$m" && series "$w/$m/report.csv" "t [s]" "energy [J]" >"$w/$m.dat"
      set -- "$@" "$w/$m.dat:$m"
    done
    plot "$w/energy.png" "Energy of the single spring per integrator (report.csv of each run)" "t [s]" "energy [J]" "" "$@"
    figure "Energy against time: which integrator gains energy" "$w/energy.png"
    run "./lab study precision scenes/spring.json --methods symplectic_euler,velocity_verlet" \
      study precision scenes/spring.json --methods symplectic_euler,velocity_verlet --out "$w/p" \
      && sed -n '/^measured order/,/^wrote/p' "$w/last.log" | grep -v '^wrote' >"$w/p.txt"
    figure "Convergence: error at T = 1 s against the time step" "$w/p/convergence.png" "$w/p.txt" ;;
  02)
    run "./lab study stability scenes/mfn_hanging.json --methods symplectic_euler" \
      study stability scenes/mfn_hanging.json --methods symplectic_euler --out "$w/s" \
      && grep 'critical dt' "$w/last.log" >"$w/s.txt"
    figure "Stability map of the hanging cloth (symplectic Euler): stiffness against time step" "$w/s/stability_symplectic_euler.png" "$w/s.txt" ;;
  03)
    over_time "$w/fall.png" "Energy drift E - E(0) of the curtain falling freely (no pins)" "energy_drift [J]" solver.dt "0.01 0.005" \
      "scenes/pbd_curtain.json --set 'cloth.pins=[]' --seconds 1" scenes/pbd_curtain.json --set 'cloth.pins=[]' --seconds 1
    figure "The experiment: the free fall's energy drift at two time steps" "$w/fall.png"
    : >"$w/itmin.dat"; : >"$w/itmean.dat"; : >"$w/itmax.dat"
    for i in 1 2 5 10 20 50; do
      run "./lab run scenes/pbd_curtain.json --set solver.iterations=$i --window 2,3 --quiet --out DIR" \
        run scenes/pbd_curtain.json --set solver.iterations=$i --window 2,3 --quiet --out "$w/c$i" || break
      for st in min mean max; do echo "$i $(window "$w/c$i" max_strain $st)" >>"$w/it$st.dat"; done
    done
    plot "$w/strain.png" "Curtain max_strain over t in [2 s, 3 s] against the solver iterations (summary.json of each run)" "solver iterations" "max_strain [1]" xy \
      "$w/itmean.dat:mean over the window" "$w/itmin.dat:min" "$w/itmax.dat:max"
    figure "Strain against iterations (the curtain sways: its strain over a window of time)" "$w/strain.png"
    run "./lab study sag scenes/pbd_curtain.json --iterations 1,2,5,10,20,50 --xpbd-substeps 1" \
      study sag scenes/pbd_curtain.json --iterations 1,2,5,10,20,50 --xpbd-substeps 1 --out "$w/sag" \
      && sed -n '/^static sag/,/^wrote/p' "$w/last.log" | grep -v '^wrote' >"$w/sag.txt"
    figure "Static sag against iterations, PBD against XPBD" "$w/sag/sag.png" "$w/sag.txt" ;;
  04)
    over_time "$w/link.png" "Strain of the link of pbd_link" "max_strain [1]" solver.dt "0.01 0.005" \
      "scenes/pbd_link.json --seconds 1" scenes/pbd_link.json --seconds 1
    figure "The experiment: the hanging link's strain at two time steps" "$w/link.png"
    : >"$w/kmin.dat"; : >"$w/kmean.dat"; : >"$w/kmax.dat"
    for k in 0.5 0.7 0.8 0.9 0.95 0.98 1; do
      run "./lab run scenes/pbd_curtain.json --set constraints.distance.stiffness=$k --window 2,3 --quiet --out DIR" \
        run scenes/pbd_curtain.json --set constraints.distance.stiffness=$k --window 2,3 --every 5 --quiet --out "$w/k$k" || break
      for st in min mean max; do echo "$k $(window "$w/k$k" max_strain $st)" >>"$w/k$st.dat"; done
    done
    plot "$w/k.png" "Curtain max_strain over t in [2 s, 3 s] against the stiffness k (summary.json of each run)" "stiffness k [1]" "max_strain [1]" y \
      "$w/kmean.dat:mean over the window" "$w/kmin.dat:min" "$w/kmax.dat:max"
    first=$fail; figure "Curtain strain against the stiffness of the distance constraint (over a window of time)" "$w/k.png"
    shown=("the runs of figure 2 at k = 1 and k = 0.9 (--every 5), their report.csv") fail=$first
    series "$w/k1/report.csv" "t [s]" "max_strain [1]" >"$w/t1.dat" 2>/dev/null; series "$w/k0.9/report.csv" "t [s]" "max_strain [1]" >"$w/t09.dat" 2>/dev/null
    plot "$w/kt.png" "Curtain max_strain against time: it swings" "t [s]" "max_strain [1]" "" "$w/t1.dat:k = 1" "$w/t09.dat:k = 0.9"
    figure "Curtain strain against time at k = 1 and k = 0.9" "$w/kt.png" ;;
  05)
    over_time "$w/hinge.png" "Bending error of the hinge of pbd_hinge" "rms_bending_error [rad]" constraints.bending.stiffness "0.1 0.5" \
      "scenes/pbd_hinge.json" scenes/pbd_hinge.json
    figure "The experiment: the hinge's bending error at two bending stiffnesses" "$w/hinge.png"
    set -- ; for k in 0.01 1; do
      : >"$w/b$k.dat"
      for i in 5 10 50; do
        run "./lab run scenes/pbd_flag.json --set constraints.bending.stiffness=$k --set solver.iterations=$i --window 4,5 --quiet --out DIR" \
          run scenes/pbd_flag.json --set constraints.bending.stiffness=$k --set solver.iterations=$i --window 4,5 --quiet --out "$w/b$k-$i" || break
        echo "$i $(window "$w/b$k-$i" rms_bending_error mean)" >>"$w/b$k.dat"
      done
      set -- "$@" "$w/b$k.dat:bending stiffness $k"
    done
    plot "$w/b.png" "The flag in the wind: rms_bending_error, mean over t in [4 s, 5 s], against the iterations (summary.json)" "solver iterations" "rms_bending_error [rad]" x "$@"
    figure "Bending error of the flag against the iterations, at bending stiffness 0.01 and 1" "$w/b.png" ;;
  06)
    # E/(m g) - h: the height the cloth would reach at rest (m = 0.1 kg, g = 9.81 m/s², h = 0.01 m, as on the sheet)
    run "./lab run scenes/pbd_bounce.json --every 1 --out DIR" run scenes/pbd_bounce.json --every 1 --quiet --out "$w/r" \
      && series "$w/r/report.csv" "t [s]" "energy [J]" "$(awk 'BEGIN { print 1 / (0.1 * 9.81) }')" -0.01 >"$w/h.dat"
    plot "$w/h.png" "Height E/(m g) - h above the contact level (m = 0.1 kg, g = 9.81 m/s^2, h = 0.01 m)" "t [s]" "height [m]" "" "$w/h.dat:E/(m g) - h"
    figure "Rebound: the height the energy reaches, against time" "$w/h.png" ;;
  07)
    run "./lab run scenes/pbd_layers.json --every 1 --out DIR" run scenes/pbd_layers.json --every 1 --quiet --out "$w/layers" \
      && series "$w/layers/report.csv" "t [s]" "min_pair_distance [m]" >"$w/layers.dat" \
      && { echo "particle 0 at the end (out/layers/state.csv, line 2: i,x,y,z,vx,vy,vz):"; sed -n 2p "$w/layers/state.csv"; } >"$w/layers.txt"
    plot "$w/l.png" "The small layer on the pinned one: closest pair of particles of pbd_layers" "t [s]" "min_pair_distance [m]" "" "$w/layers.dat:min_pair_distance"
    figure "The experiment: the small layer comes to rest on the pinned one" "$w/l.png" "$w/layers.txt"
    run "./lab run scenes/pbd_self_collision.json --every 5 --out DIR" run scenes/pbd_self_collision.json --every 5 --quiet --out "$w/on" \
      && series "$w/on/report.csv" "t [s]" "min_pair_distance [m]" >"$w/on.dat"
    plot "$w/d.png" "Folded cloth: closest pair of particles (at least h apart at rest)" "t [s]" "min_pair_distance [m]" "" "$w/on.dat:min_pair_distance"
    figure "Layer distance of the folded cloth against time" "$w/d.png"
    # The last frame with and without self-collision, where this build has an offscreen renderer (./lab render).
    for exe in "$BUILD/bin/clothlab-render" "$BUILD/bin/clothlab-render-egl"; do
      [[ -x $exe ]] && "$exe" probe >/dev/null 2>&1 && break; exe=""
    done
    if [[ -n $exe ]]; then
      clothlab=$exe
      for sc in true false; do
        run "./lab render scenes/pbd_self_collision.json --set self_collision.enabled=$sc --fps 1 --size 480x360 --out DIR" \
          render scenes/pbd_self_collision.json --set self_collision.enabled=$sc --fps 1 --size 480x360 --quiet --out "$w/r$sc" || break
        last=$(ls "$w/r$sc"/frame_*.png 2>/dev/null | tail -1); [[ -n $last ]] && cp "$last" "$w/frame_$sc.png"
        figure "The folded cloth at the end, self_collision.enabled = $sc" "$w/frame_$sc.png"
      done
    else
      say "report $nn: no offscreen renderer in this build: no pictures of the folded cloth (./lab render once builds it; then ./lab report $nn again)"
    fi ;;
  *) say "report $nn: no figures are defined for this stage (tools/report.sh)" ;;
esac

# ---- the answers table: every field, with whatever keys it has
say "report $nn: the answers ($ex/answers.json) and the write-up ($ex/writeup.md)"
table=$(jq -r -L "$HERE" 'include "answers"; html' "$answers") || die "$ex/answers.json: (JSON): cannot read it"
unset_n=$(jq -L "$HERE" 'include "answers"; [fields | to_entries[] | select((.key | IN(nums[])) and .value == null)] | length' "$answers") \
  || die "$HERE/answers.jq: (file): jq cannot count the numbers not entered"
((unset_n == 0)) || say "note: $ex/answers.json: $unset_n numbers not entered yet (null)"

# ---- the write-up: comments out, Markdown without raw HTML (nothing active in the file), formulas as MathML
# (its title line goes: the report's own title says it; its headings move one level down, under "3. Write-up")
perl -0pe 's/<!--.*?-->//gs; s/\A\s*# [^\n]*\n//' "$writeup" >"$work/writeup.md"
empty=$(awk '/^#+ / { if (h != "" && !body) print h; h = $0; body = 0; next }
             /[^[:space:]]/ { body = 1 } END { if (h != "" && !body) print h }' "$work/writeup.md" \
        | grep -v -E '^(# |## Questions to think about$)' | sed 's/^#* //' | cut -c1-60 | awk '{ printf "%s%s", (NR > 1 ? "; " : ""), $0 }')
[[ -z $empty ]] || say "note: $ex/writeup.md: no answer yet under: $empty"
body=$(pandoc -f markdown-raw_html -t html --wrap=none --mathml --shift-heading-level-by=1 "$work/writeup.md" 2>"$work/pandoc.log") \
  || die "$ex/writeup.md: (Markdown): pandoc cannot render it: $(head -1 "$work/pandoc.log")"

title=$(head -1 "$ROOT/$ex/README.md" | sed 's/^# *//')
commit=$(git -C "$ROOT" log -1 --format='commit %h of %cd' --date=short 2>/dev/null) || commit=""
dirty=$(git -C "$ROOT" status --porcelain -- exercises 2>/dev/null | wc -l)
{ cat <<HTML
<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>Write-up: $(printf '%s' "$title" | esc)</title>
<style>
body { font-family: sans-serif; max-width: 60em; margin: 2em auto; padding: 0 1em; line-height: 1.45; color: #222 }
figure { margin: 1.5em 0; border-top: 1px solid #ccc } figure img { max-width: 100% }
figcaption pre, pre { background: #f4f4f4; padding: .5em; overflow-x: auto; font-size: 90% }
table { border-collapse: collapse } th, td { border: 1px solid #bbb; padding: .3em .6em; vertical-align: top; text-align: left }
td.num { text-align: right; font-family: monospace } .missing, .fail { color: #b00 } .meta { color: #666; font-size: 90% }
</style></head><body>
<h1>Write-up (<em>Ausarbeitung</em>): $(printf '%s' "$title" | esc)</h1>
<p class="meta">Made by <code>./lab report $nn</code> on $(date '+%Y-%m-%d %H:%M')$([[ -n $commit ]] && printf ', %s' "$commit")$( ((dirty)) && printf ' (with %d uncommitted changes in exercises/)' "$dirty"). Figures made by $(printf '%s' "$made_by" | esc). Rubric: docs/rubric.md, &ldquo;Stage $nn&rdquo;.</p>
<h2>1. Figures</h2>
HTML
  cat "$figs"
  printf '<h2>2. Experiments (%s)</h2>\n%s\n' "$ex/answers.json" "$table"
  printf '<h2>3. Write-up (%s)</h2>\n%s\n</body></html>\n' "$ex/writeup.md" "$body"; } >"$html.tmp" && mv "$html.tmp" "$html" \
  || die "$html: (file): cannot write it"
echo "wrote $html ($((nfig - nfail)) of $nfig figures$( ((nfail)) && printf '; %d could not be made, their reason is in the report' "$nfail")$( ((nwarn)) && printf '; %d runs warned: their numbers are no result, the warnings are beside the figures' "$nwarn"), the answers table, the write-up; $(du -k "$html" | cut -f1) KB)"
