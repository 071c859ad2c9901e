#!/usr/bin/env bash
# Gradescope autograder setup, written to the bundle by `./lab release --gradescope DIR` (see
# docs/grading.md, "Gradescope"). Gradescope runs it once, as root on its Ubuntu image, while it builds
# the autograder's image: the bundle is unpacked in /autograder/source, the grader is the student copy
# in clothlab/ beside this file (committed files, no solutions/, the reference of every stage as
# compiled objects). It installs clothlab's packages (./lab setup) and builds the grader and its grading
# kit into /autograder/source/build, so that run_autograder only compiles and tests the submission.
set -euo pipefail
src=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${CLOTHLAB_BUILD:-$src/build}
cd "$src/clothlab"
./lab setup  # the Debian/Ubuntu packages (apt-get, as root)
mkdir -p "$build"
# The grading kit needs neither the renderer nor the app; Release as ./lab builds it.
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCLOTHLAB_REFERENCE_STAGES= -DCLOTHLAB_RENDER=OFF 2>&1 | tee "$build.configure.log"
# The reference objects link only with the compiler that made them; another compiler here means every
# stage is graded with the submission's own code for the other stages (cmake/stages.cmake warns).
if tr -s " \n" " " <"$build.configure.log" | grep -q "they are not used"; then
  echo "warning: the reference objects do not match this image's compiler; release the bundle from a build with $(c++ --version | head -1)" >&2
fi
cmake --build "$build" -j "$(nproc)" --target clothlab-grade clothlab-grade-kit
# Gradescope's Docker forbids the namespaces bubblewrap needs: the grader uses its container mode
# (docs/grading.md, "Two confinements"), which runs each program as a user of its own. That user must
# pass every folder above the build (o+x); and where Landlock is missing, the instructor's files (the
# points and the experiments' grading code in tests/, read by the build alone) must be root's alone.
for d in "$build" "$build/grade-kit" "$src" "$src/clothlab"; do
  while [[ $d != / && $d != . ]]; do chmod o+x "$d"; d=$(dirname "$d"); done
done
chmod -R go-rwx "$src/clothlab/tests"
"$build/bin/clothlab-grade" --which-sandbox --kit "$build/grade-kit/kit.json" | sed 's/^/the grader here: /' || true
echo "clothlab autograder ready: $build/grade-kit/kit.json"
