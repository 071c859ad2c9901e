#!/usr/bin/env bash
# `clothlab run SCENE --compare a,b,... --out DIR`: compare.csv with one row per run per sample (the
# error measure and the time in its header, with units), compare.png when gnuplot is there, the table
# of the last samples; a run that blows up stops alone with its message; bad lists give one error line.
# Usage: compare_cli_test.sh CLOTHLAB SOURCE_DIR TMP
set -u
exe=$(cd "$(dirname "$1")" && pwd)/$(basename "$1"); root=$2; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
fail=0
bad() { echo "FAIL: $*"; fail=1; }

if "$exe" run "$root/scenes/spring.json" --compare explicit_euler:dt=0.2,symplectic_euler,velocity_verlet --seconds 20 --out "$tmp/c" >"$tmp/out" 2>&1; then
  head -1 "$tmp/c/compare.csv" | grep -qx 'method,t \[s\],wall \[s\],error \[m\],energy \[J\],max_strain \[1\]' \
    || bad "header: $(head -1 "$tmp/c/compare.csv")"
  for m in symplectic_euler velocity_verlet; do
    n=$(grep -c "^$m," "$tmp/c/compare.csv")
    [[ $n -eq 101 ]] || bad "$m: want 101 rows (t = 0 and 100 samples), got $n"
  done
  # explicit Euler at dt = 0.2 s (omega dt = 2) blows up: its rows stop, the others go on to t = 20 s
  n=$(grep -c '^explicit_euler:dt=0.2,' "$tmp/c/compare.csv")
  [[ $n -ge 2 && $n -lt 101 ]] || bad "explicit_euler:dt=0.2: want fewer rows than the others, got $n"
  grep -q "explicit_euler:dt=0.2 stopped: unstable at step" "$tmp/out" || bad "no stop message: $(cat "$tmp/out")"
  awk -F, '$1 == "velocity_verlet" { t = $2 } END { exit !(t > 19.999 && t < 20.001) }' "$tmp/c/compare.csv" || bad "velocity_verlet does not reach t = 20 s"
  if command -v gnuplot >/dev/null; then [[ -s $tmp/c/compare.png ]] || bad "no compare.png"; fi
  grep -q "error measure error \[m\]" "$tmp/out" || bad "the measure is not named: $(head -3 "$tmp/out")"
else
  bad "compare failed: $(tail -5 "$tmp/out")"
fi

# A cloth: the measure is the RMS strain; the default --out is out/compare/<scene> (here under $tmp).
mkdir -p "$tmp/cwd"
(cd "$tmp/cwd" && "$exe" run "$root/scenes/pbd_hanging.json" --compare pbd:iterations=2,pbd:iterations=20 --seconds 0.5 --quiet >"$tmp/out2" 2>&1) \
  || bad "cloth compare failed: $(tail -3 "$tmp/out2")"
csv=$tmp/cwd/out/compare/pbd_hanging/compare.csv
head -1 "$csv" 2>/dev/null | grep -q 'rms_strain \[1\]' || bad "no out/compare/pbd_hanging/compare.csv with rms_strain"
awk -F, 'NR > 1 && $2 > 0.49 { s[$1] = $4 } END { exit !(s["pbd:iterations=2"] > s["pbd:iterations=20"]) }' "$csv" \
  || bad "2 iterations should stretch more than 20"

expect_error() {  # NAME PATTERN ARGS...
  local name=$1 pattern=$2; shift 2
  "$exe" "$@" >"$tmp/o" 2>"$tmp/e"; local code=$?
  if [[ $code -eq 0 || $code -ge 128 ]]; then bad "$name: exit code $code";
  elif [[ $(grep -c '^error: ' "$tmp/e") -ne 1 ]]; then bad "$name: want one error line, got: $(cat "$tmp/e")";
  elif ! grep -q "$pattern" "$tmp/e"; then bad "$name: want '$pattern', got: $(cat "$tmp/e")"; fi
}
expect_error one_run "error: command line: --compare: expected 2 to 4 runs" run "$root/scenes/spring.json" --compare rk4 --out "$tmp/x"
expect_error bad_method "error: command line: --compare: \"rk5\": .*solver.method: unknown value" run "$root/scenes/spring.json" --compare rk4,rk5 --out "$tmp/x"
expect_error bad_key "error: command line: --compare: \"rk4:gravity\": expected METHOD:key=value" run "$root/scenes/spring.json" --compare rk4,rk4:gravity --out "$tmp/x"
touch "$tmp/file"
expect_error out_is_a_file "error: $tmp/file/c: (folder): cannot" run "$root/scenes/spring.json" --compare rk4,rk4 --seconds 0.1 --out "$tmp/file/c"
expect_error with_dump "error: command line: --compare: --state, --dump, --strict and --window" run "$root/scenes/spring.json" --compare rk4,rk4 --dump "$tmp/d.csv"
[[ $fail -eq 0 ]] && echo "ok: run --compare writes compare.csv (a row per run per sample) and compare.png; bad lists give one error line"
exit $fail
