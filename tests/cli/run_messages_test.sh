#!/usr/bin/env bash
# The run's messages: a pinned particle that moves is reported at once, naming the pass
# and the stage that moved it, and with --strict the run stops there (exit 3); the reference moves no
# pin; an unstable run and a strict stop each state their reason once.
# A pass that creates momentum in a scene without pins is reported with its pass and stage too, and so
# is the pass that blew a run up (exercise 4.3 with its sign flipped): not only "unstable at step N".
# Usage: run_messages_test.sh CLOTHLAB PLANTED_04_WEIGHTING_LEFT_OUT PLANTED_05_Q1_NOT_BALANCED SOURCE_DIR
#        PLANTED_04_SIGN_FLIPPED
set -u
exe=$1 planted=$2 planted5=$3 root=$4 planted_sign=$5
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
bad=0
fail() { echo "FAIL: $*"; bad=1; }
curtain=$root/scenes/pbd_curtain.json

# The reference: no pin moves.
"$exe" run "$curtain" --quiet >"$tmp/ref" 2>&1 || fail "the reference run of pbd_curtain failed: $(tail -3 "$tmp/ref")"
grep -q "pinned particle" "$tmp/ref" && fail "the reference moved a pinned particle: $(grep "pinned particle" "$tmp/ref")"

# Exercise 4.3 without the mass weighting: the warning names the pass and the stage; exit 0 without --strict.
"$planted" run "$curtain" --quiet >"$tmp/planted" 2>&1 || fail "the planted run failed without --strict: $(tail -3 "$tmp/planted")"
grep -q "warning: pinned particle moved: particle [0-9]* (w = 0, infinite mass) moved .* by step 1 (t = " "$tmp/planted" \
  || fail "no pinned-particle warning at step 1: $(grep -i "warning" "$tmp/planted")"
grep -q "moved by the pass 'constraints: distance' (stage 04, exercise 4.3)" "$tmp/planted" \
  || fail "the warning does not name the distance pass and stage 04: $(grep "pinned" "$tmp/planted")"

# --strict: stops at that step with exit 3; the warning's text once, the error line its headline.
"$planted" run "$curtain" --quiet --strict >"$tmp/strict" 2>&1; rc=$?
[[ $rc == 3 ]] || fail "--strict: exit $rc, want 3"
grep -q "^error: .*pbd_curtain.json: solver: stopped at step 1 by --strict: pinned particle [0-9]* moved by the pass 'constraints: distance'" "$tmp/strict" \
  || fail "--strict: no error line naming the step and the pass: $(grep error "$tmp/strict")"
n=$(grep -c "a pinned particle never moves" "$tmp/strict")
[[ $n == 1 ]] || fail "--strict: the warning's text is said $n times, want once"
grep -q "^summary: 1 steps" "$tmp/strict" || fail "--strict: the run did not stop at step 1: $(grep summary "$tmp/strict")"

# Momentum: exercise 5.2 whose q1 forgets q4 (the gradients no longer sum to zero), on pbd_sphere (no pins).
"$exe" run "$root/scenes/pbd_sphere.json" --quiet >"$tmp/sphere" 2>&1 || fail "the reference run of pbd_sphere failed"
grep -q "momentum" "$tmp/sphere" && fail "the reference created momentum: $(grep momentum "$tmp/sphere")"
# (The flat cloth bends nothing until it meets the sphere, at step 25.)
"$planted5" run "$root/scenes/pbd_sphere.json" --quiet --steps 40 >"$tmp/q1" 2>&1
grep -q "warning: momentum created: at step 2[0-9] (t = .*) the pass 'constraints: bending' (stage 05, exercise 5.2) changed the cloth's linear momentum" "$tmp/q1" \
  || fail "no momentum warning naming the bending pass when the cloth meets the sphere: $(grep -i "warning" "$tmp/q1")"

# An unstable run (explicit Euler far beyond its stable step): the reason once.
"$exe" run "$root/scenes/spring.json" --set spring.k=1e9 --set solver.method=explicit_euler --quiet >"$tmp/unstable" 2>&1; rc=$?
[[ $rc == 3 ]] || fail "unstable spring: exit $rc, want 3"
n=$(grep -c "unstable at step" "$tmp/unstable")
[[ $n == 1 ]] || fail "the unstable run states its reason $n times, want once: $(cat "$tmp/unstable")"

# A blow-up from a wrong sign in exercise 4.3: the message names the pass and the exercise, once.
"$planted_sign" run "$curtain" --quiet >"$tmp/sign" 2>&1; rc=$?
[[ $rc == 3 ]] || fail "4.3 with its sign flipped: exit $rc, want 3 (a blow-up): $(tail -2 "$tmp/sign")"
grep -q "unstable at step [0-9]* (t = .*): .*; it first blew up in the pass 'constraints: distance' (stage 04, exercise 4.3)" "$tmp/sign" \
  || fail "the blow-up of 4.3 with its sign flipped does not name the distance pass and exercise 4.3: $(grep -i unstable "$tmp/sign")"
n=$(grep -c "it first blew up in" "$tmp/sign")
[[ $n == 1 ]] || fail "the blow-up names its pass $n times, want once"
# The explicit Euler spring above has no passes to name: its message stays as it was.
grep -q "it first blew up" "$tmp/unstable" && fail "the unstable spring names a pass: $(grep unstable "$tmp/unstable")"

((bad == 0)) || exit 1
echo "a moved pin, created momentum and a blow-up are reported with their pass and stage (a pin stops the run with --strict); each reason is said once"
