#!/usr/bin/env bash
# Inputs the fuzzer found (tests/fuzz/regressions/NAME.json, in scene_fuzz's format: the scene text,
# then each --set override after a NUL byte), run through the command line: each gives exit 1 and the
# one line `error: <file>: <field>: <reason>` that starts with NAME.expect's text after the file name
# (or, when NAME.expect says `loads`, runs one step and exits 0).
set -u
exe=$1; dir=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0; fail=0
for input in "$dir"/*.json; do
  name=$(basename "$input" .json)
  [[ -f $dir/$name.expect ]] || { fail=$((fail+1)); echo "FAIL: $name: no $name.expect"; continue; }
  expect=$(head -1 "$dir/$name.expect")
  # Split as scene_fuzz does: the parts between NUL bytes (a NUL at the end leaves an empty override).
  { cat "$input"; printf '\0'; } >"$tmp/raw"
  sets=(); first=1
  while IFS= read -r -d '' part; do
    if ((first)); then printf '%s' "$part" >"$tmp/$name.json"; first=0; else sets+=(--set "$part"); fi
  done <"$tmp/raw"
  "$exe" run "$tmp/$name.json" --steps 1 --quiet "${sets[@]}" >"$tmp/out" 2>"$tmp/err"
  code=$?
  if [[ $expect == loads ]]; then
    if [[ $code -eq 0 ]]; then pass=$((pass+1)); else fail=$((fail+1)); echo "FAIL: $name: want it to load and run, exit $code: $(cat "$tmp/err")"; fi
  elif [[ $code -ne 1 || $(grep -ac '^error: ' "$tmp/err") -ne 1 || $(wc -l <"$tmp/err") -ne 1 ]]; then
    fail=$((fail+1)); echo "FAIL: $name: want exit 1 and one error line, got exit $code: $(head -c 600 "$tmp/err")"
  elif ! grep -aqF "error: $tmp/$name.json: $expect" "$tmp/err"; then
    fail=$((fail+1)); echo "FAIL: $name: want 'error: $tmp/$name.json: $expect...', got: $(cat "$tmp/err")"
  else
    pass=$((pass+1))
  fi
done
echo "fuzz regressions: $pass ok, $fail failing"
[[ $fail -eq 0 && $pass -gt 0 ]]
