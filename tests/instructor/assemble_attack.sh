#!/usr/bin/env bash
# Puts one red-team submission together: the attack snippet tests/instructor/hostile/NAME.cpp applied to
# today's stub of its stage (exercises/NN_*/*.cpp), so no attack carries a copy of a stub and a changed
# signature reaches every attack by itself. Writes OUT/NN_stage/FILE.cpp.
# Usage: assemble_attack.sh SOURCE_DIR NAME STAGE OUT      (NAME as in attacks.tsv; benign: benign_NN)
# A snippet is C++ in sections, each opened by a marker line:
#   (before the first marker)  lines put at the top of the file
#   //@head       lines put after the stub's #includes (before `namespace clothlab {`)
#   //@each       lines put before every `throw NotImplemented(...)` of the stub
#   //@task N.M   lines put instead of task N.M's `throw NotImplemented(...)`
#   //@tail       lines put at the end of the file
#   //@no-stub    the lines after it are the whole file (an attack that needs no stub)
#   //@use NAME   (inside a section) the lines of tests/instructor/hostile/lib/NAME.cpp, shared by attacks
#   //@stub NN    (inside a section) today's stub of stage NN from its first #include on: another stage's
#                 functions with their signatures as the stage's header and stub spell them today
#   @TREE@        (anywhere) the absolute path of SOURCE_DIR: an attacker who knows where the instructor's
#                 tree is (the absolute-path attacks; without it their guesses hold on one machine only)
set -eu
root=$1 name=$2 stage=$3 out=$4
snippet=$root/tests/instructor/hostile/$name.cpp
[[ -f $snippet ]] || { echo "assemble_attack.sh: $snippet: no such attack snippet" >&2; exit 2; }
stub=$(ls "$root"/exercises/"$stage"_*/*.cpp 2>/dev/null | head -1)
[[ -n $stub ]] || { echo "assemble_attack.sh: no stub for stage $stage in $root/exercises" >&2; exit 2; }
dir=$out/$(basename "$(dirname "$stub")")
mkdir -p "$dir"
awk -v snippet="$snippet" -v libdir="$root/tests/instructor/hostile/lib" -v exercises="$root/exercises" -v tree="$(cd "$root" && pwd)" '
  BEGIN {
    sec = "top"
    while ((getline line < snippet) > 0) {
      gsub(/@TREE@/, tree, line)
      if (line ~ /^\/\/@(head|each|tail|no-stub)$/ || line ~ /^\/\/@task [0-9]+\.[0-9]+$/) { sec = substr(line, 4); have[sec] = 1; continue }
      if (line ~ /^\/\/@use [a-z_]+$/) {
        lib = libdir "/" substr(line, 8) ".cpp"
        if ((getline part < lib) <= 0) { print snippet ": " line ": no " lib > "/dev/stderr"; bad = 1; exit 2 }
        do text[sec] = text[sec] part "\n"; while ((getline part < lib) > 0)
        close(lib); continue
      }
      if (line ~ /^\/\/@stub [0-9][0-9]$/) {
        other = ""; cmd = "ls " exercises "/" substr(line, 9) "_*/*.cpp 2>/dev/null | head -1"; cmd | getline other; close(cmd)
        if (other == "") { print snippet ": " line ": no stub of that stage" > "/dev/stderr"; bad = 1; exit 2 }
        from = 0
        while ((getline part < other) > 0) if (from || (from = part ~ /^#include/)) text[sec] = text[sec] part "\n"
        close(other); continue
      }
      if (line ~ /^\/\/@/) { print snippet ": unknown section marker: " line > "/dev/stderr"; bad = 1; exit 2 }
      text[sec] = text[sec] line "\n"
    }
    if (have["no-stub"]) { printf "%s", text["no-stub"]; exit }
    printf "%s", text["top"]
  }
  have["no-stub"] { exit }
  /^namespace clothlab \{/ && !headDone { printf "%s", text["head"]; headDone = 1 }
  /throw NotImplemented\("exercise [0-9]+\.[0-9]+ / {
    task = $0; sub(/.*throw NotImplemented\("exercise /, "", task); sub(/ .*/, "", task)
    if (("task " task) in have) { printf "%s", text["task " task]; used["task " task] = 1; next }
    printf "%s", text["each"]
  }
  { print }
  END {
    if (bad) exit 2
    if (!have["no-stub"]) printf "%s", text["tail"]
    for (k in have) if (k ~ /^task / && !(k in used)) { print snippet ": //@" k ": the stub has no such task" > "/dev/stderr"; exit 2 }
    if (have["head"] && !headDone && !have["no-stub"]) { print snippet ": the stub has no `namespace clothlab {` for //@head" > "/dev/stderr"; exit 2 }
  }
' "$stub" >"$dir/$(basename "$stub")"
