#!/usr/bin/env bash
# The includes run one way: the framework library (framework/src, framework/include) never includes
# the programs' code in framework/app, and no student contract (framework/include/clothlab/exercise/)
# includes the scene file's types (core/scene.h): a stage takes the small types it needs.
# Then it proves it fails on a copy with each kind of upward include planted.
# Usage: include_direction_check.sh SOURCE_DIR
set -u
root=$1
check() {  # check TREE: one line per upward include, returns 1 if any
  local tree=$1 bad=0 line
  while IFS= read -r line; do
    echo "${line#$tree/}: the library includes framework/app (programs depend on the library, not back)"; bad=1
  done < <(grep -rnE '^\s*#\s*include\s+"([^"]*/)?(app/|\.\./app/|\.\./\.\./app/)' "$tree/framework/src" "$tree/framework/include" 2>/dev/null)
  while IFS= read -r line; do
    echo "${line#$tree/}: a student contract includes core/scene.h (give the stage its own small types)"; bad=1
  done < <(grep -rnE '^\s*#\s*include\s+"clothlab/core/scene\.h"' "$tree/framework/include/clothlab/exercise" 2>/dev/null)
  return $bad
}
out=$(check "$root") || { echo "$out"; echo "FAIL: includes run upward"; exit 1; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/framework/src/gui" "$tmp/framework/include/clothlab/exercise"
echo '#include "../../app/stub_advice.h"' >"$tmp/framework/src/gui/app.cpp"
echo '#include "clothlab/core/scene.h"' >"$tmp/framework/include/clothlab/exercise/06_collision.h"
out=$(check "$tmp") && { echo "FAIL: planted upward includes are not caught"; exit 1; }
[[ $(grep -c . <<<"$out") == 2 ]] || { echo "FAIL: not both planted includes named: $out"; exit 1; }
echo "no include runs upward (framework/src and include -> app, exercise headers -> core/scene.h); both planted ones caught"
