#!/usr/bin/env bash
# The core, the CLI without render options and every test binary must not link any GL library.
set -u
build=$1
bad=0; n=0
for exe in "$build"/bin/clothlab "$build"/bin/clothlab-grade "$build"/bin/grade_* "$build"/bin/framework_tests "$build"/bin/*_tests; do
  [[ -x $exe ]] || continue
  n=$((n+1))
  if ldd "$exe" | grep -Ei 'lib(GL|GLX|EGL|OSMesa|glfw|imgui)[^a-z]' ; then
    echo "FAIL: $exe links a GL library"; bad=1
  fi
done
echo "checked $n binaries for GL libraries"
[[ $n -gt 0 ]] || { echo "FAIL: no binaries found under $build"; exit 1; }
exit $bad
