#!/usr/bin/env bash
# The fuzzed scene loader and the sanitized command line (docs/reliability.md).
#
#   run.sh BUILD_DIR check          build (clang, ASan + UBSan) scene_fuzz and clothlab in BUILD_DIR;
#                                   replay the seeds (scenes/, tests/fuzz/seeds/) and the regressions
#                                   (tests/fuzz/regressions/), fuzz for a few seconds, and run the CLI
#                                   tests (every scene, every bad input) on the sanitized clothlab
#   run.sh BUILD_DIR fuzz SECONDS   fuzz for SECONDS; the corpus grows in BUILD_DIR/corpus, a crash
#                                   is written to BUILD_DIR/crash-*
# Exit 0 when no input broke the contract and no sanitizer reported anything.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${1:?usage: run.sh BUILD_DIR check|fuzz SECONDS}; mode=${2:-check}; seconds=${3:-60}
mkdir -p "$build" && build=$(cd "$build" && pwd)
command -v clang++ >/dev/null || { echo "error: clang++ not found (apt-get install clang libclang-rt-14-dev)" >&2; exit 1; }
export ASAN_OPTIONS=halt_on_error=1:detect_leaks=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1

if [[ ! -f $build/CMakeCache.txt ]]; then
  CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCLOTHLAB_REFERENCE_STAGES= \
    -DCLOTHLAB_SANITIZE=ON -DCLOTHLAB_FUZZ=ON -DCLOTHLAB_RENDER=OFF >"$build/configure.log" 2>&1 \
    || { cat "$build/configure.log" >&2; exit 1; }
fi
cmake --build "$build" -j "${CLOTHLAB_JOBS:-$(nproc)}" --target scene_fuzz clothlab >"$build/build.log" 2>&1 \
  || { tail -40 "$build/build.log" >&2; exit 1; }
fuzz=$build/bin/scene_fuzz
seeds=("$root/scenes" "$here/seeds" "$here/regressions")

case $mode in
  check)
    # Each seed and regression once (a file argument is run, not mutated), then a short mutation run.
    "$fuzz" $(find "${seeds[@]}" -type f -not -name '*.expect' | sort) >"$build/replay.log" 2>&1 \
      || { tail -40 "$build/replay.log" >&2; echo "FAIL: a seed or regression input breaks the loader (log: $build/replay.log)" >&2; exit 1; }
    echo "replayed $(find "${seeds[@]}" -type f -not -name '*.expect' | wc -l) seeds and regressions"
    rm -rf "$build/check-corpus" && mkdir -p "$build/check-corpus"
    (cd "$build" && "$fuzz" -max_total_time="${CLOTHLAB_FUZZ_SECONDS:-10}" -max_len=4096 -timeout=10 -artifact_prefix="$build/" "$build/check-corpus" "${seeds[@]}" \
       >"$build/check-fuzz.log" 2>&1) \
      || { tail -40 "$build/check-fuzz.log" >&2; echo "FAIL: fuzzing found an input that breaks the loader (log: $build/check-fuzz.log)" >&2; exit 1; }
    grep -E '^#[0-9]+.*DONE' "$build/check-fuzz.log" || true
    # The command line, sanitized: every scene runs, every bad input is one error line.
    bash "$root/tests/cli/cli_test.sh" "$build/bin/clothlab" "$root"
    ;;
  fuzz)
    mkdir -p "$build/corpus"
    cd "$build"
    "$fuzz" -max_total_time="$seconds" -max_len=4096 -timeout=10 -artifact_prefix="$build/" -print_final_stats=1 "$build/corpus" "${seeds[@]}"
    ;;
  *) echo "error: run.sh: unknown mode $mode (check or fuzz)" >&2; exit 1 ;;
esac
