#!/usr/bin/env bash
# The docs' commands and the scene fields against the code:
#  1. the commands `./lab help` lists are the commands `lab` dispatches, and back, and so are those
#     of the `lab` line of docs/design.md's Layout (but help);
#  2. every `./lab X` and `build/bin/clothlab X` line in a code block of README.md, docs/*.md and the
#     task sheets names a command that exists (lab's dispatcher, clothlab's own --help);
#  3. the quick ones run, as shown, in a copy of the tree (so their out/ folders land in a temporary
#     folder): `./lab run` and `./lab hint`, each must exit 0 (or the code its comment names,
#     "# ... exit 3" for a run shown to be unstable);
#  4. every key the scene loader reads (framework/src/io/scene_json.cpp) is documented in
#     docs/scenes.md, and every key the Fields table documents is one the loader knows.
# Then it proves it fails on a planted unknown command and a planted undocumented scene field.
# Usage: docs_commands_check.sh SOURCE_DIR BUILD_DIR
set -u
shopt -s nullglob  # docs/instructor/ may hold no file yet
root=$1 build=$2
fail() { echo "FAIL: $*"; exit 1; }
[[ -x $build/bin/clothlab ]] || fail "$build/bin/clothlab is not built"

# The lines of the fenced code blocks of FILE that start with ./lab or build/bin/clothlab*
# (with their comments: doc_commands FILE keep).
doc_commands() {
  awk -v keep="${2:-}" '/^ *```/ { inb = !inb; next }
    inb && /^ *(\.\/lab |build\/bin\/clothlab)/ { sub(/^ */, ""); if (keep == "") sub(/ +#.*$/, ""); print }' "$1"
}
lab_dispatched() { sed -n 's/^  \([a-z|-]*\)) c=\$1.*/\1/p' "$1/lab" | tr '|' '\n' | sort -u; }
lab_listed() { "$1/lab" help | sed -n 's/^  \([a-z][a-z-]*\).*/\1/p' | sort -u; }
clothlab_listed() { "$build/bin/clothlab" --help | sed -n '/^Subcommands:/,$ s/^  \([a-z][a-z-]*\).*/\1/p' | sort -u; }

# check TREE: prints one line per problem, returns 1 if any
check_commands() {
  local tree=$1 bad=0 f line cmd sub
  local lab_cmds; lab_cmds=$(lab_dispatched "$tree")
  [[ $(lab_listed "$tree") == "$lab_cmds" ]] || {
    echo "lab: 'lab help' lists [$(lab_listed "$tree" | tr '\n' ' ')], the dispatcher runs [$(tr '\n' ' ' <<<"$lab_cmds")]"; bad=1; }
  # docs/design.md's Layout names them on its `lab` line (all but help).
  local layout; layout=$(sed -n 's/^lab  *the one entry point: \([a-z -]*\).*/\1/p' "$tree/docs/design.md" | tr ' ' '\n' | grep . | sort -u)
  [[ $layout == "$(grep -vx help <<<"$lab_cmds")" ]] || {
    echo "docs/design.md: the Layout's lab line lists [$(tr '\n' ' ' <<<"$layout")], the dispatcher runs [$(tr '\n' ' ' <<<"$lab_cmds")]"; bad=1; }
  local cl_cmds; cl_cmds=$(clothlab_listed)
  for f in "$tree/README.md" "$tree/README.student.md" "$tree"/docs/*.md "$tree"/docs/instructor/*.md "$tree"/exercises/*/README.md; do
    while IFS= read -r line; do
      read -r cmd sub _ <<<"$line"
      case $cmd in
        ./lab) grep -qx -- "$sub" <<<"$lab_cmds" || { echo "${f#$tree/}: '$line': lab has no command '$sub'"; bad=1; } ;;
        build/bin/clothlab) grep -qx -- "$sub" <<<"$cl_cmds" || { echo "${f#$tree/}: '$line': clothlab has no command '$sub'"; bad=1; } ;;
      esac
    done < <(doc_commands "$f")
  done
  return $bad
}

# The keys the loader reads: r.number("k", ...), .object("k"), .get("k"), ... in scene_json.cpp.
loader_keys() { grep -oE '\.(number|integer|boolean|choice|text|vec3|object|get|has)\("[a-z_]+"' "$1" | sed -E 's/.*\("//; s/"$//' | sort -u; }
# Every string literal of the loader and the names it parses (methods in core/scene.cpp, kernels
# registered at the extension point): the keys and the values it accepts.
loader_words() {
  local src; src=$(dirname "$1")/../..
  cat "$1" "$src/src/core/scene.cpp" "$src/../solutions/kernels/register_batched.cpp" "$src/src/sim/kernel_registry.cpp" 2>/dev/null \
    | grep -oE '"[a-z][a-z0-9_-]*"' | tr -d '"' | sort -u
}
# Every word inside a `code span` of a Markdown file.
code_words() { grep -oE '`[^`]+`' "$1" | tr -c 'a-z0-9_\n-' ' ' | tr ' ' '\n' | grep -E '^[a-z][a-z0-9_-]*$' | sort -u; }
# The Fields table of docs/scenes.md: the backticked words of its rows.
documented_words() { sed -n '/^## Fields/,/^### /p' "$1" | grep '^|' | grep -oE '`[a-z][a-z0-9_-]*`' | tr -d '`' | sort -u; }

check_fields() {  # check_fields LOADER.cpp SCENES.md
  local bad=0 k
  local doc; doc=$(code_words "$2")
  for k in $(loader_keys "$1"); do
    grep -qx -- "$k" <<<"$doc" || { echo "docs/scenes.md: the scene key '$k' is read by the loader but not documented"; bad=1; }
  done
  local words; words=$(loader_words "$1")
  for k in $(documented_words "$2"); do
    grep -qx -- "$k" <<<"$words" || { echo "docs/scenes.md: the Fields table documents '$k', which the loader does not know"; bad=1; }
  done
  return $bad
}

out=$(check_commands "$root") || { echo "$out"; fail "the docs name commands that do not exist"; }
out=$(check_fields "$root/framework/src/io/scene_json.cpp" "$root/docs/scenes.md") \
  || { echo "$out"; fail "docs/scenes.md and the scene loader disagree"; }

# 3. Run the quick commands as shown, in a copy of the tree whose build/ is this build.
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
(cd "$root" && git ls-files -z | xargs -0 cp --parents -t "$tmp/" 2>/dev/null) || cp -r "$root/." "$tmp/"
rm -rf "$tmp/build" && ln -s "$(cd "$build" && pwd)" "$tmp/build"
ran=0
for f in "$tmp/README.md" "$tmp/README.student.md" "$tmp"/docs/*.md "$tmp"/docs/instructor/*.md "$tmp"/exercises/*/README.md; do
  while IFS= read -r raw; do
    line=${raw%% #*} want=0
    [[ $raw =~ \#.*exit\ ([0-9]+) ]] && want=${BASH_REMATCH[1]}
    read -r cmd sub _ <<<"$line"
    [[ $cmd == ./lab && ( $sub == run || $sub == hint ) ]] || continue
    [[ $sub == hint ]] && line="$line --exercises $tmp/exercises"
    (cd "$tmp" && CLOTHLAB_NO_BUILD=1 timeout 300 bash -c "$line" >"$tmp/cmd.log" 2>&1 </dev/null)
    rc=$?
    ((rc == want)) || { tail -5 "$tmp/cmd.log"; fail "${f#$tmp/}: '$line' exited with $rc (want $want)"; }
    ran=$((ran + 1))
  done < <(doc_commands "$f" keep)
done
((ran >= 5)) || fail "only $ran documented ./lab run commands found (the extraction broke?)"

# The checks catch what they are for: a planted unknown command and a planted undocumented field
# (in the copy of the tree).
printf '\n```sh\n./lab runn scenes/spring.json\n```\n' >>"$tmp/README.md"
out=$(check_commands "$tmp") && fail "a planted './lab runn' in README.md is not caught"
grep -q "no command 'runn'" <<<"$out" || fail "the planted command's message does not name it: $out"
loader=$tmp/framework/src/io/scene_json.cpp
sed -i 's/number("dt"/number("dt_planted"/' "$loader"
grep -q dt_planted "$loader" || fail "could not plant an undocumented field (the loader reads dt differently?)"
out=$(check_fields "$loader" "$tmp/docs/scenes.md") && fail "a planted undocumented scene key is not caught"
grep -q "'dt_planted'" <<<"$out" || fail "the planted key is not named: $out"
echo "the docs' commands exist ($ran quick ones ran as shown), the scene fields are documented and parsed (planted mistakes caught)"
