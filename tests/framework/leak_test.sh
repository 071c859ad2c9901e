#!/usr/bin/env bash
# clothlab-leak-check finds a reference function body planted into a copy, also when it is reformatted
# and renamed; it passes a clean copy and rejects bad input with one error line.
set -u
check=$1; root=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail=0
bad() { echo "FAIL: $*"; fail=1; }

# A small clean copy: the stubs, their task sheets and a framework file that is no solution.
mkdir -p "$tmp/copy/framework/src/core"
cp -r "$root/exercises" "$tmp/copy/"
cp "$root/framework/src/core/grid.cpp" "$tmp/copy/framework/src/core/"
"$check" "$root" "$tmp/copy" >"$tmp/out" 2>&1 || bad "a clean copy is reported: $(cat "$tmp/out")"

# Plant the body of stage 02's addClothSpringForces (task 2.2) into the framework file.
body=$(sed -n '/^void addClothSpringForces(/,/^}/p' "$root/solutions/02_mfn/mfn.cpp" | sed '1d;$d')
[[ -n $body ]] || bad "no addClothSpringForces in solutions/02_mfn/mfn.cpp (update this test)"
cp "$tmp/copy/framework/src/core/grid.cpp" "$tmp/grid.cpp"
printf '\nnamespace clothlab {\nvoid sumForces(const std::vector<Spring>& springs, const Matrix3X& x, const Matrix3X& v, Matrix3X& f) {\n%s\n}\n}\n' \
  "$body" >>"$tmp/copy/framework/src/core/grid.cpp"
"$check" "$root" "$tmp/copy" >"$tmp/out" 2>&1
code=$?
[[ $code -eq 1 ]] || bad "planted body: exit $code (want 1): $(cat "$tmp/out")"
grep -q "^leak: framework/src/core/grid.cpp:[0-9]*: .*addClothSpringForces() in solutions/02_mfn/mfn.cpp" "$tmp/out" \
  || bad "planted body: the report should name the file and addClothSpringForces: $(cat "$tmp/out")"

# The same body on one line, its comments gone, in a header under another name: still found.
cp "$tmp/grid.cpp" "$tmp/copy/framework/src/core/grid.cpp"
printf '%s\n' "$body" | sed 's|//.*||' | tr -s ' \n' ' ' >"$tmp/copy/framework/src/core/helpers.h"
"$check" "$root" "$tmp/copy" >"$tmp/out" 2>&1
[[ $? -eq 1 ]] && grep -q "^leak: framework/src/core/helpers.h:1: .*addClothSpringForces()" "$tmp/out" \
  || bad "reformatted body: $(cat "$tmp/out")"

# Bad input: one error line, exit 2.
"$check" "$root" "$tmp/nope" >"$tmp/out" 2>&1
[[ $? -eq 2 && $(grep -c "^error: command line: $tmp/nope: (folder)" "$tmp/out") -eq 1 ]] || bad "missing copy: $(cat "$tmp/out")"
"$check" "$root" "$tmp/copy" --window x >"$tmp/out" 2>&1
[[ $? -eq 2 ]] && grep -q "^error: command line: --window" "$tmp/out" || bad "bad --window: $(cat "$tmp/out")"

[[ $fail -eq 0 ]] && echo "ok: the leak check finds a planted reference body (also reformatted), passes a clean copy"
exit $fail
