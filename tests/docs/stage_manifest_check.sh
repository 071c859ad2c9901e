#!/usr/bin/env bash
# Every stage has a manifest, exercises/NN_name/stage.json (issue #27), and the files of the stage agree
# with it. The manifest (it ships to students: no answers, no expected values):
#   {"stage": "04",                                 the folder's number NN
#    "title": "Distance constraint",                 the title of tests/NN_name.points.json
#    "tasks": [{"task": "4.1", "title": "...",       every task N.M of the stage, in order
#               "functions": ["distanceConstraint"], the student functions of N.M, by name
#               "class": "formula"},                 formula | algorithm | short derivation | derivation
#              {"task": "4.4", ..., "bonus": true}], (docs/grading.md, "Points per task"); "bonus": optional
#    "header": "framework/include/clothlab/exercise/NN_name.h", "stub": "exercises/NN_name/FILE.cpp",
#    "points": "tests/NN_name.points.json", "hints": "exercises/NN_name/hints.json",
#    "mistakes": "tests/instructor/mistakes/NN_name.cmake",         these five paths: the conventional ones
#    "scenes": ["scenes/pbd_curtain.json", ...]}                     the scenes the stage's sheet and answers use
# Checked, per stage, one line per disagreement (naming the file that disagrees):
#   - the manifest: valid JSON, the keys above and no other, the paths the conventional ones;
#   - the header: every declaration under a "/// Exercise N.M —" (or "/// Bonus N.Ma —", for a bonus task)
#     comment is a function listed under task N.M, and every listed function is declared so;
#   - the stub: it exists, with a "// TODO N.M" per task and no TODO of another task;
#   - the points file: the same title; every task has at least one test, TaskN_M_* under "tests" (a
#     bonus task: BonusN_M_* under "bonus"), and every test's suite is one of a listed task or Experiments;
#   - hints.json: its keys are the tasks;
#   - the sheet (README.md): the rows of its Points table ("| task | what | points |" in "## Before you
#     start") are the tasks, "N.M (bonus)" exactly for a bonus task;
#   - docs/grading.md's class table (| task | class | why |, under "## Points per task"; a row names its
#     tasks as "1.1 Hooke force, 1.2 spring damping" or "7.2–7.4 ..."): each task there has the class its
#     manifest gives; every task that is not a bonus task is there; every task there is in a manifest
#     (a bonus task may be left out of the table: it is graded beside the stage's points);
#   - the mistakes file exists and has at least one clothlab_mistake(...) (not where tests/instructor/ is
#     left out: the student copy);
#   - every listed scene exists, and every scene that the sheet's "## Run it" section, a `./lab ...`
#     command of the sheet or a "how" command of answers.json names is listed.
# Then it proves it catches planted mismatches, each in a fresh copy: a function renamed in a header, a
# hints key removed, a listed scene missing, a used scene not listed, a class changed in a manifest and in
# the table's range row "7.2–7.4", a points suite of no task, a TODO removed, a sheet row renumbered, a
# manifest key misspelt, and the bonus mark dropped.
# Usage: stage_manifest_check.sh SOURCE_DIR
set -u
export LC_ALL=C.UTF-8
root=$1
[[ -d $root/exercises ]] || { echo "error: $root/exercises: no such folder"; exit 2; }
command -v jq >/dev/null || { echo "error: jq is not installed"; exit 2; }

work=$(mktemp -d); trap 'rm -rf "$work"' EXIT

# The manifest's own shape. Arguments: $name (NN_name), $nn (NN). One line per problem.
VALIDATE='
def classes: ["formula", "algorithm", "short derivation", "derivation"];
def top: ["stage", "title", "tasks", "header", "stub", "points", "hints", "mistakes", "scenes"];
def conv($key; $want): if has($key) and .[$key] != $want then "\($key): \(.[$key] | tojson), but the stage'"'"'s file is \($want | tojson)" else empty end;
def dups: group_by(.) | map(select(length > 1) | .[0]) | .[];
if type != "object" then "not a JSON object" else
  (keys - top | .[] | "unknown key \(tojson) (the keys: \(top | join(", ")))"),
  (top - keys | .[] | "no key \(tojson)"),
  conv("stage"; $nn),
  conv("header"; "framework/include/clothlab/exercise/\($name).h"),
  conv("points"; "tests/\($name).points.json"),
  conv("hints"; "exercises/\($name)/hints.json"),
  conv("mistakes"; "tests/instructor/mistakes/\($name).cmake"),
  (if has("stub") and ((.stub | type) != "string" or (.stub | test("^exercises/\($name)/[^/]+\\.cpp$") | not))
   then "stub: \(.stub | tojson) is not exercises/\($name)/FILE.cpp" else empty end),
  (if has("title") and ((.title | type) != "string" or .title == "") then "title: not a non-empty string" else empty end),
  (if has("scenes") then
     if (.scenes | type) != "array" then "scenes: not a list"
     else (.scenes[] | select(type != "string" or (test("^scenes/[^/]+\\.json$") | not)) | "scenes: \(tojson) is not scenes/NAME.json"),
          (.scenes | map(tostring) | dups | "scenes: \(tojson) is listed twice")
     end
   else empty end),
  (if has("tasks") then
     if (.tasks | type) != "array" or (.tasks | length) == 0 then "tasks: not a non-empty list"
     else
       ($nn | tonumber | tostring) as $n |
       (.tasks | to_entries[] | .key as $i | .value as $t | "tasks[\($i)]" as $at |
         if ($t | type) != "object" then "\($at): not an object" else
           ($t | keys - ["task", "title", "functions", "class", "bonus"] | .[] | "\($at): unknown key \(tojson)"),
           (["task", "title", "functions", "class"] - ($t | keys) | .[] | "\($at): no key \(tojson)"),
           (if ($t | has("task")) and (($t.task | type) != "string" or ($t.task | test("^\($n)\\.[0-9]+$") | not))
            then "\($at): task \($t.task | tojson) is not \"\($n).M\"" else empty end),
           (if ($t | has("title")) and (($t.title | type) != "string" or $t.title == "") then "\($at): title: not a non-empty string" else empty end),
           (if ($t | has("functions")) and (($t.functions | type) != "array" or ($t.functions | length) == 0
                or ($t.functions | any(type != "string" or (test("^[A-Za-z_][A-Za-z0-9_]*$") | not))))
            then "\($at): functions: not a non-empty list of C++ names" else empty end),
           (if ($t | has("class")) and ([$t.class] | inside(classes) | not) then "\($at): class \($t.class | tojson) is not one of \(classes | join(", "))" else empty end),
           (if ($t | has("bonus")) and ($t.bonus | type) != "boolean" then "\($at): bonus: not true or false" else empty end)
         end),
       (.tasks | map(.task? // empty | tostring) | dups | "tasks: task \(tojson) is listed twice"),
       (.tasks | map(.functions? // [] | if type == "array" then .[] else empty end | tostring) | dups | "tasks: function \(tojson) is listed twice")
     end
   else empty end)
end'

# The manifest's facts, one a line: T<TAB>N.M<TAB>task|bonus<TAB>CLASS, F<TAB>N.M<TAB>FUNCTION, S<TAB>SCENE,
# X<TAB>STUB.
FACTS='((.tasks[] | ["T", .task, (if .bonus then "bonus" else "task" end), .class]),
        (.tasks[] | .task as $t | .functions[] | ["F", $t, .]), (.scenes[] | ["S", .]), ["X", .stub] | @tsv)'

# class_table TREE: TASK<TAB>CLASS per task of docs/grading.md's class table (ranges "7.2–7.4" expanded).
class_table() {
  [[ -f $1/docs/grading.md ]] || return 0
  perl -CSD -Mutf8 -ne '
    if (/^## /) { $sec = /^## Points per task/; $in = 0; next }
    next unless $sec;
    if (/^\| task \| class \| why \|$/) { $in = 1; $sep = 1; next }
    if ($in && $sep) { $sep = 0; next }
    if ($in && !/^\|/) { $in = 0; next }
    next unless $in;
    my @c = split /\|/; my ($tasks, $class) = ($c[1] // "", $c[2] // ""); $class =~ s/^\s+|\s+$//g;
    my $any = 0;
    while ($tasks =~ /(\d+)\.(\d+)(?:\s*[–-]\s*(\d+)\.(\d+))?/g) {
      my ($n, $a, $n2, $b) = ($1, $2, $3 // $1, $4 // $2); $any = 1;
      if ($n2 != $n || $b < $a) { print "?\t$&\t$class\n"; next }
      print "$n.$_\t$class\n" for $a .. $b;
    }
    $tasks =~ s/^\s+|\s+$//g; print "?\t$tasks\t$class\n" unless $any;' "$1/docs/grading.md"
}

# header_functions HEADER: TAG<TAB>TASK<TAB>FUNCTION per "/// Exercise N.M —" / "/// Bonus N.Ma —" comment:
# the function declared on the first line after it that is no comment and has a "(" ("?" when none).
header_functions() {
  awk '
    function flush() { if (tag != "") print tag "\t" task "\t?"; tag = "" }
    /^[[:space:]]*\/\/\/[[:space:]]*(Exercise|Bonus)[[:space:]]+[0-9]+\.[0-9]+[a-z]?[[:space:]]/ {
      flush(); line = $0; sub(/^[[:space:]]*\/\/\/[[:space:]]*/, "", line)
      split(line, w, /[[:space:]]+/); tag = w[1]; task = w[2]; sub(/[a-z]$/, "", task); next }
    tag != "" && !/^[[:space:]]*\/\// && /\(/ {
      decl = $0; sub(/\(.*/, "", decl)
      if (match(decl, /[A-Za-z_][A-Za-z0-9_]*[[:space:]]*$/)) { name = substr(decl, RSTART, RLENGTH); gsub(/[[:space:]]/, "", name) }
      else name = "?"
      print tag "\t" task "\t" name; tag = "" }
    END { flush() }' "$1"
}

# sheet_facts SHEET: from the task sheet, in one pass: "row<TAB>CELL" per row of the Points table in
# "## Before you start" whose first cell starts with a digit, and "scene<TAB>scenes/X.json" per scene
# its "## Run it" section or a line with a `./lab ...` command names.
sheet_facts() {
  awk '
    /^## / { sec = $0; intable = 0 }
    sec ~ /^## Before you start/ && /^\| task \| what \| points \|$/ { intable = 1; skip = 1; next }
    intable && skip { skip = 0; next }
    intable && !/^\|/ { intable = 0 }
    intable { split($0, c, "|"); t = c[2]; gsub(/^[ *]+|[ *]+$/, "", t); if (t ~ /^[0-9]/) print "row\t" t }
    sec ~ /^## Run it/ || /\.\/lab [a-z]/ {
      s = $0
      while (match(s, /scenes\/[A-Za-z0-9_.-]+\.json/)) { print "scene\t" substr(s, RSTART, RLENGTH); s = substr(s, RSTART + RLENGTH) }
    }' "$1"
}

or_null() { if [[ -f $1 ]]; then echo "$1"; else echo /dev/null; fi; }  # a file for --slurpfile
is_task() { [[ -n ${kind[$1]:-} ]]; }
is_bonus() { [[ ${kind[$1]:-} == bonus ]]; }

# check TREE [NN...]: one line per disagreement, status 1 if any. With NN...: only those stages (the
# self-test); the class table's tasks are then held against those stages' manifests only.
check() {
  local tree=$1 bad=0 dir name nn m rel hdr stub pf hf sheet task fn tag cls what where suite scene row f n key val line
  local -A all_tasks=() read_stage=() tclass=() kind=() klass=() listed=() declared=() todo=() tested=() hint=() rows=() scenes=() seen=()
  [[ -f $tree/docs/grading.md ]] || { echo "docs/grading.md: no such file (the class table)"; bad=1; }
  while IFS=$'\t' read -r task what cls; do
    if [[ $task == "?" ]]; then echo "docs/grading.md: the class table's row '$what' names no task N.M (or a range across stages)"; bad=1
    elif [[ -n ${tclass[$task]:-} ]]; then echo "docs/grading.md: the class table names task $task twice"; bad=1
    else tclass[$task]=$what
    fi
  done < <(class_table "$tree")
  local only=" ${*:2} "

  for dir in "$tree"/exercises/[0-9][0-9]_*/; do
    dir=${dir%/}; name=${dir##*/}; nn=${name:0:2}; rel=exercises/$name; m=$rel/stage.json
    [[ $only == "  " || $only == *" $nn "* ]] || continue
    [[ -f $dir/stage.json ]] || { echo "$m: no manifest"; bad=1; continue; }
    # the manifest's shape first (E lines): the comparisons below need a well-formed one
    line=$(jq -r --arg name "$name" --arg nn "$nn" "[$VALIDATE] as \$e | if \$e != [] then \$e[] | \"E\\t\\(.)\" else $FACTS end" \
           "$dir/stage.json" 2>&1) \
      || line="E	not valid JSON"
    kind=() klass=() listed=() declared=() todo=() tested=() hint=() rows=() scenes=() seen=()
    local -a order=() used=()
    if [[ $line == E* ]]; then sed -n "s|^E\t|$m: |p" <<<"$line"; bad=1; continue; fi
    while IFS=$'\t' read -r key task val cls; do
      case $key in
        T) order+=("$task"); kind[$task]=$val klass[$task]=$cls all_tasks[$task]=1 ;;
        F) listed["$task $val"]=1 ;;
        S) scenes[$task]=1 ;;
        X) stub=$task ;;
      esac
    done <<<"$line"
    read_stage[$nn]=1

    # the header
    hdr=framework/include/clothlab/exercise/$name.h
    if [[ ! -f $tree/$hdr ]]; then echo "$hdr: no such file (the stage's contract)"; bad=1
    else
      while IFS=$'\t' read -r tag task fn; do
        declared["$task $fn"]=1
        if [[ $fn == "?" ]]; then echo "$hdr: '$tag $task' declares no function after it"; bad=1
        elif [[ -z ${listed["$task $fn"]:-} ]]; then echo "$hdr: '$tag $task' declares $fn, which $m does not list under task $task"; bad=1
        elif [[ $tag == Exercise ]] && is_bonus "$task"; then
          echo "$hdr: '$tag $task' ($fn), but $m marks $task a bonus task (its comment: '/// Bonus ${task}a —')"; bad=1
        elif [[ $tag == Bonus ]] && ! is_bonus "$task"; then
          echo "$hdr: '$tag $task' ($fn), but $m does not mark $task a bonus task"; bad=1
        fi
      done < <(header_functions "$tree/$hdr")
      for key in "${!listed[@]}"; do
        [[ -n ${declared[$key]:-} ]] || { echo "$m: task ${key% *} lists ${key#* }, which $hdr declares under no '/// Exercise ${key% *}'/'/// Bonus ${key% *}' comment"; bad=1; }
      done
    fi

    # the stub
    if [[ ! -f $tree/$stub ]]; then echo "$m: stub $stub: no such file"; bad=1
    else
      while read -r line; do todo[${line##* }]=1; done < <(grep -oE '//[[:space:]]*TODO[[:space:]]+[0-9]+\.[0-9]+' "$tree/$stub")
      for task in "${order[@]}"; do
        [[ -n ${todo[$task]:-} ]] || { echo "$stub: no '// TODO $task' for task $task of $m"; bad=1; }
      done
      for task in "${!todo[@]}"; do
        is_task "$task" || { echo "$stub: '// TODO $task' names no task of $m"; bad=1; }
      done
    fi

    # the points file, hints.json and the answers' "how" commands, read in one go
    pf=tests/$name.points.json hf=$rel/hints.json
    [[ -f $tree/$pf ]] || { echo "$pf: no such file"; bad=1; }
    [[ -f $tree/$hf ]] || { echo "$hf: no such file"; bad=1; }
    if ! line=$(jq -rn --slurpfile s "$dir/stage.json" --slurpfile p "$(or_null "$tree/$pf")" \
                 --slurpfile h "$(or_null "$tree/$hf")" --slurpfile a "$(or_null "$dir/answers.json")" '
        ($s[0].title) as $title |
        ($p[0] // empty | (if .title != $title then ["title", (.title | tojson), ($title | tojson)] else empty end),
                          ((.tests // {}) | keys[] | ["tests", .]), ((.bonus // {}) | keys[] | ["bonus", .])),
        ($h[0] // empty | keys[] | ["hint", .]),
        ($a[0] // empty | .. | objects | .how? // empty | strings | scan("scenes/[A-Za-z0-9_.-]+\\.json") | ["how", .])
        | @tsv' 2>/dev/null); then
      for f in "$pf" "$hf" "$rel/answers.json"; do
        [[ ! -f $tree/$f ]] || jq empty "$tree/$f" 2>/dev/null || echo "$f: not valid JSON"
      done
      bad=1; continue
    fi
    while IFS=$'\t' read -r where suite val; do
      case $where in
        "") continue ;;
        title) echo "$pf: title $suite, but $m says $val"; bad=1; continue ;;
        hint) hint[$suite]=1; continue ;;
        how) used+=("answers.json	$suite"); continue ;;
      esac
      suite=${suite%%.*}
      [[ $where == tests && $suite == Experiments ]] && continue
      [[ -z ${seen["$where $suite"]:-} ]] || continue  # one line per suite, not per test
      seen["$where $suite"]=1
      if [[ $suite =~ ^(Task|Bonus)([0-9]+)_([0-9]+)_ ]]; then
        task=${BASH_REMATCH[2]}.${BASH_REMATCH[3]}
        if ! is_task "$task"; then echo "$pf: \"$where\" has $suite, of task $task, which $m does not list"; bad=1
        elif [[ $where == tests && ${BASH_REMATCH[1]} == Task ]] && ! is_bonus "$task"; then tested[$task]=1
        elif [[ $where == bonus && ${BASH_REMATCH[1]} == Bonus ]] && is_bonus "$task"; then tested[$task]=1
        else echo "$pf: \"$where\" has $suite, but $m marks $task as $(is_bonus "$task" && echo 'a bonus task' || echo 'no bonus task') (a bonus task's tests: Bonus${task/./_}_* under \"bonus\"; another's: Task${task/./_}_* under \"tests\")"; bad=1
        fi
      else
        echo "$pf: \"$where\" has $suite, which is neither Task/BonusN_M_* nor Experiments"; bad=1
      fi
    done <<<"$line"
    if [[ -f $tree/$pf ]]; then
      for task in "${order[@]}"; do
        [[ -n ${tested[$task]:-} ]] && continue
        if is_bonus "$task"; then echo "$pf: no test Bonus${task/./_}_* under \"bonus\" for bonus task $task of $m"
        else echo "$pf: no test Task${task/./_}_* under \"tests\" for task $task of $m"; fi
        bad=1
      done
    fi
    if [[ -f $tree/$hf ]]; then
      for task in "${order[@]}"; do [[ -n ${hint[$task]:-} ]] || { echo "$hf: no hints for task $task of $m"; bad=1; }; done
      for task in "${!hint[@]}"; do is_task "$task" || { echo "$hf: hints for $task, which $m does not list"; bad=1; }; done
    fi

    # the sheet: its Points table, the scenes it names
    sheet=$rel/README.md
    if [[ ! -f $tree/$sheet ]]; then echo "$sheet: no such file"; bad=1
    else
      while IFS=$'\t' read -r key row; do
        if [[ $key == scene ]]; then used+=("README.md	$row"); continue; fi
        task=${row%% *}; rows[$task]=1
        if ! [[ $row =~ ^[0-9]+\.[0-9]+(\ \(bonus\))?$ ]]; then echo "$sheet: Points table row '$row' is not 'N.M' or 'N.M (bonus)'"; bad=1
        elif ! is_task "$task"; then echo "$sheet: Points table row $task, which $m does not list"; bad=1
        elif [[ $row == *"(bonus)" ]] && ! is_bonus "$task"; then echo "$sheet: Points table row '$row', but $m does not mark $task a bonus task"; bad=1
        elif [[ $row != *"(bonus)" ]] && is_bonus "$task"; then echo "$sheet: Points table row '$row', but $m marks $task a bonus task (the row: '$task (bonus)')"; bad=1
        fi
      done < <(sheet_facts "$tree/$sheet")
      for task in "${order[@]}"; do [[ -n ${rows[$task]:-} ]] || { echo "$sheet: no Points table row for task $task of $m"; bad=1; }; done
    fi

    # docs/grading.md's class table
    for task in "${order[@]}"; do
      if [[ -z ${tclass[$task]:-} ]]; then
        is_bonus "$task" || { echo "docs/grading.md: the class table has no row for task $task ($m: ${klass[$task]})"; bad=1; }
      elif [[ ${tclass[$task]} != "${klass[$task]}" ]]; then
        echo "docs/grading.md: the class table gives task $task the class '${tclass[$task]}', $m '${klass[$task]}'"; bad=1
      fi
    done

    # the mistakes file (tests/instructor/ is not in the student copy)
    if [[ -d $tree/tests/instructor ]]; then
      f=tests/instructor/mistakes/$name.cmake
      if [[ ! -f $tree/$f ]]; then echo "$f: no such file (the stage's typical mistakes)"; bad=1
      else
        n=$(grep -cE '^[[:space:]]*clothlab_mistake[[:space:]]*\(' "$tree/$f")
        ((n >= 1)) || { echo "$f: no clothlab_mistake(...)"; bad=1; }
      fi
    fi

    # the scenes: every listed one exists, every used one is listed
    for scene in "${!scenes[@]}"; do
      [[ -f $tree/$scene ]] || { echo "$m: lists $scene: no such file"; bad=1; }
    done
    for line in "${used[@]}"; do
      scene=${line#*	}
      [[ -n ${scenes[$scene]:-} ]] || { echo "$rel/${line%%	*}: names $scene, which $m does not list under \"scenes\""; bad=1; }
    done | sort -u | grep . && bad=1
  done

  # every task of the class table is in its stage's manifest (of the stages read; a stage that is not has no folder)
  for task in $(printf '%s\n' "${!tclass[@]}" | sort -V); do
    nn=$(printf %02d "${task%%.*}")
    if [[ -n ${read_stage[$nn]:-} ]]; then
      [[ -n ${all_tasks[$task]:-} ]] || { echo "docs/grading.md: the class table names task $task, which exercises/${nn}_*/stage.json does not list"; bad=1; }
    elif ! compgen -G "$tree/exercises/${nn}_*/" >/dev/null; then
      echo "docs/grading.md: the class table names task $task, of no stage (no folder exercises/${nn}_*)"; bad=1
    fi
  done
  return $bad
}

n=$(ls -d "$root"/exercises/[0-9][0-9]_*/ | wc -l)
((n >= 7)) || { echo "FAIL: only $n stage folders found in $root/exercises"; exit 1; }
check "$root" || { echo "FAIL: a stage's files disagree with its manifest exercises/NN_name/stage.json (lines above)"; exit 1; }

# The check catches planted mismatches, each in a fresh copy of the files it reads.
mkdir -p "$work/orig/framework/include/clothlab" "$work/orig/tests/instructor" "$work/orig/docs" "$work/orig/scenes" \
  && cp -r "$root/exercises" "$work/orig/" && cp -r "$root/framework/include/clothlab/exercise" "$work/orig/framework/include/clothlab/" \
  && cp "$root"/tests/[0-9][0-9]_*.points.json "$work/orig/tests/" && cp -r "$root/tests/instructor/mistakes" "$work/orig/tests/instructor/" \
  && cp "$root/docs/grading.md" "$work/orig/docs/" && cp "$root"/scenes/*.json "$work/orig/scenes/" \
  || { echo "FAIL: could not copy the files the check reads into $work/orig"; exit 1; }
fresh() { rm -rf "$work/t" && cp -r "$work/orig" "$work/t"; }
edit() {  # edit FILE PERL: in the copy, FILE changed by the Perl substitution (must change it)
  perl -CSD -Mutf8 -0pi -e "$2" "$work/t/$1"
  cmp -s "$root/$1" "$work/t/$1" && { echo "FAIL: could not plant into $1 (update this test): $2"; exit 1; }
  return 0
}
json() {  # json FILE JQ: in the copy, FILE rewritten by jq
  jq "$2" "$work/t/$1" >"$work/t/$1.new" && mv "$work/t/$1.new" "$work/t/$1"
  cmp -s "$root/$1" "$work/t/$1" && { echo "FAIL: could not plant into $1 (update this test): $2"; exit 1; }
  return 0
}
planted=0
expect_caught() {  # expect_caught WHAT NN PATTERN...: the check of stage NN fails and names each pattern
  local out what=$1 nn=$2 p; shift 2
  if out=$(check "$work/t" "$nn"); then echo "FAIL: the check misses a planted mismatch: $what"; exit 1; fi
  for p in "$@"; do
    grep -qE -- "$p" <<<"$out" || { echo "FAIL: planted $what, but no line matches /$p/:"; echo "$out"; exit 1; }
  done
  planted=$((planted + 1))
}
fresh; out=$(check "$work/t") || { echo "FAIL: the check fails on an unchanged copy (update fresh()):"; echo "$out"; exit 1; }
fresh; edit framework/include/clothlab/exercise/04_distance.h 's/^Vec3 distanceGradient\(/Vec3 distanceGrad(/m'
expect_caught "a function renamed in the header" 04 \
  '04_distance\.h: .Exercise 4\.2. declares distanceGrad, which .* does not list' 'stage\.json: task 4\.2 lists distanceGradient, which .* declares under no'
fresh; json exercises/05_bending/hints.json 'del(.["5.3"])'
expect_caught "a hints key removed" 05 '05_bending/hints\.json: no hints for task 5\.3'
fresh; rm "$work/t/scenes/pbd_bounce.json"
expect_caught "a listed scene missing" 06 '06_collision/stage\.json: lists scenes/pbd_bounce\.json: no such file'
fresh; json exercises/05_bending/stage.json '.scenes -= ["scenes/pbd_hanging.json"]'
expect_caught "a scene of the sheet's 'Run it' not listed" 05 '05_bending/README\.md: names scenes/pbd_hanging\.json, which .* does not list'
fresh; json exercises/01_hooke/stage.json '.scenes -= ["scenes/spring.json"]'
expect_caught "a scene of a 'how' command not listed" 01 '01_hooke/answers\.json: names scenes/spring\.json'
fresh; json exercises/03_pbd_loop/stage.json '(.tasks[] | select(.task == "3.2") | .class) = "formula"'
expect_caught "a class changed in a manifest" 03 "grading\.md: the class table gives task 3\.2 the class 'derivation', .* 'formula'"
fresh; edit docs/grading.md 's/^(\| 7\.2–7\.4 [^|]*\| )algorithm /$1formula /m'
expect_caught "a class changed in the table's range row" 07 \
  "task 7\.2 the class 'formula'" "task 7\.3 the class 'formula'" "task 7\.4 the class 'formula'"
fresh; json tests/06_collision.points.json '.tests |= with_entries(.key |= sub("^Task6_4_VelocityUpdate"; "Task6_5_VelocityUpdate"))'
expect_caught "a points suite of no task" 06 '06_collision\.points\.json: "tests" has Task6_5_VelocityUpdate, of task 6\.5'
fresh; edit exercises/01_hooke/hooke.cpp 's|// TODO 1\.3:|// 1.3:|'
expect_caught "a TODO removed from the stub" 01 "01_hooke/hooke\.cpp: no '// TODO 1\.3'"
fresh; edit exercises/02_mfn/README.md 's/^\| 2\.3 \|/| 2.4 |/m'
expect_caught "a sheet's Points row renumbered" 02 '02_mfn/README\.md: Points table row 2\.4' '02_mfn/README\.md: no Points table row for task 2\.3'
fresh; json exercises/07_self_collision/stage.json '.tasks[0] |= (.clas = .class | del(.class))'
expect_caught "a key misspelt in a manifest" 07 '07_self_collision/stage\.json: tasks\[0\]: unknown key "clas"' '07_self_collision/stage\.json: tasks\[0\]: no key "class"'
fresh; json exercises/04_distance/stage.json '(.tasks[] | select(.task == "4.4")) |= del(.bonus)'
expect_caught "the bonus mark dropped" 04 "04_distance\.h: 'Bonus 4\.4' \(tetherAnchors\), but .* does not mark 4\.4" \
  'no row for task 4\.4' '"bonus" has Bonus4_4_' "row '4\.4 \(bonus\)', but"

echo "all $n stages agree with their manifests exercises/NN_name/stage.json (header functions, stub TODOs, points, hints, sheet rows, the class table, mistakes, scenes); $planted planted mismatches caught"
