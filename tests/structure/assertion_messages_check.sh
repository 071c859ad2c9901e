#!/usr/bin/env bash
# Feedback that explains: every graded assertion in tests/NN_*_test.cpp carries its own explanation, a
# message streamed with `<<` that names the quantity, what physics demands and what was measured
# (GoogleTest's own text names only the expressions). Checked on every EXPECT_* / ASSERT_* / ADD_FAILURE /
# FAIL in the graded tests:
#   1. it has a streamed message (`<<` after the assertion's closing parenthesis); EXPECT_CLOSE,
#      ASSERT_CLOSE and EXPECT_SAME_DOUBLE too (their text is "actual = 1.2, expected 1 within 0.01"
#      and says nothing of what is measured). The one exception: EXPECT_TRUE(testing_util::answerFileIsComplete(...)),
#      whose message names the answers file and the field that is missing;
#   2. no GoogleTest comparison that prints doubles with 17 digits (0.29999999999999999): EXPECT_NEAR,
#      EXPECT_DOUBLE_EQ, EXPECT_FLOAT_EQ, EXPECT_LT/LE/GT/GE (and ASSERT_) are replaced by the 6-digit
#      helpers of tests/test_util.h (EXPECT_CLOSE, EXPECT_SAME_DOUBLE, EXPECT_LESS, EXPECT_GREATER, ...).
#      EXPECT_EQ/NE stay for integers and strings.
# Usage: assertion_messages_check.sh SOURCE_DIR   (checks SOURCE_DIR/tests; then proves the check fails
# on a temporary copy with a bare assertion and a 17-digit comparison planted).
set -u
root=$1
shopt -s nullglob
files=("$root"/tests/[0-9][0-9]_*_test.cpp)
((${#files[@]})) || { echo "error: no graded tests $root/tests/NN_*_test.cpp"; exit 2; }

# check FILE...: one line per violation ("file:line: ..."), exit status 1 if there are any.
check() {
  awk -v count_to="${COUNT_TO:-}" '
    FNR == 1 { if (text != "") scan(); text = ""; file = FILENAME }
    { text = text $0 "\n" }
    END { if (text != "") scan(); if (count_to != "") print total > count_to; exit bad }

    # Blanks out comments and the contents of string and character literals (keeping their quotes and
    # line breaks), so that code characters inside them do not count.
    function strip(s,   out, i, c, n, st) {
      out = ""; n = length(s); st = 0
      for (i = 1; i <= n; i++) {
        c = substr(s, i, 1)
        if (st == 0) {
          if (c == "/" && substr(s, i + 1, 1) == "/") { st = 1; out = out " "; continue }
          if (c == "/" && substr(s, i + 1, 1) == "*") { st = 2; out = out " "; continue }
          if (c == "\"") { st = 3; out = out c; continue }
          if (c == "\x27") { st = 4; out = out c; continue }
          out = out c
        } else if (st == 1) { if (c == "\n") { st = 0; out = out c } else out = out " " }
        else if (st == 2) { if (c == "*" && substr(s, i + 1, 1) == "/") { st = 0; i++; out = out "  " } else out = out (c == "\n" ? c : " ") }
        else if (st == 3) { if (c == "\\") { out = out "  "; i++ } else if (c == "\"") { st = 0; out = out c } else out = out (c == "\n" ? c : " ") }
        else if (st == 4) { if (c == "\\") { out = out "  "; i++ } else if (c == "\x27") { st = 0; out = out c } else out = out " " }
      }
      return out
    }

    function report(pos, msg,   before) {
      before = substr(code, 1, pos)
      print file ":" (gsub(/\n/, "", before) + 1) ": " msg
      bad = 1
    }

    function scan(   rest, off, m, name, start, i, n, c, depth, close_at, stmt_end, tail, args) {
      code = strip(text)
      n = length(code); off = 0; rest = code
      while (match(rest, /(^|[^A-Za-z0-9_])(EXPECT|ASSERT)_[A-Z_]+[ \t\n]*\(|(^|[^A-Za-z0-9_])(ADD_FAILURE|FAIL)[ \t\n]*\(/)) {
        m = substr(rest, RSTART, RLENGTH)
        start = off + RSTART + (m ~ /^[^A-Z]/ ? 1 : 0)
        name = m; sub(/^[^A-Z]/, "", name); sub(/[ \t\n]*\($/, "", name)
        total++
        # the assertion call: from its "(" to the matching ")"
        i = off + RSTART + RLENGTH - 1; depth = 0; close_at = 0
        for (; i <= n; i++) {
          c = substr(code, i, 1)
          if (c == "(") depth++
          else if (c == ")") { depth--; if (depth == 0) { close_at = i; break } }
        }
        off = (close_at ? close_at : n); rest = substr(code, off + 1)
        if (!close_at) { report(start, name ": unbalanced parentheses"); return }
        args = substr(code, start, close_at - start + 1)
        # the statement: up to the ";" (or "}") that ends it at depth 0
        stmt_end = index(rest, ";"); tail = stmt_end ? substr(rest, 1, stmt_end - 1) : rest
        if (name ~ /^(EXPECT|ASSERT)_(NEAR|DOUBLE_EQ|FLOAT_EQ|LT|LE|GT|GE)$/)
          report(start, name " prints doubles with 17 digits (0.29999999999999999): use the 6-digit helpers of tests/test_util.h (EXPECT_CLOSE, EXPECT_SAME_DOUBLE, EXPECT_LESS, EXPECT_LESS_EQ, EXPECT_GREATER, EXPECT_GREATER_EQ, EXPECT_EXACT)")
        if (name ~ /^(EXPECT|ASSERT)_(TRUE|FALSE)$/ && args ~ /^[A-Z_]+[ \t\n]*\([ \t\n]*(::)?(clothlab::)?(testing_util::)?answerFileIsComplete[ \t\n]*\(/) continue
        if (tail !~ /<</)
          report(start, name " without a message: stream one with << that names the quantity, what physics demands and what was measured")
      }
    }
  ' "$@"
}

out=$(COUNT_TO=$(mktemp) && export COUNT_TO && check "${files[@]}"; echo "#count $(cat "$COUNT_TO")"; rm -f "$COUNT_TO")
count=$(sed -n 's/^#count //p' <<<"$out"); out=$(grep -v '^#count ' <<<"$out")
if [[ -n $out ]]; then
  echo "$out"
  echo "FAIL: graded assertions without an explanation or with 17-digit numbers (lines above)"
  exit 1
fi

# The check can fail: plant violations into a temporary copy of the graded tests.
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
expect_caught() {  # expect_caught NAME PATTERN: the check fails on the copy and names the planted violation
  local name=$1 pattern=$2 got
  if got=$(check "$tmp"/*_test.cpp); then echo "FAIL: the check misses a planted violation: $name"; exit 1; fi
  grep -qE -- "$pattern" <<<"$got" || { echo "FAIL: planted $name, but the report does not name it: $got"; exit 1; }
}
fresh() { rm -f "$tmp"/*_test.cpp && cp "${files[@]}" "$tmp/"; }
first=$(basename "${files[0]}")

fresh; printf '\nTEST(Planted, Bare) {\n    EXPECT_TRUE(1 + 1 == 2);\n}\n' >>"$tmp/$first"
expect_caught "a bare EXPECT_TRUE" "^$tmp/$first:[0-9]+: EXPECT_TRUE without a message"
fresh; printf '\nTEST(Planted, BareClose) {\n    const double x = 0.3;\n    EXPECT_CLOSE(x, 0.3, 1e-9);  // << in a comment is no message\n}\n' >>"$tmp/$first"
expect_caught "a bare EXPECT_CLOSE" "^$tmp/$first:[0-9]+: EXPECT_CLOSE without a message"
fresh; printf '\nTEST(Planted, StringIsNotAStream) {\n    ASSERT_TRUE(std::string("a << b").empty());\n}\n' >>"$tmp/$first"
expect_caught "a << inside a string literal" "ASSERT_TRUE without a message"
fresh; printf '\nTEST(Planted, SeventeenDigits) {\n    EXPECT_NEAR(0.1 + 0.2, 0.3, 1e-9) << "the sum";\n}\n' >>"$tmp/$first"
expect_caught "an EXPECT_NEAR" "EXPECT_NEAR prints doubles with 17 digits"
fresh; printf '\nTEST(Planted, BareFailure) {\n    ADD_FAILURE();\n}\n' >>"$tmp/$first"
expect_caught "a bare ADD_FAILURE" "ADD_FAILURE without a message"

echo "assertion messages: all $count graded assertions in ${#files[@]} files carry a streamed explanation (or answerFileIsComplete's file and field) and no 17-digit comparison; the check fails on a planted bare EXPECT_TRUE, a bare EXPECT_CLOSE, a << inside a string, an EXPECT_NEAR and a bare ADD_FAILURE"
