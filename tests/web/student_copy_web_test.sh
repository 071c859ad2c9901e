#!/usr/bin/env bash
# The student copy's page links the browser's reference objects (./lab release: framework/reference/web/,
# compiled by em++) for the stages named by --reference and the student's code for the others, as
# ./lab build --reference does natively. The copy (released from BUILD_DIR; its browser objects from
# BUILD_DIR/web-reference) holds them with their compiler, no source path, no debug section and no
# reference line (clothlab-leak-check); its `./lab web --no-serve --reference 03,04,05,06` builds the
# page, which runs pbd_sphere (stages 03-06) as the native reference does (browser_test.sh: moves, the
# native run's centroid within 0.1 mm after 80 steps), while spring (stage 01, the student's stub)
# stops at "not implemented". A copy released with --no-web-reference-objects says at once that the
# browser reference is not in it.
#   student_copy_web_test.sh SOURCE_ROOT BUILD_DIR CLOTHLAB SCENES_DIR LEAK_CHECK TMP
set -u -o pipefail
root=$1 build_dir=$2 clothlab=$3 scenes=$4 leak_check=$5 tmp=$6
here=$(cd "$(dirname "$0")" && pwd)
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$tmp" && mkdir -p "$tmp"
command -v em++ >/dev/null || fail "em++ is not installed (./lab setup --web)"

CLOTHLAB_BUILD=$build_dir "$root/lab" release "$tmp/copy" >"$tmp/release.log" 2>&1 || { tail -20 "$tmp/release.log"; fail "./lab release"; }
grep -q "browser reference objects (em++" "$tmp/release.log" || fail "./lab release does not report the browser's reference objects: $(tail -1 "$tmp/release.log")"
web=$tmp/copy/framework/reference/web
grep -q '^compiler_id=' "$web/compiler.txt" || fail "framework/reference/web/compiler.txt does not record the compiler"
for d in "$root"/solutions/[0-9][0-9]_*/; do
  d=$(basename "$d")
  compgen -G "$web/$d/*.o" >/dev/null || fail "no browser reference objects framework/reference/web/$d/*.o in the copy"
done
for o in "$web"/*/*.o; do
  magic=$(head -c 4 "$o" | od -An -tx1 | tr -d ' \n')  # "\0asm": a WebAssembly module (no `file` on a minimal Debian)
  [[ $magic == 0061736d ]] || fail "${o#$tmp/copy/}: not a WebAssembly object (it starts with the bytes $magic, not 00 61 73 6d)"
  strings -a "$o" | grep -q -e "$root" -e 'solutions/' -e '^\.debug_' && fail "${o#$tmp/copy/}: names the instructor's tree or has debug sections"
done
[[ -z $(find "$tmp/copy" -path '*/solutions*' -print -quit) ]] || fail "the copy holds a solutions path"
"$leak_check" "$root" "$tmp/copy" >"$tmp/leak.log" 2>&1 || { tail -20 "$tmp/leak.log"; fail "the copy gives away reference code"; }

# The copy's page with the reference for 03-06 (Dear ImGui's sources from this build: no second download).
mkdir -p "$tmp/build/web-imgui" && cp -r "$build_dir"/web-imgui/imgui-* "$tmp/build/web-imgui/" 2>/dev/null
(cd "$tmp/copy" && CLOTHLAB_BUILD=$tmp/build ./lab web --no-serve --reference 03,04,05,06 --out "$tmp/page") >"$tmp/web.log" 2>&1 \
  || { tail -20 "$tmp/web.log"; fail "./lab web --no-serve --reference 03,04,05,06 in the copy"; }
log=$tmp/build/web.configure.log
! grep -q "framework/reference/web/ holds" "$log" || fail "the copy's web build ignores its browser reference objects: $(grep -A2 'holds' "$log" | head -3)"
grep -q "stage 04 (04_distance) uses stage_04_solutions" "$log" && grep -q "stage 01 (01_hooke) uses stage_01_exercises" "$log" \
  || fail "--reference 03,04,05,06 in the copy's web build: $(grep 'uses stage_' "$log" | tr '\n' ' ')"
bash "$here/browser_test.sh" "$tmp/page" "$clothlab" "$scenes" "$tmp/sphere" pbd_sphere 80 1e-4 || fail "pbd_sphere with the browser reference objects (above)"
# Stage 01 is the student's (a stub): the page says so.
timeout 300 python3 "$here/page_run.py" --serve "$tmp/page" --seconds 15 "index.html?scene=spring&steps=5" \
  >"$tmp/spring.json" 2>"$tmp/spring.log" || fail "page_run.py spring: $(tail -3 "$tmp/spring.log")"
jq -e '.message | test("not implemented: exercise 1")' "$tmp/spring.json" >/dev/null \
  || fail "spring (stage 01 not in --reference) does not run the student's stub: message $(jq -c .message "$tmp/spring.json")"

# Released without them: --reference says so before building anything.
CLOTHLAB_BUILD=$build_dir "$root/lab" release "$tmp/bare" --no-web-reference-objects >"$tmp/bare.log" 2>&1 || { tail "$tmp/bare.log"; fail "./lab release --no-web-reference-objects"; }
[[ ! -e $tmp/bare/framework/reference/web ]] || fail "--no-web-reference-objects: the copy has framework/reference/web/"
(cd "$tmp/bare" && CLOTHLAB_BUILD=$tmp/bare-build ./lab web --no-serve --reference 04) >"$tmp/bare-web.log" 2>&1 && fail "./lab web --reference 04 in a copy without browser objects succeeds"
grep -q "the browser reference is not in this copy" "$tmp/bare-web.log" || fail "./lab web --reference 04 without browser objects: $(cat "$tmp/bare-web.log")"
[[ ! -e $tmp/bare-build ]] || fail "./lab web --reference 04 without browser objects configured a build before saying no"
rm -rf "$tmp/copy" "$tmp/bare" "$tmp/build" "$tmp/bare-build"
echo "ok: the student copy's page links the browser reference objects for 03-06 (pbd_sphere as native) and the student's stub for 01; without them --reference says so; no leak"
