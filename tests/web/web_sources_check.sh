#!/usr/bin/env bash
# The fast part of the browser build's tests (./lab test; no Emscripten needed): what breaks the web build
# while the native build still builds.
#   1. the browser's main (framework/app/web_main.cpp) compiles against today's App, ImGui's GLFW
#      backend, the renderer's ImGui backend (render/imgui_gl.h) and GLFW (g++ -fsyntax-only; emscripten.h stood in for by the few declarations it uses);
#   2. every framework source with a CLOTHLAB_WEB branch, and every GL source of the renderer (those that
#      include its switch, framework/src/render/gl.h), compiles with the switch on (-DCLOTHLAB_WEB=1:
#      OpenGL ES 3.0's GLES3/gl3.h, from libgles-dev: ./lab setup --test);
#   3. each element web_main.cpp writes (getElementById) is in web/index.html.
# Each check is shown to fail on a planted case in a temp copy (a renamed App member, a removed id).
#   web_sources_check.sh SOURCE_DIR TMP
# Not covered here (ctest -L web, ./lab test --web): em++ itself, the shaders compiled by WebGL2, the
# page running in a browser.
set -uo pipefail
src=$1 tmp=$2
rm -rf "$tmp" && mkdir -p "$tmp/stub"
cat >"$tmp/stub/emscripten.h" <<'H'
// Stand-in for the declarations of Emscripten's emscripten.h that web_main.cpp uses (syntax check only).
#pragma once
#define EM_ASM(code, ...) ((void)0)
#define EM_ASM_INT(code, ...) 0
#define EM_JS(ret, name, params, ...) ret name params;
void emscripten_set_main_loop(void (*f)(), int fps, int simulate_infinite_loop);
H
flags=(-std=c++17 -fsyntax-only -DCLOTHLAB_WEB=1 -I"$tmp/stub" -I"$src/framework/include" -I/usr/include/eigen3 $(pkg-config --cflags imgui))

check() {  # check ROOT [main]: 0 when every check holds in the tree ROOT (main: not the framework's sources)
  local root=$1 f id ok=0
  g++ "${flags[@]}" -I"$root/framework/include" "$root/framework/app/web_main.cpp" 2>"$tmp/err.txt" \
    || { echo "web_main.cpp does not compile: $(grep -m1 error "$tmp/err.txt")"; ok=1; }
  while IFS= read -r f; do
    g++ "${flags[@]}" "$f" 2>"$tmp/err.txt" || { echo "$f does not compile with CLOTHLAB_WEB: $(grep -m1 error "$tmp/err.txt")"; ok=1; }
  done < <([[ ${2:-} == main ]] || grep -rlE --include='*.cpp' 'CLOTHLAB_WEB|#include "gl\.h"' "$root/framework/src")
  for id in $(grep -o "getElementById('[a-z-]*')" "$root/framework/app/web_main.cpp" | sed "s/.*('\(.*\)')/\1/" | sort -u); do
    grep -q "id=\"$id\"" "$root/web/index.html" || { echo "web/index.html has no element id=\"$id\" (web_main.cpp writes it)"; ok=1; }
  done
  return $ok
}

rc=0
check "$src" || rc=1
((rc == 0)) && echo "ok: web_main.cpp, the CLOTHLAB_WEB sources and the renderer's GL sources compile, index.html has every element the app writes"

# Planted: each check catches its case.
plant() {  # plant NAME SED_FILE SED_EXPR EXPECTED_TEXT
  local copy="$tmp/plant-$1"
  mkdir -p "$copy/framework/app" "$copy/web"
  cp "$src/framework/app/web_main.cpp" "$copy/framework/app/"
  cp "$src/web/index.html" "$copy/web/"
  ln -s "$src/framework/src" "$copy/framework/src"
  ln -s "$src/framework/include" "$copy/framework/include"
  sed -i "$3" "$copy/$2"
  local out; out=$(check "$copy" main) && { echo "FAIL: planted $1 was not caught"; rc=1; return; }
  grep -q "$4" <<<"$out" || { echo "FAIL: planted $1 caught for another reason: $out"; rc=1; return; }
  echo "ok: planted $1 caught: $(head -1 <<<"$out")"
}
plant app_api_change framework/app/web_main.cpp 's/->statusJson()/->statusJsonRenamed()/' "web_main.cpp does not compile"
plant missing_status_element web/index.html 's/id="clothlab-status"/id="status"/' 'no element id="clothlab-status"'
exit $rc
