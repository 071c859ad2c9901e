#!/usr/bin/env bash
# The grading kit's precompiled header is used: compiled the way clothlab-grade compiles a submission
# (kit.json's compiler and flags, the kit's headers seen under another path as in the sandbox's
# /kit/include, -include of the header), GCC reads the .gch (its -H output marks a precompiled header
# it used with "!") instead of parsing Eigen again. A .gch that no longer matches the flags would be
# skipped in silence: each stage would then compile twice as long. Then through the grader: a stage
# file is compiled with the header, and a file that defines a macro before its first #include
# without it (docs/grading.md, "compile").
# Usage: kit_precompiled_header_check.sh SOURCE_DIR KIT GRADER
set -u
root=$1 kit=$2 grader=$3
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
pch=$(jq -r '.precompiled_header // empty' "$kit"); inc=$(jq -r .include_dir "$kit")
[[ -n $pch && -f $inc/$pch.gch ]] || fail "$kit: no precompiled header, or no $inc/$pch.gch"
cp -r "$inc" "$tmp/include"
mapfile -t flags < <(jq -r '.compile_flags[]' "$kit")
mapfile -t sys < <(jq -r '.system_includes[] | "-isystem", .' "$kit")
for src in "$root"/exercises/01_hooke/hooke.cpp "$root"/exercises/06_collision/collision.cpp; do
  out=$("$(jq -r .compiler "$kit")" "${flags[@]}" -I"$tmp/include" "${sys[@]}" -include "$tmp/include/$pch" -Winvalid-pch -H -fsyntax-only "$src" 2>&1)
  grep -q "^! $tmp/include/$pch.gch" <<<"$out" || { head -5 <<<"$out"; fail "the compile of $src did not use $pch.gch"; }
done
# Through the grader: the reference of stage 01 with a check that the header came first, and a second
# file that defines a macro first, with a check that it did not.
mkdir -p "$tmp/sub" && cp -r "$root/solutions/01_hooke" "$tmp/sub/" || fail "no solutions/01_hooke"
printf '\n#ifndef CLOTHLAB_PRECOMPILED_H\n#error compiled without the precompiled header\n#endif\n' >>"$tmp/sub/01_hooke/hooke.cpp"
printf '#define CLOTHLAB_MY_SETTING 1\n#ifdef CLOTHLAB_PRECOMPILED_H\n#error the precompiled header came before my first define\n#endif\n#include "clothlab/exercise/01_hooke.h"\n' >"$tmp/sub/01_hooke/setting.cpp"
"$grader" --kit "$kit" --submission "$tmp/sub" --work "$tmp/work" --stage 01 >"$tmp/grade.log" 2>&1
grep -qE '^01 .* ([0-9.]+) / \1 *$' "$tmp/grade.log" || { tail -15 "$tmp/grade.log"; fail "stage 01 with both checks did not compile to full points"; }
echo "submission files compiled with the kit's flags read $pch.gch; the grader compiles a stage file with it and a file that defines a macro first without it"
