#!/usr/bin/env bash
# Every attack proven live: each attack of tests/instructor/hostile/attacks.tsv is graded by
# clothlab-grade-weakened (a test tool: tests/sandbox/CMakeLists.txt) with the defence its `defence`
# column names switched off, and must then bite. The lint is off in every run here (CLOTHLAB_WEAKEN=
# lint,DEFENCE): it is a help for students, no defence, so no attack may need it to score 0.
# An attack bites when, with its defence off, it
#   - earns points on the stage it attacks, or
#   - changes the points of another stage (defence column `NAME:NN`: stage NN is graded too, and
#     compared with the reference graded in the same run), or
#   - hands out the reference: its failure messages hold a line of its stage's reference solution
#     that the stub does not have, or
#   - says it escaped ("ESCAPED: ..." in a failure message), or leaves a file named clothlab-hostile*
#     or clothlab-escape* in /tmp, /var/tmp or /dev/shm, or
#   - changes the instructor's tree: the copy of it that these runs grade with (its points, tests,
#     reference; graded alone, also when the grading then stops), or
#   - keeps the grading from ending (defence `time`: the run is stopped after $bound s).
# An attack that does not bite fails this test by name ("DEAD: NAME"): it no longer tests its
# defence. attacks.tsv's expect `dead` marks the ones known not to bite (README: why); such an attack
# that bites fails the test too, so that the mark is removed. With every defence on, the same attacks score 0 (hostile_test.sh, the red team).
# Defences this test does not switch off (attacks.tsv, README "Every attack proven live"):
#   -                          a robustness case, aimed at no defence (a crash, the benign files)
#   landlock, container-seccomp, uid   container mode's own: grade.container_mode_defences_are_load_bearing
#   pid                        bubblewrap's PID namespace, with kill_other_runs: grade.pid_namespace_is_load_bearing
#   memory, file-size, processes       the shared machine's memory, disk or process table would pay: named, not run
#   names                      two students' file names (--class): grade.class_gradebook grades both
# With --plant-dead, a copy of defines_other_stage whose stage-04 functions all gained a parameter (a
# signature changed under it, as an attack kept by hand would be) is graded beside them as
# `planted_dead`; the test then passes only when it names exactly that attack dead.
# Usage: hostile_live_test.sh SOURCE_DIR WEAKENED_GRADER KIT [name-regex] [--plant-dead]
set -u
root=$(cd "$1" && pwd) grader=$(realpath "$2") kit=$(realpath "$3") only=${4:-.} plant=${5:-}  # absolute: the attacks look for them
hostile=$root/tests/instructor/hostile
bound=150
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
chmod 711 "$tmp"
fail() { echo "FAIL: $*"; exit 1; }
[[ -x $grader ]] || fail "no $grader (build clothlab-grade-weakened)"

# The instructor's tree and kit these runs grade with are copies in $tmp: with a defence off an attack
# may write, delete or kill there, never in SOURCE_DIR. The copy of the tree (what the graded kit
# names: stubs, reference, public headers, tests, points, the attack snippets) is where the attacks
# are put together from (@TREE@) and what the kit's points folder and the compile view point into;
# the kit's objects stay where the build put them (read-only in every view). $tmp/CMakeCache.txt
# names the copy, as the build's does the tree: it is the first one above the test binaries (in
# $tmp/out_*) and above the kit, where the attacks that look for the tree find it.
tree=$tmp/tree
mkdir -p "$tree/tests" "$tree/framework" "$tmp/build/grade-kit" "$tmp/build/tests"
cp -r "$root/exercises" "$root/solutions" "$tree/" && cp -r "$root/framework/include" "$tree/framework/" \
  && cp "$root"/tests/*.* "$tree/tests/" && cp -r "$root/tests/instructor" "$tree/tests/" \
  && cp -r "$(dirname "$kit")/../tests/generated" "$tmp/build/tests/" || fail "cannot copy the tree and the kit into $tmp"
jq --arg p "$tree/tests" '.points_dir = $p' "$kit" >"$tmp/build/grade-kit/kit.json" || fail "$kit: not a kit"
kit=$tmp/build/grade-kit/kit.json
echo "CMAKE_HOME_DIRECTORY:INTERNAL=$tree" >"$tmp/CMakeCache.txt"
chmod -R go-w "$tree"  # root's files, as the instructor's are: user nobody may read them, not change them
# The tree copy's files and their checksums: an attack that changes them bites (then the copy is renewed).
tree_sums() { (cd "$tree" && find . -type f -print0 | sort -z | xargs -0 cksum); }
tree_sums >"$tmp/tree_sums"
restore_tree() {  # the next run starts from the untouched copy
  [[ $(tree_sums) == "$(cat "$tmp/tree_sums")" ]] && return
  rm -rf "$tree/tests" && mkdir "$tree/tests" && cp "$root"/tests/*.* "$tree/tests/" && cp -r "$root/tests/instructor" "$tree/tests/"
  rm -rf "$tree/exercises" "$tree/solutions" "$tree/framework/include" && cp -r "$root/exercises" "$root/solutions" "$tree/" \
    && cp -r "$root/framework/include" "$tree/framework/" && chmod -R go-w "$tree"
  [[ $(tree_sums) == "$(cat "$tmp/tree_sums")" ]] || fail "cannot restore the copy of the tree in $tree"
}

declare -A stage_of=() defence_of=() known_dead=()  # known_dead: attacks.tsv's expect `dead` (README: why)
groups=()
assemble() {  # assemble STUDENT SNIPPET-NAME STAGE: the reference with the attacked stage's folder replaced
  bash "$tree/tests/instructor/assemble_attack.sh" "$tree" "$2" "$3" "$tmp/attack_$1" || fail "attacks.tsv: $2: cannot put the attack together"
  local dir; dir=$(cd "$tmp/attack_$1" && ls -d "$3"_*/)
  mkdir -p "$tmp/sub_$1" && cp -r "$root"/solutions/[0-9][0-9]_* "$tmp/sub_$1/"
  rm -rf "${tmp:?}/sub_$1/${dir%/}" && cp -r "$tmp/attack_$1/${dir%/}" "$tmp/sub_$1/"
}
skipped=()
while IFS=$'\t' read -r name stage defence what expect; do
  [[ $name == name || -z $name || ! $name =~ $only || $name == benign || ${expect:-} == known-open ]] && continue
  [[ ${expect:-} == dead ]] && known_dead[$name]=1
  case ${defence%%:*} in
    -) continue ;;
    landlock|container-seccomp|uid|memory|file-size|processes|names) skipped+=("$name ($defence)"); continue ;;
  esac
  assemble "$name" "$name" "$stage"
  stage_of[$name]=$stage defence_of[$name]=$defence
  [[ " ${groups[*]} " == *" $defence "* ]] || groups+=("$defence")
done <"$hostile/attacks.tsv"
if [[ $plant == --plant-dead ]]; then
  assemble planted_dead defines_other_stage 01
  # Every stage-04 function pulled in by //@stub 04 gains a parameter: overloads now, no collision.
  f=$(ls "$tmp"/sub_planted_dead/01_*/*.cpp)
  awk '/ATTACK: stage 04/ { s = 1 } s && /\) \{$/ { sub(/\) \{$/, ", int planted) {") } { print }' "$f" >"$f.new" && mv "$f.new" "$f"
  grep -q "int planted) {" "$f" || fail "--plant-dead: no stage-04 function found in the assembled defines_other_stage"
  stage_of[planted_dead]=01 defence_of[planted_dead]=$(awk -F'\t' '$1 == "defines_other_stage" { print $3 }' "$hostile/attacks.tsv")
  [[ " ${groups[*]} " == *" ${defence_of[planted_dead]} "* ]] || groups+=("${defence_of[planted_dead]}")
fi
((${#stage_of[@]})) || fail "no attack matches '$only'"

# The lines of a stage's reference that its stub does not have (longer than 25 characters): one of
# them in a failure message hands the reference out.
reference_lines() {
  local nn=$1
  cat "$root"/exercises/"$nn"_*/*.cpp | sed 's/^[[:space:]]*//' | sort -u >"$tmp/stub_$nn"
  sed 's/^[[:space:]]*//' "$root"/solutions/"$nn"_*/*.cpp | grep -v '^//' | awk 'length > 25' | sort -u | comm -23 - "$tmp/stub_$nn"
}
# `network`: an endpoint on the machine's loopback (tcp 127.0.0.1:47613, socket_connect's target) that
# greets whoever connects. Inside the sandbox's own network namespace nothing listens there; with the
# machine's network in view the attack reaches it and says so ("ESCAPED: ... it said: ...").
listener=""
if [[ " ${groups[*]} " == *network* ]]; then
  python3 -c '
import socket, sys
s = socket.socket(); s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
try: s.bind(("127.0.0.1", 47613))
except OSError as e: print(e); sys.exit(1)
s.listen(16); print("listening", flush=True)
while True:
    c, _ = s.accept(); c.settimeout(2)
    try: c.sendall(b"the red team live test endpoint\n"); c.recv(65536)
    except OSError: pass
    c.close()' >"$tmp/listener.log" 2>&1 &
  listener=$!
  trap 'kill "$listener" 2>/dev/null; rm -rf "$tmp"' EXIT
  for _ in $(seq 50); do grep -q listening "$tmp/listener.log" && break; kill -0 "$listener" 2>/dev/null || break; sleep 0.1; done
  grep -q listening "$tmp/listener.log" || fail "network: cannot listen on 127.0.0.1:47613: $(cat "$tmp/listener.log")"
fi
escapes() { ls -d /tmp/clothlab-hostile* /tmp/clothlab-escape* /var/tmp/clothlab-hostile* /var/tmp/clothlab-escape* \
               /dev/shm/clothlab-hostile* /dev/shm/clothlab-escape* 2>/dev/null; }
escapes >"$tmp/escapes_before"

bad=0 dead=()
for g in "${groups[@]}"; do
  switch=${g%%:*} victim=""; [[ $g == *:* ]] && victim=${g#*:}
  members=(); for a in "${!defence_of[@]}"; do [[ ${defence_of[$a]} == "$g" ]] && members+=("$a"); done
  # One run per attacked stage (each student graded on that stage only, and the victim stage); `time`:
  # one run per attack (a run that does not end says nothing about its neighbours).
  runs=()
  if [[ $switch == time ]]; then runs=("${members[@]}"); else
    for s in $(for a in "${members[@]}"; do echo "${stage_of[$a]}"; done | sort -u); do
      run=""; for a in "${members[@]}"; do [[ ${stage_of[$a]} == "$s" ]] && run+=" $a"; done
      runs+=("${run# }")
    done
  fi
  for run in "${runs[@]}"; do
    class=$tmp/class_${switch//+/_}_${run%% *}; out=$tmp/out_${switch//+/_}_${run%% *}
    mkdir -p "$class"
    stages=()
    for a in $run; do
      mv "$tmp/sub_$a" "$class/$a"
      [[ " ${stages[*]} " == *" ${stage_of[$a]} "* ]] || stages+=("${stage_of[$a]}")
    done
    if [[ -n $victim ]]; then
      mkdir -p "$class/reference" && cp -r "$root"/solutions/[0-9][0-9]_* "$class/reference/"
      [[ " ${stages[*]} " == *" $victim "* ]] || stages+=("$victim")
    fi
    args=(); for s in "${stages[@]}"; do args+=(--stage "$s"); done
    limit=1800; [[ $switch == time ]] && limit=$bound
    (CLOTHLAB_WEAKEN=lint,${switch//+/,} timeout -s KILL "$limit" "$grader" --kit "$kit" --class "$class" --out "$out" \
      --timeout 8 "${args[@]}" >"$tmp/grade.log" 2>&1) 2>/dev/null  # (no "Killed" line from the shell)
    rc=$?
    if [[ $switch == time ]]; then
      if ((rc == 137)); then echo "live: $run ($g): the grading did not end within $bound s"
      elif [[ -n ${known_dead[$run]:-} ]]; then echo "KNOWN DEAD: $run ($g): the grading ended (attacks.tsv: dead)"
      else dead+=("$run ($g): the grading ended (status $rc)"); fi
      continue
    fi
    changed=$(tree_sums | diff "$tmp/tree_sums" - | sed -n 's/^[<>] [0-9]* [0-9]* \.\///p' | sort -u | head -1)
    if ((rc != 0)) && [[ -n $changed && $run != *" "* ]]; then  # it damaged the tree so that the grading stopped
      if [[ -n ${known_dead[$run]:-} ]]; then echo "$run bites now: remove 'dead' from its row in attacks.tsv and from README"; bad=1
      else echo "live: $run ($g): changed the instructor's tree (its copy): $changed; the grading stopped: $(tail -1 "$tmp/grade.log")"; fi
      escapes | comm -13 "$tmp/escapes_before" - | xargs -r rm -rf
      restore_tree
      continue
    fi
    ((rc == 0)) || { tail -20 "$tmp/grade.log"; fail "the weakened grading run ($g) failed"; }
    book=$out/gradebook.csv
    IFS=, read -r -a H <"$book"
    col() { local i; for ((i = 1; i < ${#H[@]}; i++)); do [[ ${H[$i]} == "$1" ]] && { echo $((i + 1)); return; }; done; }
    for a in $run; do
      s=${stage_of[$a]} why=""
      got=$(grep "^$a," "$book" | cut -d, -f"$(col "$s")")
      awk -v p="$got" 'BEGIN { exit !(p > 0) }' && why="$got points on stage $s"
      if [[ -z $why && -n $victim ]]; then
        mine=$(grep "^$a," "$book" | cut -d, -f"$(col "$victim")") ref=$(grep "^reference," "$book" | cut -d, -f"$(col "$victim")")
        [[ $mine != "$ref" ]] && why="stage $victim scores $mine, the reference $ref"
      fi
      fb=$out/feedback/$a.json
      jq -r '.. | .message? // empty' "$fb" >"$tmp/messages" 2>/dev/null
      if [[ -z $why ]] && grep -q "ESCAPED:" "$tmp/messages"; then why="$(grep -m1 -o 'ESCAPED:.\{0,60\}' "$tmp/messages")"; fi
      if [[ -z $why ]]; then
        reference_lines "$s" >"$tmp/ref_lines"
        line=$(grep -F -x -f "$tmp/ref_lines" <(sed 's/^[[:space:]]*//' "$tmp/messages") | head -1)
        [[ -n $line ]] && why="its failure message hands out the reference: ${line:0:60}"
      fi
      # (a change is told only of an attack graded alone: it cannot say which of several made it)
      if [[ -z $why && -n $changed && $run == "$a" ]]; then why="changed the instructor's tree (its copy): $changed"; fi
      new=$(escapes | comm -13 "$tmp/escapes_before" -)
      if [[ -z $why && -n $new ]]; then why="left $(echo "$new" | head -1)"; fi
      if [[ -n $why && -n ${known_dead[$a]:-} ]]; then
        echo "$a bites now ($why): remove 'dead' from its row in attacks.tsv and from README"; bad=1
      elif [[ -n $why ]]; then echo "live: $a ($g): $why"
      elif [[ -n ${known_dead[$a]:-} ]]; then echo "KNOWN DEAD: $a ($g): 0 points on stage $s, nothing else changed (attacks.tsv: dead)"
      else dead+=("$a ($g): 0 points on stage $s, nothing else changed"); fi
    done
    escapes | comm -13 "$tmp/escapes_before" - | xargs -r rm -rf
    restore_tree
  done
done
for s in "${skipped[@]}"; do echo "not switched off here: $s"; done
for d in "${dead[@]}"; do echo "DEAD: $d"; done
if [[ $plant == --plant-dead ]]; then
  [[ ${#dead[@]} == 1 && ${dead[0]} == "planted_dead "* ]] \
    || fail "the planted dead attack must be the one named dead (and only it): ${dead[*]:-none}"
  echo "the planted dead attack (defines_other_stage with changed stage-04 signatures) is named dead; every other attack bites with its defence off"
  exit 0
fi
((bad == 0)) || fail "an attack marked dead bites (lines above)"
((${#dead[@]} == 0)) || fail "${#dead[@]} attack(s) do not bite with their defence off (lines above): each no longer tests its defence"
echo "$((${#stage_of[@]} - ${#known_dead[@]})) attacks, each graded with its defence off: every one bites (${#known_dead[@]} marked dead in attacks.tsv do not, as marked)"
