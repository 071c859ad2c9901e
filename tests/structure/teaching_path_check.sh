#!/usr/bin/env bash
# The teaching path stays textbook: the checks of the "one clear teaching path" design, runnable by anyone.
#   1. nothing under framework/ includes, declares or links anything from solutions/;
#   2. framework/src/sim/pbd.cpp has no preprocessor conditionals (#if, #ifdef, ...);
#   3. PbdSimulation::step() is at most 40 lines.
# Usage: teaching_path_check.sh SOURCE_DIR   (checks that tree; then proves each check can fail on a
# temporary copy with the violation planted).
set -u
root=$1

check() {  # check TREE: prints the violations, exit status 1 if there are any
  local tree=$1 bad=0
  if grep -rnE '#include[[:space:]]*["<][^">]*(solutions/|kernels/|bending_batched)' "$tree/framework"; then
    echo "framework/ includes code from solutions/"; bad=1
  fi
  if grep -rnE 'solutions/|clothlab_kernels' "$tree/framework" --include=CMakeLists.txt --include='*.cmake'; then
    echo "framework/ CMake links code from solutions/"; bad=1
  fi
  if grep -rnwE 'BendingBlocks|bendingBlocks|projectBendingBlocks|BendingLoop' "$tree/framework"; then
    echo "framework/ declares or names a type or function of solutions/kernels"; bad=1
  fi
  if grep -nE '^[[:space:]]*#[[:space:]]*if' "$tree/framework/src/sim/pbd.cpp"; then
    echo "framework/src/sim/pbd.cpp has preprocessor conditionals"; bad=1
  fi
  local lines
  lines=$(awk '/^void PbdSimulation::step\(\)/{on=1} on{n++} on&&/^}/{print n; exit}' "$tree/framework/src/sim/pbd.cpp")
  if [[ -z $lines || $lines -gt 40 ]]; then
    echo "PbdSimulation::step() is ${lines:-not found} lines (at most 40)"; bad=1
  fi
  return $bad
}

check "$root" || { echo "FAIL: the teaching path checks do not hold"; exit 1; }

# Each check must be able to fail: plant each violation in a temporary copy of framework/.
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
plant() {  # plant NAME COMMAND...: copy framework/, run COMMAND in the copy, the check must fail
  local name=$1; shift
  rm -rf "$tmp/t" && mkdir -p "$tmp/t" && cp -r "$root/framework" "$tmp/t/"
  (cd "$tmp/t" && "$@")
  if check "$tmp/t" >/dev/null; then echo "FAIL: the check misses a planted violation: $name"; exit 1; fi
}
plant include   sed -i '1i #include "../../solutions/kernels/bending_batched.h"' framework/src/sim/pbd.cpp
plant cmake     sh -c 'echo "target_link_libraries(clothlab PRIVATE clothlab_kernels)" >> framework/CMakeLists.txt'
plant declare   sed -i '1i struct BendingBlocks;' framework/include/clothlab/sim/pbd.h
plant ifdef     sed -i '1i #ifdef CLOTHLAB_BATCHED_KERNELS\n#endif' framework/src/sim/pbd.cpp
plant long_step sh -c 'awk "{print} /^void PbdSimulation::step\\(\\)/{for(i=0;i<40;i++) print \"    // padding\"}" framework/src/sim/pbd.cpp > x && mv x framework/src/sim/pbd.cpp'
echo "teaching path checks hold (framework/ free of solutions/, no #if in pbd.cpp, step() $(awk '/^void PbdSimulation::step\(\)/{on=1} on{n++} on&&/^}/{print n; exit}' "$root/framework/src/sim/pbd.cpp") lines); each check fails when violated"
