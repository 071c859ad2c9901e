#!/usr/bin/env bash
# The tests write only into temp or build folders, never into the source tree.
#   source_tree_check.sh snapshot SRC FILE   records `git status` of the source tree in FILE (before the tests)
#   source_tree_check.sh compare  SRC FILE   fails when `git status` differs from FILE (after the tests)
set -u
mode=$1; src=$2; file=$3
# --no-optional-locks: do not write git's index while tests (and people) work in the tree.
status() { git --no-optional-locks -C "$src" status --porcelain --untracked-files=all; }
case $mode in
  snapshot)
    mkdir -p "$(dirname "$file")"
    status >"$file" || { echo "FAIL: git status in $src"; exit 1; }
    echo "recorded the state of $src ($(wc -l <"$file") changed or untracked files) in $file" ;;
  compare)
    [[ -f $file ]] || { echo "FAIL: $file: (file): no snapshot (the test hygiene.source_tree_snapshot did not run)"; exit 1; }
    status >"$file.after" || { echo "FAIL: git status in $src"; exit 1; }
    if ! cmp -s "$file" "$file.after"; then
      echo "FAIL: the test run changed the source tree $src (tests must write only into temp or build folders):"
      diff "$file" "$file.after" | sed -n 's/^</  before:/p; s/^>/  after: /p'
      exit 1
    fi
    echo "ok: the test run left the source tree unchanged" ;;
  *) echo "usage: source_tree_check.sh snapshot|compare SRC FILE"; exit 2 ;;
esac
