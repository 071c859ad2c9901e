#!/usr/bin/env bash
# The grading kit (build/grade-kit/kit.json, cmake/grade_kit.cmake) stays valid JSON when the build's
# flags hold a quote and a backslash: a scratch configure (no build) with such a flag in
# CMAKE_CXX_FLAGS, then the flag read back through jq exactly as the compiler gets it.
# Usage: kit_json_check.sh SOURCE_DIR
set -u
root=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
cmake -S "$root" -B "$tmp/b" -DCMAKE_BUILD_TYPE=Release '-DCMAKE_CXX_FLAGS=-DKIT_CHECK=\"a\\b\"' >"$tmp/cfg.log" 2>&1 ||
  { tail -5 "$tmp/cfg.log"; fail "the scratch configure failed"; }
flag=$(jq -r '.compile_flags[] | select(startswith("-DKIT_CHECK"))' "$tmp/b/grade-kit/kit.json") || fail "kit.json is not JSON"
[[ $flag == '-DKIT_CHECK="a\b"' ]] || fail "the flag came back as [$flag], not [-DKIT_CHECK=\"a\\b\"]"
echo "kit.json carries the flag -DKIT_CHECK=\"a\\b\" exactly"
