#!/usr/bin/env bash
# The solvers' headline speed figures in one run, on this machine (run it on a quiet one):
#   bash benchmarks/speed_summary.sh [BUILD_DIR]   (default: build; needs bench_pbd, bench_mfn, clothlab-render)
# Prints the 128² PBD step (exercise path and batched kernel, 1 and 2 threads) with the speed-up,
# XPBD against PBD, implicit Euler at Δt = 0.01 s (1 and 2 threads) and the app's frame rate on a
# 64² cloth. Wall-clock medians of 3 repetitions (about 5 minutes on a quiet 2-core machine); targets in brackets.
set -euo pipefail
build=${1:-build}
cd "$(dirname "$0")/.."
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

# median wall-clock time (ms) of each benchmark, as "name ms" lines
medians() { "$@" --benchmark_repetitions=3 --benchmark_report_aggregates_only=true --benchmark_format=csv 2>/dev/null |
  awk -F, '$1 ~ /_median"?$/ { n = $1; gsub(/"/, "", n); sub(/_median$/, "", n); t = $3; if ($5 ~ /us/) t /= 1000; print n, t }'; }
medians "$build/bin/bench_pbd" --benchmark_filter='PbdStep(Batched)?/n:128/|(Pbd|Xpbd)Step(Batched)?/n:64/threads:1' > "$tmp/pbd"
medians "$build/bin/bench_mfn" --benchmark_filter='ImplicitLargeStep/(default|default_2_threads)/128' > "$tmp/mfn"
get() { awk -v n="$1" '$1 == n { print $2 }' "$tmp/pbd" "$tmp/mfn"; }
pbd() { get "BM_$1/n:$2/threads:$3/real_time"; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (a == "" || b == "" || b == 0) print "n/a"; else printf "%.2f", a / b }'; }

printf '%-58s %10s\n' "figure" "value"
for kernel in PbdStep PbdStepBatched; do
  t1=$(pbd $kernel 128 1); t2=$(pbd $kernel 128 2)
  target=$([[ $kernel == PbdStep ]] && echo "<= 14 ms" || echo "<= 5.5 ms")
  printf '%-58s %7s ms  [%s]\n' "$kernel 128², 2 threads" "${t2:-n/a}" "$target"
  printf '%-58s %7s ms\n' "$kernel 128², 1 thread" "${t1:-n/a}"
  printf '%-58s %10s  [>= 1.8]\n' "$kernel 128² speed-up 1 -> 2 threads" "$(ratio "$t1" "$t2")"
done
printf '%-58s %10s  [<= 1.15]\n' "XPBD / PBD, 64², 1 thread, exercise path" "$(ratio "$(pbd XpbdStep 64 1)" "$(pbd PbdStep 64 1)")"
printf '%-58s %10s  [<= 1.15]\n' "XPBD / PBD, 64², 1 thread, batched kernel" "$(ratio "$(pbd XpbdStepBatched 64 1)" "$(pbd PbdStepBatched 64 1)")"
printf '%-58s %7s ms  [<= 50 ms]\n' "implicit Euler 128², dt = 0.01 s, 1 thread" "$(get BM_ImplicitLargeStep/default/128/iterations:10/real_time)"
printf '%-58s %7s ms\n' "implicit Euler 128², 2 threads" "$(get BM_ImplicitLargeStep/default_2_threads/128/iterations:10/real_time)"
if [[ -x $build/bin/clothlab-render ]]; then
  fps=$("$build/bin/clothlab-render" gui scenes/pbd_sphere.json --set cloth.nx=64 --set cloth.ny=64 \
        --screenshot "$tmp/s.png" --frames 120 | sed -n 's/.*(\([0-9.]*\) fps.*/\1/p')
  printf '%-58s %7s fps [>= 30]\n' "app, pbd_sphere 64², 1280x800, OSMesa (./lab gui ... --frames 120)" "$fps"
fi
