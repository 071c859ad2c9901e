#!/usr/bin/env bash
# -DCLOTHLAB_RENDER=OFF: configure without any GL package (pkg-config disabled); check that no render
# target exists and the CLI links no GL library (CLOTHLAB_FULL_OFF_CHECK=1: also build the CLI and run a scene).
set -eu
src=$1; dir=$2
mkdir -p "$dir"
cmake -S "$src" -B "$dir" -DCMAKE_BUILD_TYPE=Release -DCLOTHLAB_RENDER=OFF -DCMAKE_DISABLE_FIND_PACKAGE_PkgConfig=ON \
      -DCMAKE_DISABLE_FIND_PACKAGE_glfw3=ON -DCMAKE_DISABLE_FIND_PACKAGE_OpenGL=ON >"$dir/configure.log" 2>&1 \
  || { cat "$dir/configure.log"; echo "FAIL: configure with CLOTHLAB_RENDER=OFF"; exit 1; }
if cmake --build "$dir" --target help | grep -Eq 'clothlab-render|clothlab-gui|clothlab_render'; then
  echo "FAIL: render targets exist with CLOTHLAB_RENDER=OFF"; exit 1
fi
# The CLI's link line names no GL library (the core compiles with the same flags as in the main build).
link=$(find "$dir/framework" -path '*clothlab.dir/link.txt' | head -1)
[[ -f $link ]] || { echo "FAIL: no link line for the clothlab CLI"; exit 1; }
if grep -Eiq -- '-l(GL|OSMesa|glfw|imgui)\b|lib(GL|OSMesa|glfw|imgui)\.' "$link"; then echo "FAIL: the CLI links GL: $(cat "$link")"; exit 1; fi
# The full build (core + CLI + a scene run, about a minute on 2 cores) with CLOTHLAB_FULL_OFF_CHECK=1.
if [[ -n ${CLOTHLAB_FULL_OFF_CHECK:-} ]]; then
  cmake --build "$dir" --target clothlab -j "${CLOTHLAB_JOBS:-2}" >"$dir/build.log" 2>&1 \
    || { tail -30 "$dir/build.log"; echo "FAIL: build with CLOTHLAB_RENDER=OFF"; exit 1; }
  "$dir/bin/clothlab" run "$src/scenes/spring.json" --steps 10 --quiet >/dev/null || { echo "FAIL: clothlab run"; exit 1; }
  if ldd "$dir/bin/clothlab" | grep -Ei 'lib(GL|GLX|EGL|OSMesa|glfw|imgui)[^a-z]'; then echo "FAIL: links GL"; exit 1; fi
  echo "ok: built and ran the CLI with CLOTHLAB_RENDER=OFF"
fi
echo "ok: CLOTHLAB_RENDER=OFF configures without any GL package; no render targets; the CLI links no GL"
