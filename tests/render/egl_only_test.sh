#!/usr/bin/env bash
# Without OSMesa's development files (libosmesa6-dev, gone with Mesa 25.1) the renderer is still
# configured, as clothlab-render-egl alone: pkg-config sees every installed .pc file but osmesa.pc.
# CLOTHLAB_FULL_EGL_CHECK=1 also builds clothlab-render-egl there and renders a frame with it.
# Exit 77 (skipped) without pkg-config or EGL's .pc files.
set -eu
src=$1; dir=$2
command -v pkg-config >/dev/null && pkg-config --exists egl opengl || { echo "skip: no pkg-config or no egl/opengl .pc"; exit 77; }
rm -rf "$dir/pc"; mkdir -p "$dir/pc"
IFS=: read -r -a paths <<<"$(pkg-config --variable pc_path pkg-config)"
for p in "${paths[@]}"; do
  for f in "$p"/*.pc; do
    [[ -e $f && $(basename "$f") != osmesa.pc && ! -e $dir/pc/$(basename "$f") ]] && ln -s "$f" "$dir/pc/"
  done
done
PKG_CONFIG_LIBDIR=$dir/pc PKG_CONFIG_PATH= cmake -S "$src" -B "$dir" -DCMAKE_BUILD_TYPE=Release -DCLOTHLAB_REFERENCE_STAGES= \
  >"$dir/configure.log" 2>&1 || { cat "$dir/configure.log"; echo "FAIL: configure without osmesa.pc"; exit 1; }
grep -q "offscreen renderer: OSMesa OFF .* EGL ON" "$dir/configure.log" \
  || { grep clothlab: "$dir/configure.log"; echo "FAIL: want OSMesa OFF, EGL ON"; exit 1; }
targets=$(cmake --build "$dir" --target help)
grep -q 'clothlab-render-egl' <<<"$targets" || { echo "FAIL: no clothlab-render-egl target without OSMesa"; exit 1; }
! grep -Eq '(^|\.\.\. )clothlab-render$' <<<"$targets" || { echo "FAIL: a clothlab-render (OSMesa) target without osmesa.pc"; exit 1; }
if [[ -n ${CLOTHLAB_FULL_EGL_CHECK:-} ]]; then
  cmake --build "$dir" --target clothlab-render-egl -j "${CLOTHLAB_JOBS:-2}" >"$dir/build.log" 2>&1 \
    || { tail -30 "$dir/build.log"; echo "FAIL: build clothlab-render-egl without OSMesa"; exit 1; }
  ! ldd "$dir/bin/clothlab-render-egl" | grep -q OSMesa || { echo "FAIL: clothlab-render-egl links libOSMesa"; exit 1; }
  "$dir/bin/clothlab-render-egl" render "$src/scenes/spring.json" --seconds 0 --size 160x120 --out "$dir/frames" --quiet \
    | grep '^renderer: EGL' || { echo "FAIL: clothlab-render-egl did not render"; exit 1; }
  [[ -s $dir/frames/frame_0000.png ]] || { echo "FAIL: no frame"; exit 1; }
  echo "ok: built clothlab-render-egl without OSMesa and rendered a frame"
fi
echo "ok: without osmesa.pc the renderer configures with clothlab-render-egl alone"
