#!/usr/bin/env bash
# The grading kit's precompiled header is used: compiled the way clothlab-grade compiles a submission
# (kit.json's compiler and flags, -include of the header), GCC reads the .gch (its -H output marks
# a precompiled header it used with "!") instead of parsing Eigen again. A .gch that no longer matches
# the flags would be skipped in silence: each stage would then compile twice as long.
# Usage: kit_precompiled_header_check.sh SOURCE_DIR KIT
set -u
root=$1 kit=$2
fail() { echo "FAIL: $*"; exit 1; }
pch=$(jq -r '.precompiled_header // empty' "$kit"); inc=$(jq -r .include_dir "$kit")
[[ -n $pch && -f $inc/$pch.gch ]] || fail "$kit: no precompiled header, or no $inc/$pch.gch"
mapfile -t flags < <(jq -r '.compile_flags[]' "$kit")
mapfile -t sys < <(jq -r '.system_includes[] | "-isystem", .' "$kit")
src=$root/exercises/01_hooke/hooke.cpp
out=$("$(jq -r .compiler "$kit")" "${flags[@]}" -I"$inc" "${sys[@]}" -include "$inc/$pch" -Winvalid-pch -H -fsyntax-only "$src" 2>&1)
grep -q "^! $inc/$pch.gch" <<<"$out" || { head -5 <<<"$out"; fail "the compile of $src did not use $inc/$pch.gch"; }
echo "a submission file compiled with the kit's flags reads $pch.gch"
