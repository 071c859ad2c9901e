#!/usr/bin/env bash
# The clothlab CLI on good and bad input: every scene runs; every bad input gives exactly one
# `error: <file>: <field>: <reason>` line and a non-zero exit, never a crash.
set -u
exe=$1; root=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0; fail=0
ok()   { pass=$((pass+1)); }
bad()  { fail=$((fail+1)); echo "FAIL: $*"; }

# Every scene in scenes/ loads and runs a few steps.
for s in "$root"/scenes/*.json; do
  if "$exe" run "$s" --steps 20 --quiet >"$tmp/out" 2>&1; then ok; else bad "scene $s does not run: $(tail -3 "$tmp/out")"; fi
done

# expect_error NAME EXPECTED_FIELD_TEXT JSON [extra args]
expect_error() {
  local name=$1 field=$2 json=$3; shift 3
  printf '%s' "$json" > "$tmp/$name.json"
  "$exe" run "$tmp/$name.json" --steps 1 "$@" >"$tmp/out" 2>"$tmp/err"
  local code=$?
  local lines; lines=$(grep -ac '^error: ' "$tmp/err")
  if [[ $code -ne 1 ]]; then bad "$name: exit code $code (want 1): $(head -c 400 "$tmp/err")";
  elif [[ $lines -ne 1 ]]; then bad "$name: want one error line, got: $(head -c 400 "$tmp/err")";
  elif ! grep -aq "^error: $tmp/$name.json: $field" "$tmp/err"; then bad "$name: want 'error: $tmp/$name.json: $field...', got: $(head -c 400 "$tmp/err")";
  else ok; fi
}
expect_error syntax       '(JSON syntax)'  '{"model": "spring",'
expect_error no_model     'model: missing' '{}'
expect_error bad_model    'model: unknown value' '{"model": "blob"}'
expect_error neg_mass     'spring.mass: must be > 0' '{"model": "spring", "spring": {"mass": -1}}'
expect_error zero_dt      'solver.dt: must be > 0' '{"model": "spring", "solver": {"dt": 0}}'
expect_error wrong_type   'spring.k: expected a number' '{"model": "spring", "spring": {"k": "stiff"}}'
expect_error unknown_key  'spring.stiffness: unknown key' '{"model": "spring", "spring": {"stiffness": 3}}'
expect_error bad_vec      'spring.start: expected an array of 3 numbers' '{"model": "spring", "spring": {"start": [1, 2]}}'
expect_error huge         '(JSON syntax): number overflow' '{"model": "spring", "spring": {"k": 1e999}}'
expect_error nan_set      'spring.k: expected a number' '{"model": "spring"}' --set spring.k=nan
expect_error set_unknown  'solver.dtt: unknown key' '{"model": "spring"}' --set solver.dtt=0.1
expect_error grid         'cloth.nx: must be between 2' '{"model": "cloth", "cloth": {"nx": 1}}'
expect_error self_thick   'self_collision.thickness: must be > 0' '{"model": "cloth", "solver": {"method": "pbd"}, "self_collision": {"thickness": 0}}'
expect_error self_method  'self_collision: works with method "pbd" or "xpbd"' '{"model": "cloth", "self_collision": {}}'
expect_error pin_range    'cloth.pins\[0\]: particle index 100' '{"model": "cloth", "cloth": {"nx": 3, "ny": 3, "pins": [100]}}'
expect_error chain_short  'chain.particles: must be between 2' '{"model": "chain", "chain": {"particles": 1}}'
expect_error method       'solver.method: unknown value' '{"model": "spring", "solver": {"method": "magic"}}'
expect_error pbd_spring   'solver.method: "pbd" needs model "cloth"' '{"model": "spring", "solver": {"method": "pbd"}}'
expect_error collider     'colliders\[0\].radius: must be > 0' '{"model": "cloth", "colliders": [{"type": "sphere", "radius": -1}]}'
expect_error not_object   '(top level): expected an object' '[1, 2, 3]'
expect_error pbd_damping  'pbd.damping: must be <= 1 (got 2)' '{"model": "cloth", "pbd": {"damping": 2}, "solver": {"method": "pbd"}}'
expect_error old_damping  'forces.damping: renamed: use forces.air_damping' '{"model": "cloth", "forces": {"damping": 0.1}}'

# Extreme input (docs/reliability.md "The fuzzed scene loader"; the limits: docs/scenes.md "Limits").
expect_error big_number   'solver.dt: must be <= 10 (got 1e+308)' '{"model": "spring", "solver": {"dt": 1e308}}'
expect_error neg_zero_mass 'spring.mass: must be > 0 (got -0)' '{"model": "spring", "spring": {"mass": -0.0}}'
expect_error neg_zero_dt  'solver.dt: must be > 0 (got -0)' '{"model": "spring"}' --set solver.dt=-0.0
deep=$(printf '%.0s[' {1..100000}); expect_error deep_nesting '(JSON syntax): nested deeper than 64 levels' "{\"model\": $deep"
expect_error deep_set     'model: nested deeper than 64 levels' '{"model": "spring"}' --set "model=$deep"
expect_error not_utf8     '(JSON syntax): ' $'{"model": "spr\xff\xfeing"}'
expect_error not_utf8_set 'spring.k: expected a number (got string' '{"model": "spring"}' --set $'spring.k=\xff'
expect_error newline_key  'spring.a\\x0ab: unknown key' '{"model": "spring"}' --set $'spring.a\nb=1'
expect_error grid_huge    'cloth.nx: must be between 2 and 4096 (got 100000)' '{"model": "cloth", "cloth": {"nx": 100000, "ny": 100000}}'
expect_error grid_area    'cloth.ny: grid too large (nx\*ny > 4,000,000)' '{"model": "cloth", "cloth": {"nx": 4096, "ny": 4096}}'
expect_error chain_huge   'chain.particles: must be between 2 and 100000 (got 18446744073709551615)' '{"model": "chain", "chain": {"particles": 18446744073709551615}}'
expect_error pin_negative 'cloth.pins\[1\]: particle index -1 outside the cloth (0..8)' '{"model": "cloth", "cloth": {"nx": 3, "ny": 3, "pins": [0, -1]}}'
expect_error pin_u64      'cloth.pins\[0\]: particle index 18446744073709551615 outside' '{"model": "cloth", "cloth": {"nx": 3, "ny": 3, "pins": [18446744073709551615]}}'
expect_error set_inf      'spring.k: expected a number (got string "inf")' '{"model": "spring"}' --set spring.k=inf
expect_error set_overflow 'spring.k: expected a number (got string "1e999")' '{"model": "spring"}' --set spring.k=1e999
expect_error set_index    'colliders.3.radius: no element "3" in this array' '{"model": "cloth", "colliders": [{"type": "plane"}]}' --set colliders.3.radius=1
# A file over the size limit is refused before it is read (a sparse 100 MB file).
truncate -s 100M "$tmp/big.json"
"$exe" run "$tmp/big.json" >"$tmp/out" 2>"$tmp/err"
if [[ $? -eq 1 && $(wc -l <"$tmp/err") -eq 1 ]] && grep -q "^error: $tmp/big.json: (file): larger than the limit of 16 MiB (104857600 bytes)" "$tmp/err"; then ok; else bad "100 MB file: $(cat "$tmp/err")"; fi
rm -f "$tmp/big.json"

# A missing file.
"$exe" run "$tmp/nope.json" >"$tmp/out" 2>"$tmp/err"
if [[ $? -eq 1 ]] && grep -q "^error: $tmp/nope.json: (file): cannot open" "$tmp/err"; then ok; else bad "missing file: $(cat "$tmp/err")"; fi

# An explicit method that blows up stops with "unstable at step N" and a non-zero exit.
"$exe" run "$root/scenes/spring.json" --set solver.method=explicit_euler --set spring.k=1e9 --set solver.dt=0.01 --steps 10000 --quiet >"$tmp/out" 2>"$tmp/err"
code=$?
if [[ $code -eq 3 ]] && grep -q "unstable at step" "$tmp/err"; then ok; else bad "blow-up: exit $code, $(cat "$tmp/err")"; fi

# A stiff cloth with explicit Euler blows up the same way; implicit Euler runs it.
"$exe" run "$root/scenes/mfn_implicit.json" --set solver.method=explicit_euler --steps 100 --quiet >"$tmp/out" 2>"$tmp/err"
code=$?
if [[ $code -eq 3 ]] && grep -q "unstable at step" "$tmp/err"; then ok; else bad "cloth blow-up: exit $code, $(cat "$tmp/err")"; fi

# When a result is not a result (run.h: RunChecks). No false alarm: every shipped scene at its own
# settings passes --strict. pbd_sphere at three times its step falls through the sphere: the summary
# says so with the step and the worst penetration of the run, summary.json carries the warning, exit
# 0; with --strict it is an error, exit 3. A particle leaving |x| < report.blowup is named as such.
for s in "$root"/scenes/*.json; do
  if "$exe" run "$s" --strict --quiet >"$tmp/out" 2>"$tmp/err"; then ok; else bad "--strict on $s at its own settings: $(cat "$tmp/err")"; fi
done
"$exe" run "$root/scenes/pbd_sphere.json" --set solver.dt=0.03 --quiet --out "$tmp/fall" >"$tmp/out" 2>"$tmp/err"
code=$?
if [[ $code -eq 0 ]] && grep -q "warning: fell through: .* at step [0-9]" "$tmp/out" && grep -q "worst_penetration .* at step" "$tmp/out" \
   && grep -q '"kind": "fell_through"' "$tmp/fall/summary.json"; then ok; else bad "fell through without --strict: exit $code, $(grep -i warn "$tmp/out")"; fi
"$exe" run "$root/scenes/pbd_sphere.json" --set solver.dt=0.03 --quiet --strict >"$tmp/out" 2>"$tmp/err"
code=$?
# --strict stops at the first warning (here: not converged, two steps before the fall), its sentence in
# the summary, its headline in the one error line.
if [[ $code -eq 3 && $(grep -c '^error: ' "$tmp/err") -eq 1 ]] && grep -q "^error: .*pbd_sphere.json: solver: stopped at step [0-9]* by --strict: " "$tmp/err" \
   && grep -q "^  warning: " "$tmp/out"; then ok
else bad "fell through --strict: exit $code, $(cat "$tmp/err")"; fi
"$exe" run "$root/scenes/pbd_hanging.json" --set cloth.nx=64 --set cloth.ny=64 --set solver.iterations=2 --steps 30 --quiet --strict >"$tmp/out" 2>"$tmp/err"
code=$?
if [[ $code -eq 3 ]] && grep -q "not converged: .* since step [0-9]" "$tmp/err"; then ok; else bad "not converged --strict: exit $code, $(cat "$tmp/err")"; fi
"$exe" run "$root/scenes/spring.json" --set report.blowup=1.4 --quiet --out "$tmp/region" >"$tmp/out" 2>"$tmp/err"
code=$?
# The reason once: on the error line, not again in the summary.
if [[ $code -eq 3 ]] && grep -q "left the region |x| < 1.4 m" "$tmp/err" && ! grep -q "left the region" "$tmp/out" \
   && grep -q "stopped early, at step 1" "$tmp/out" && ! grep -q "no longer finite" "$tmp/out" \
   && grep -q '"cause": "left_region"' "$tmp/region/summary.json"; then ok; else bad "left the region: exit $code, $(cat "$tmp/err")"; fi

# The studies write CSV (and PNG when gnuplot is there) and print their table.
if "$exe" study stability "$root/scenes/spring.json" --methods symplectic_euler,implicit_euler --k-count 3 --dt-count 3 --steps 100 \
     --out "$tmp/st" >"$tmp/out" 2>&1 && grep -q "agrees in" "$tmp/out" && [[ -s $tmp/st/stability.csv ]]; then ok; else bad "study stability: $(tail -3 "$tmp/out")"; fi
if "$exe" study precision "$root/scenes/spring.json" --methods rk4 --dt-count 2 --out "$tmp/pr" >"$tmp/out" 2>&1 \
     && grep -q "measured order" "$tmp/out" && [[ $(wc -l <"$tmp/pr/precision.csv") -eq 3 ]]; then ok; else bad "study precision: $(tail -3 "$tmp/out")"; fi
# The collision axis of the stability study: the map as text, CSV (and PNG), fell through at 0.03 s.
if "$exe" study stability "$root/scenes/pbd_sphere.json" --collision --dt-min 0.01 --dt-max 0.03 --dt-count 2 --iterations 10 --seconds 1 \
     --out "$tmp/col" >"$tmp/out" 2>&1 && grep -q "^ *0.03  *F$" "$tmp/out" && grep -q "^ *0.01  *\.$" "$tmp/out" \
   && [[ $(wc -l <"$tmp/col/collision.csv") -eq 3 ]]; then ok; else bad "study stability --collision: $(tail -4 "$tmp/out")"; fi
# The extremes report (a small matrix): a markdown table with the command, a CSV, no silently wrong cell.
if "$exe" study extremes --scenes "$root/scenes" --methods symplectic_euler,pbd --k 1,1e9 --dt 1e-3,1 --iterations 1,10 --steps 10 --out "$tmp/ex" >"$tmp/out" 2>&1 \
   && grep -q '`./lab study extremes --steps 10 --methods symplectic_euler,pbd' "$tmp/ex/extremes.md" && grep -q '\*\*0 silently wrong\*\*' "$tmp/ex/extremes.md" \
   && [[ $(grep -c ',symplectic_euler,' "$tmp/ex/extremes.csv") -eq 32 ]]; then ok; else bad "study extremes: $(tail -3 "$tmp/out")"; fi
# Without gnuplot on the PATH: a clear note, the CSV all the same, exit 0.
if env PATH=/nonexistent "$exe" study precision "$root/scenes/spring.json" --methods rk4 --dt-count 2 --out "$tmp/np" >"$tmp/out" 2>"$tmp/err" \
     && grep -q "gnuplot not found" "$tmp/err" && [[ -s $tmp/np/precision.csv && ! -e $tmp/np/precision.png ]]; then ok; else bad "study without gnuplot: $(cat "$tmp/err")"; fi
# Position-based scene: iterations and substeps at equal projections against an XPBD reference.
if "$exe" study precision "$root/scenes/pbd_hanging.json" --set cloth.nx=5 --set cloth.ny=5 --methods pbd --budgets 1,4 --end-time 0.1 \
     --reference-substeps 16 --out "$tmp/pp" >"$tmp/out" 2>&1 && grep -q "smallest error at equal cost" "$tmp/out" \
     && grep -q "reference: xpbd with 16 substeps" "$tmp/out" && [[ $(wc -l <"$tmp/pp/precision.csv") -eq 5 ]]; then ok; else bad "study precision pbd: $(tail -3 "$tmp/out")"; fi
"$exe" study precision "$root/scenes/pbd_hanging.json" --budgets 1,x >"$tmp/out" 2>"$tmp/err"
if [[ $? -eq 1 ]] && grep -q "^error: command line: --budgets" "$tmp/err"; then ok; else bad "study bad budgets: $(cat "$tmp/err")"; fi
"$exe" study precision "$root/scenes/spring.json" --dt-min -1 >"$tmp/out" 2>"$tmp/err"
if [[ $? -eq 1 ]] && grep -q "^error: command line: --dt-min" "$tmp/err"; then ok; else bad "study bad range: $(cat "$tmp/err")"; fi

# --dump writes the documented header and one row per particle.
"$exe" run "$root/scenes/chain.json" --steps 10 --quiet --dump "$tmp/state.csv" >/dev/null 2>&1
if [[ "$(head -1 "$tmp/state.csv")" == "i,x,y,z,vx,vy,vz" && $(wc -l <"$tmp/state.csv") -eq 11 ]]; then ok; else bad "dump: $(head -3 "$tmp/state.csv")"; fi

# Numbers that round-trip: a dumped state reads back bit for bit (--state), and a run restarted from
# its dump at step 50 ends bit-identical to the straight run of 100 steps (PBD with collisions; a
# mass-spring cloth with symplectic Euler; one with implicit Euler, at 10 x 10 particles: up to 300
# unknowns it solves exactly; above, conjugate gradients start from the last step's Δv, which a dump
# does not hold, docs/reliability.md).
for run in pbd_sphere mfn_hanging "mfn_implicit --set cloth.nx=10 --set cloth.ny=10"; do
  read -r sc set <<<"$run"
  read -ra set <<<"${set:-}"
  "$exe" run "$root/scenes/$sc.json" "${set[@]}" --steps 50 --quiet --dump "$tmp/s50.csv" >/dev/null 2>&1
  "$exe" run "$root/scenes/$sc.json" "${set[@]}" --steps 0 --quiet --state "$tmp/s50.csv" --dump "$tmp/again.csv" >/dev/null 2>&1
  if cmp -s "$tmp/s50.csv" "$tmp/again.csv"; then ok; else bad "$sc: the state does not read back bit for bit"; fi
  "$exe" run "$root/scenes/$sc.json" "${set[@]}" --steps 100 --quiet --dump "$tmp/s100.csv" >/dev/null 2>&1
  "$exe" run "$root/scenes/$sc.json" "${set[@]}" --steps 50 --quiet --state "$tmp/s50.csv" --dump "$tmp/restart.csv" >/dev/null 2>&1
  if cmp -s "$tmp/s100.csv" "$tmp/restart.csv"; then ok; else bad "$sc: 50 + 50 steps from a dump differ from 100 steps"; fi
done
# report.csv writes 17 significant digits (0.1 s is 0.10000000000000001), and summary.json's shortest
# form reads back as the same double as report.csv's. Compared as doubles: jq 1.7 (Debian 13) compares
# two number literals as decimals, where 6.174370319044302 and 6.1743703190443018 differ; a difference
# is computed in double precision in every jq.
"$exe" run "$root/scenes/chain.json" --set solver.dt=0.1 --steps 1 --every 1 --quiet --out "$tmp/rt" >/dev/null 2>&1
row=$(tail -1 "$tmp/rt/report.csv")
if [[ $(cut -d, -f2 <<<"$row") == 0.10000000000000001 ]]; then ok; else bad "report.csv t with 17 digits: $row"; fi
if jq -e --arg e "$(cut -d, -f4 <<<"$row")" '(.metrics.energy.value - ($e | tonumber)) == 0 and (.simulated_time - 0.1) == 0' "$tmp/rt/summary.json" >/dev/null
then ok; else bad "summary.json energy does not read back as report.csv's: $row, $(cat "$tmp/rt/summary.json")"; fi
# --window T0,T1: every metric's min, mean and max over the states with t in [T0, T1] s, taken at every
# step whatever --every is. Checked against report.csv of the same run written at every step (awk over
# its rows with 0.5 <= t <= 1, not the code under test), on a metric that oscillates (the spring's error).
# Compared as doubles (a difference): jq 1.7 (Debian 13) compares two number literals digit by digit.
"$exe" run "$root/scenes/spring.json" --steps 1500 --every 1 --quiet --out "$tmp/win1" >/dev/null 2>&1
"$exe" run "$root/scenes/spring.json" --steps 1500 --every 500 --window 0.5,1 --out "$tmp/win" >"$tmp/win.out" 2>&1
want=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "error [m]") c = i; next }
                $2 >= 0.5 - 1e-9 && $2 <= 1 + 1e-9 { v = $c + 0; n++; s += v; if (n == 1 || v < lo) lo = v; if (n == 1 || v > hi) hi = v }
                END { printf "%d %.17g %.17g %.17g", n, lo, s / n, hi }' "$tmp/win1/report.csv")
read -r n lo mean hi <<<"$want"
if [[ $n -eq 501 ]] && jq -e --argjson lo "$lo" --argjson mean "$mean" --argjson hi "$hi" '.window.states == 501 and .window.from == 0.5 and .window.to == 1
     and (.window.metrics.error.min - $lo) == 0 and (.window.metrics.error.max - $hi) == 0 and (.window.metrics.error.mean - $mean | fabs) <= 1e-12 * $hi
     and .window.metrics.error.max > 2 * .window.metrics.error.min' "$tmp/win/summary.json" >/dev/null \
   && grep -q '^over t in \[0.5, 1\] s (501 states, --window):' "$tmp/win.out" && grep -qE '^  error +[0-9.e+-]+ +[0-9.e+-]+ +[0-9.e+-]+ m$' "$tmp/win.out"
then ok; else bad "--window 0.5,1: report.csv gives $want (states, min, mean, max of error), the run: $(jq -c .window "$tmp/win/summary.json" 2>&1 | head -c 600)"; fi
# Bad windows: one error line naming --window, exit 1 (a window after the run's end, reversed, not two numbers).
for w in "3" "2,1" "0.5,9" "a,1" ","; do
  "$exe" run "$root/scenes/spring.json" --steps 100 --window "$w" >"$tmp/out" 2>"$tmp/err"
  code=$?
  if [[ $code -eq 1 && $(grep -c '^error: ' "$tmp/err") -eq 1 ]] && grep -q "^error: command line: --window: \"$w\": " "$tmp/err"; then ok
  else bad "--window $w: exit $code, $(cat "$tmp/err")"; fi
done
# Bad state files: one error line naming the file and the row or field, exit 1.
bad_state() {  # bad_state NAME FIELD CONTENT
  printf '%b' "$3" >"$tmp/$1.csv"
  "$exe" run "$root/scenes/chain.json" --steps 1 --state "$tmp/$1.csv" >"$tmp/out" 2>"$tmp/err"
  local code=$?
  if [[ $code -eq 1 && $(grep -c '^error: ' "$tmp/err") -eq 1 ]] && grep -q "^error: $tmp/$1.csv: $2" "$tmp/err"; then ok
  else bad "state $1: exit $code, $(cat "$tmp/err")"; fi
}
bad_state header '(header)' 'x,y,z\n'
bad_state short  '(rows)' 'i,x,y,z,vx,vy,vz\n0,0,0,0,0,0,0\n'
bad_state nan    'row 2' 'i,x,y,z,vx,vy,vz\n0,nan,0,0,0,0,0\n'
bad_state word   'row 2' 'i,x,y,z,vx,vy,vz\n0,a,0,0,0,0,0\n'
bad_state order  'row 2' 'i,x,y,z,vx,vy,vz\n3,0,0,0,0,0,0\n'
"$exe" run "$root/scenes/spring.json" --state "$tmp/s50.csv" >"$tmp/out" 2>"$tmp/err"
if [[ $? -eq 1 ]] && grep -q "^error: command line: --state" "$tmp/err"; then ok; else bad "spring --state: $(cat "$tmp/err")"; fi

# One meaning per quantity: the same cloth as a mass-spring network and as PBD writes the same
# strain columns, as fractions with their unit, and a precision study writes its strain in [1].
for m in symplectic_euler pbd; do
  "$exe" run "$root/scenes/mfn_hanging.json" --set solver.method=$m --steps 5 --quiet --out "$tmp/csv_$m" >/dev/null 2>&1
  header=$(head -1 "$tmp/csv_$m/report.csv")
  if [[ $header == "step,t [s],wall [s],energy [J],energy_drift [J],max_strain [1],rms_strain [1]"* ]]; then ok; else bad "report.csv header ($m): $header"; fi
  if grep -q '%' "$tmp/csv_$m/report.csv" "$tmp/csv_$m/summary.json"; then bad "percent in the $m report"; else ok; fi
done
if grep -q 'rms_strain \[1\]' <(head -1 "$tmp/pp/precision.csv"); then ok; else bad "precision.csv header: $(head -1 "$tmp/pp/precision.csv")"; fi

# Hints are free help: `hint N.M [LEVEL]` shows levels 1 to LEVEL (default 1), the same on every call,
# writes no file and speaks of no record or count; bad task numbers and levels are one error line.
mkdir -p "$tmp/ex/04_distance"
printf '{"4.1": ["level-one text?", "level-two text", "level-three text"]}' >"$tmp/ex/04_distance/hints.json"
for args in "4.1" "4.1" "4.1 2" "4.1 3" "4.1"; do
  read -r _ level <<<"$args"; level=${level:-1}
  # shellcheck disable=SC2086
  "$exe" hint $args --exercises "$tmp/ex" >"$tmp/out" 2>&1 || bad "hint $args: exit $?"
  cat "$tmp/out" >>"$tmp/hints_all"
  if grep -q "level $level of 3" "$tmp/out" && [[ $(grep -c '^hint 4.1, level' "$tmp/out") -eq $level ]]; then ok
  else bad "hint $args should show levels 1 to $level: $(cat "$tmp/out")"; fi
done
grep -q 'level 1 of 3 (a question and the slide to look at)' "$tmp/hints_all" && grep -q '^more: ./lab hint 4.1 2 (one sub-step)' "$tmp/hints_all" \
  && grep -q 'level 3 of 3 (the formula)' "$tmp/hints_all" && ok || bad "hint should name each level and how to get the next: $(cat "$tmp/hints_all")"
[[ $(ls "$tmp/ex/04_distance") == hints.json ]] && ok || bad "hint wrote into the stage folder: $(ls "$tmp/ex/04_distance")"
grep -qiE 'record|taken|count|grade|instructor' "$tmp/hints_all" && bad "hint speaks of a record: $(cat "$tmp/hints_all")" || ok
for t in 4.9 x 7.1 "4.1 4" "4.1 0" "4.1 two"; do
  # shellcheck disable=SC2086
  "$exe" hint $t --exercises "$tmp/ex" >"$tmp/out" 2>"$tmp/err"; code=$?
  [[ $code -eq 1 && $(grep -c '^error: ' "$tmp/err") -eq 1 ]] && ok || bad "hint $t: exit $code, $(cat "$tmp/err")"
done
"$exe" hint 4.1 --shown --exercises "$tmp/ex" >/dev/null 2>&1 && bad "hint --shown (levels taken) still accepted" || ok

echo "cli checks: $pass ok, $fail failing"
[[ $fail -eq 0 ]]

