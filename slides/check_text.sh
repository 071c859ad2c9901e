#!/usr/bin/env bash
# Checks what the projector shows, in both editions (fast, text only; in ./lab test as
# slides.projected_text; slides/edition_text.sh gives each edition's text):
# - the introduction names every lab stage, exercises/NN_name;
# - no audience answer and no live-demo runbook on a projected slide: no "question? (answer)", no
#   "Answers"/"Point at"/"Run" blocks outside the speaker notes, and every live-demo slide has notes
#   with the run command, its duration "(about N min)" and the answers;
# - no answer of the speaker notes on any projected slide of its deck: every paragraph of the notes
#   that starts with **Answer**/**Answers**/**Antwort**/**Antworten** gives its keys, and none of them
#   may appear in the deck's projected text, on any slide, whatever the line breaks. The keys of an
#   answer: its formulas ($...$, cut at = < > \le \ge \approx; a part counts when it has an operator
#   ^ / + - inside and is not just "a - b" of two symbols), its numbers (a formula's part that is a
#   number, or a number followed by a unit, with two significant digits or more; not searched in raw
#   LaTeX, where TikZ coordinates are numbers) and its word 4-grams (a math span is one word; at least
#   one word of 4+ letters that is no stop word, or a formula), all after the same normalising of both
#   texts: one line, lower case, LaTeX spacing and \vb, \mathbf, \text... dropped, braces dropped,
#   German decimal commas as points. A 4-gram or formula that is also in a question of the deck (the
#   numbered items under "Ask the audience", the **Ask:** of the notes, a projected sentence ending in
#   "?") is an echo of the question, not an answer;
# - notes on every derivation slide: a heading marked {.en .derivation} / {.de .derivation} has, in
#   both editions, notes with "**Derivation** (about N min)" ("**Herleitung** (etwa N min)"), the
#   question to ask ("**Ask:** ...?", "**Frage:** ...?") and its "**Answer:**" ("**Antwort:**"); a slide
#   that shows two or more display formulas ($$) and is not marked is a derivation slide without
#   notes; a slide's minutes (its notes' first "(about N min)", else 2) agree in both editions;
# - the lecture plan of slides/README.md is the one slides/lecture_plan.sh computes from the decks,
#   and no lecture is longer than 90 minutes;
# - no text below body size (\tiny, \scriptsize, \footnotesize) in the decks and the preamble;
# - every slide title has both languages: as many `## ... {.en}` as `## ... {.de}` headings, none
#   without, and as many `::: en` as `::: de` blocks.
# Then it runs itself on copies of slides/ with planted faults (an answer on an earlier slide over
# two lines, an answer's number and formula in the German edition, a derivation slide without notes,
# an unmarked derivation, a plan that disagrees) and fails unless each is caught.
#   bash slides/check_text.sh        (exit 1 and what is wrong when something is)
set -uo pipefail
SRC=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
ROOT=$(cd "$SRC/.." && pwd)
bad=0
problem() { echo "$1: $2"; bad=$((bad + 1)); }
SRC_TMP=$(mktemp -d); trap 'rm -rf "$SRC_TMP"' EXIT

# One deck in one edition (its text with the notes, slides/edition_text.sh LANG FILE, on stdin):
# the answers and the derivation notes as described above; one problem per line, and one line
# "minutes<TAB>N<TAB>TITLE" per slide.
# shellcheck disable=SC2016
DECK_PL='
use strict; use warnings;
my ($lang) = @ARGV;
my %STOP = map { $_ => 1 } qw(the and that this with from than then they them their there these those
  what which when where while does into onto only also each every other about after before because
  would could should must have been being were your more most less much many same such very just over
  under between along without within der die das den dem des und oder ein eine einen einem einer eines
  nicht auch nur mit von bei für aus auf über unter zum zur sich sie ihr ihre ihren wird werden sind ist
  war waren noch schon dann denn wenn weil dass als wie was wer welche welcher jedes jeder jede alle
  dieser diese dieses einmal);
my %W = $lang eq "de"
  ? (deriv => "Herleitung", about => "etwa", ask => "Frage", answer => "Antwort")
  : (deriv => "Derivation", about => "about", ask => "Ask", answer => "Answer");
# the text as tokens: words, and each math span as one token "$..." (normalised)
sub tokens {
  my ($t) = @_;
  $t =~ s/\s+/ /g;
  my @tok;
  for my $piece (split /(\$\$.*?\$\$|\$[^\$]+\$)/, $t) {
    next unless length $piece;
    if ($piece =~ /^\$/) {
      my $m = $piece; $m =~ s/^\$+|\$+$//g;
      $m =~ s/\\[,;:! ]|\\q?quad\b|\\(?:left|right|[bB]igg?[lr]?)\b//g;
      $m =~ s/\\[td]frac/\\frac/g;
      $m =~ s/\\(?:vb|mathbf|boldsymbol|mathrm|text|operatorname)\b//g;
      $m =~ s/\{,\}/./g; $m =~ s/\s+//g; $m =~ s/[{}]//g;
      push @tok, "\$" . lc $m if length $m;
    } else {
      my $p = lc $piece;
      $p =~ s/\*\*|`//g; $p =~ s/(?<=\d),(?=\d)/./g;
      push @tok, grep { length } split /[^\p{L}\p{N}.\x27^_+\/=<>-]+|(?<!\d)\.|\.(?!\d)/, $p;
    }
  }
  return @tok;
}
sub grams { my @t = @_; map { join " ", @t[$_ .. $_ + 3] } 0 .. $#t - 3 }
# the slides: title, classes, projected lines, notes lines
my (@slides, @stack);
my $raw = 0;
my $cur = { title => "(chapter title)", classes => "", proj => [], notes => [], text => [] };
push @slides, $cur;
for my $line (split /\n/, do { local $/; <STDIN> }) {
  my $fence = $line =~ /^```/;  # a raw LaTeX block opens with ```{=latex} and closes with ```
  if ($fence) { if ($raw) { $raw = 0 } elsif ($line =~ /^```\{=latex\}/) { $raw = 1 } }
  if ($line =~ /^:::+ *([^: ].*?) *$/) { push @stack, ($1 eq "notes" ? "notes" : "div"); next }
  if ($line =~ /^:::+ *$/ && @stack) { pop @stack; next }
  my $in_notes = grep { $_ eq "notes" } @stack;
  if (!$in_notes && $line =~ /^## (.*?)( \{(\.[^}]*)\})? *$/) {
    $cur = { title => $1, classes => $3 // "", proj => [], notes => [], text => [] };
    push @slides, $cur;
    next;
  }
  push @{ $in_notes ? $cur->{notes} : $cur->{proj} }, $line;
  push @{ $cur->{text} }, $line unless $in_notes || $raw || $fence;  # without raw LaTeX (TikZ coordinates)
}
# paragraphs of a slide notes that start with **WORD...**
sub paragraphs {
  my ($lines, $re) = @_;
  my (@out, $para);
  for my $l (@$lines, "") {
    if ($l =~ /^\s*$/) { push @out, $para if defined $para; undef $para; next }
    if (defined $para) { $para .= " $l" } elsif ($l =~ $re) { $para = $l }
  }
  return @out;
}
my $ANSWER = qr/^\*\*(?:Answers?|Antwort(?:en)?)\b/;
# the questions of the deck (echoes of them in an answer are no leak): their 4-grams and formulas
my (%qgram, %qformula);
for my $s (@slides) {
  my $proj = join "\n", @{ $s->{proj} };
  my @q = paragraphs($s->{notes}, qr/^\*\*(?:Ask|Frage):\*\*/);
  push @q, grep { /^\d+\. / } @{ $s->{proj} } if $proj =~ /\*\*(?:Ask the audience|Fragen ans Publikum)\*\*/;
  (my $flat = $proj) =~ s/\s+/ /g;
  push @q, grep { /\?$/ } split /(?<=[.!?])\s+/, $flat;  # a question on a slide: "Why? -- stage 06"
  for my $t (map { [tokens($_)] } @q) {
    $qgram{$_} = 1 for grams(@$t);
    $qformula{$_} = 1 for map { split /=|<|>|\\le|\\ge|\\approx|\\to\b|\\rightarrow|,/, substr($_, 1) } grep { /^\$/ } @$t;
  }
}
# each slide projected, as one line of tokens
my @shown = map { [$_->{title}, " " . join(" ", tokens(join " ", $_->{title}, @{ $_->{proj} })) . " "] } @slides;
my @shown_text = map { [$_->{title}, " " . join(" ", tokens(join " ", $_->{title}, @{ $_->{text} })) . " "] } @slides;
sub where {  # the titles of the projected slides that contain the words NEEDLE, or ()
  my ($needle) = @_;
  return map { $_->[0] } grep { index($_->[1], " $needle ") >= 0 } @shown;
}
my $units = qr/^(?:m|mm|cm|km|s|ms|kg|g|n\/m|n|j|mj|rad|hz|%|m\/s|mm\/s|cm\/s)$/;
my %told;
for my $s (@slides) {
  for my $answer (paragraphs($s->{notes}, $ANSWER)) {
    (my $text = $answer) =~ s/^\*\*[^*]*\*\*\s*(?:\([^)]*\))?:?//;  # "**Answer** (stage 06, question 1):"
    my @t = tokens($text);
    my @keys;  # [kind, needle]
    for my $j (0 .. $#t) {
      my $tok = $t[$j];
      if ($tok =~ /^\$(.*)/) {
        for my $part (split /=|<|>|\\le|\\ge|\\approx|\\to\b|\\rightarrow|,/, $1) {
          if ($part =~ /^\d+(?:\.\d+)?$/) { push @keys, ["number", $part]; next }
          next unless length $part >= 3 && $part =~ /[\^\/+\-]/;
          next if $part =~ /^[\^\/+\-]|[\^\/+\-]$/;  # a fragment: "displacement$/\Delta t$"
          next if $part =~ /^\\?[a-z]+(?:_\w+)?[+\-]\\?[a-z]+(?:_\w+)?$/;  # "p_1-p_0": notation
          next if $part =~ /^\\?[a-z]+(?:_\w+)?\^(?:\*|t|\\prime)$/;   # "x^*", "a^T": a name
          next if $qformula{$part};  # the question names it
          push @keys, ["formula", $part];
        }
      } elsif ($tok =~ /^\d+(?:\.\d+)?$/ && $j < $#t && $t[$j + 1] =~ $units) {
        push @keys, ["number", $tok];
      }
    }
    for my $g (grams(@t)) {
      next if $qgram{$g};
      my $content = grep { /^\$./ || (length >= 4 && !$STOP{$_}) } split / /, $g;
      push @keys, ["words", $g] if $content >= 1;
    }
    for my $k (@keys) {
      my ($kind, $needle) = @$k;
      if ($kind eq "number") {
        (my $sig = $needle) =~ s/\.//; $sig =~ s/^0+//; $sig =~ s/0+$// unless $needle =~ /\./;
        next if length $sig < 2;
      }
      my @at = $kind eq "formula" ? (map { $_->[0] } grep { index($_->[1], $needle) >= 0 } @shown)
             : $kind eq "number" ? (map { $_->[0] } grep { $_->[1] =~ /(?<![\w.])\Q$needle\E(?!\w|\.\d)/ } @shown_text)
             : where($needle);
      for my $at (@at) {
        next if $told{"$needle\t$at"}++;
        print "the answer in the notes of \x27$s->{title}\x27 is on the projected slide \x27$at\x27 ($kind \x27$needle\x27)\n";
      }
    }
  }
}
for my $s (@slides[1 .. $#slides]) {
  my $notes = join "\n", @{ $s->{notes} };
  my ($min) = $notes =~ /\((?:about|etwa)\s+(\d+)\s+min\)/;
  print "minutes\t", ($min // 2), "\t$s->{title}\n";
  if ($s->{classes} =~ /(^| )\.derivation\b/) {
    $notes =~ /\*\*$W{deriv}\*\* \($W{about} \d+ min\)/
      or print "the derivation slide \x27$s->{title}\x27 has no notes \x27**$W{deriv}** ($W{about} N min)\x27 (what to say)\n";
    grep { /\?/ } paragraphs($s->{notes}, qr/^\*\*$W{ask}:\*\*/)
      or print "the derivation slide \x27$s->{title}\x27 has no question for the audience in its notes (**$W{ask}:** ...?)\n";
    $notes =~ /^\*\*$W{answer}:\*\*/m
      or print "the derivation slide \x27$s->{title}\x27 has no answer to its question in its notes (**$W{answer}:**)\n";
  } else {
    my $display = () = join("\n", @{ $s->{proj} }) =~ /\$\$.+?\$\$/gs;
    print "the slide \x27$s->{title}\x27 shows $display display formulas: a derivation slide without notes (mark its headings {.$lang .derivation} and give it notes)\n"
      if $display >= 2;
  }
}
'

for lang in en de; do
  intro=$(bash "$SRC/edition_text.sh" "$lang" --projected "$SRC"/01_*.md)
  for d in "$ROOT"/exercises/[0-9][0-9]_*/; do
    [[ -d $d ]] || continue
    stage=$(basename "$d")
    grep -qF -- "$stage" <<<"$intro" || problem "01_introduction.md ($lang)" "does not name the lab stage $stage"
  done
  for md in "$SRC"/${CHECK_TEXT_DECKS:-[0-9][0-9]}_*.md; do
    deck="$(basename "$md") ($lang)"
    shown=$(bash "$SRC/edition_text.sh" "$lang" --projected "$md")
    while IFS= read -r line; do
      [[ -n $line ]] && problem "$deck" "an answer on a projected slide: ${line:0:90}"
    done < <(grep -vE '^#' <<<"$shown" | grep -E '\? *\([^)]*\)')
    while IFS= read -r line; do
      [[ -n $line ]] && problem "$deck" "speaker-notes text on a projected slide: ${line:0:90}"
    done < <(grep -E '\*\*(Answers?|Antwort|Antworten|Point at|Zeigen|Run|Starten)\b|If the demo cannot run' <<<"$shown")
    full=$(bash "$SRC/edition_text.sh" "$lang" "$md")
    # the live-demo slide's notes: the command, how long, the answers
    demo=$(awk '/^## /{p = ($0 ~ /^## Live[ -][Dd]emo/)} p' <<<"$full")
    grep -qE '^::: notes' <<<"$demo" || problem "$deck" "the live-demo slide has no speaker notes"
    grep -qE '\((about|etwa) [0-9]+ min\): `\./lab gui ' <<<"$demo" \
      || problem "$deck" "the live-demo notes do not start the demo: **Run** (about N min): \`./lab gui ...\`"
    grep -qE '^\*\*(Answers|Antworten):\*\*' <<<"$demo" || problem "$deck" "the live-demo notes have no answers"
    # answers in the notes against every projected slide, derivation notes, minutes per slide
    out=$(perl -CSD -Mutf8 -e "$DECK_PL" "$lang" <<<"$full") || problem "$deck" "the analysis of the deck failed (perl)"
    while IFS= read -r line; do
      [[ -n $line ]] && problem "$deck" "$line"
    done < <(grep -v $'^minutes\t' <<<"$out")
    grep $'^minutes\t' <<<"$out" | cut -f2 >"$SRC_TMP/minutes.$lang.$(basename "$md")"
  done
done
for md in "$SRC"/${CHECK_TEXT_DECKS:-[0-9][0-9]}_*.md; do
  cmp -s "$SRC_TMP/minutes.en.$(basename "$md")" "$SRC_TMP/minutes.de.$(basename "$md")" \
    || problem "$(basename "$md")" "the minutes per slide differ between the editions (the notes' '(about N min)' and '(etwa N min)')"
done
# the lecture plan: README's table is the computed one, each lecture at most 90 minutes
plan=$(bash "$SRC/lecture_plan.sh") || problem "slides/lecture_plan.sh" "failed"
while IFS= read -r row; do
  [[ $row == '| '[0-9]* ]] || continue
  grep -qxF -- "$row" "$SRC/README.md" || problem "slides/README.md" "the lecture plan lacks the row the decks give: $row"
  minutes=$(awk -F'|' '{ gsub(/[^0-9]/, "", $5); print $5 }' <<<"$row")
  ((minutes <= 90)) || problem "slides/README.md" "a lecture of $minutes minutes (over 90): $row"
done <<<"$plan"
while IFS= read -r row; do
  grep -qxF -- "$row" <<<"$plan" || problem "slides/README.md" "a lecture plan row the decks do not give (bash slides/lecture_plan.sh): $row"
done < <(sed -n '/^## Lecture plan/,/^## /p' "$SRC/README.md" | grep -E '^\| [0-9]')
for f in "$SRC"/[0-9][0-9]_*.md "$SRC/preamble.tex"; do
  while IFS= read -r line; do
    [[ -n $line ]] && problem "$(basename "$f")" "text below body size: $line"
  done < <(grep -nE '\\(tiny|scriptsize|footnotesize)\b' "$f")
done
HEAD='\{\.(en|de)( +\.[A-Za-z-]+)*\} *$'
for md in "$SRC"/[0-9][0-9]_*.md; do
  deck=$(basename "$md")
  en=$(grep -cE '^#+ .*\{\.en( +\.[A-Za-z-]+)*\} *$' "$md"); de=$(grep -cE '^#+ .*\{\.de( +\.[A-Za-z-]+)*\} *$' "$md")
  ((en == de)) || problem "$deck" "$en headings {.en} but $de headings {.de}"
  while IFS= read -r line; do
    [[ -n $line ]] && problem "$deck" "a heading in no language (add {.en} and a {.de} twin): $line"
  done < <(grep -E '^#+ ' "$md" | grep -vE "$HEAD")
  en=$(grep -cE '^#+ .*\{\.en \.derivation\} *$' "$md"); de=$(grep -cE '^#+ .*\{\.de \.derivation\} *$' "$md")
  ((en == de)) || problem "$deck" "$en derivation headings {.en .derivation} but $de {.de .derivation}"
  en=$(grep -cxE '::: *en *' "$md"); de=$(grep -cxE '::: *de *' "$md")
  ((en == de)) || problem "$deck" "$en '::: en' blocks but $de '::: de' blocks"
done
echo "projected text: $( ((bad == 0)) && echo "both editions clean" || echo "$bad problems")"
((bad == 0)) || exit 1
[[ -n ${CHECK_TEXT_PLANTED:-} ]] && exit 0

# The check fails on planted faults, each in a fresh copy of slides/ (and empty exercises/NN_name/).
plant_root=$SRC_TMP/tree
fresh() {
  rm -rf "$plant_root" && mkdir -p "$plant_root" && cp -r "$SRC" "$plant_root/slides" \
    && for d in "$ROOT"/exercises/[0-9][0-9]_*/; do mkdir -p "$plant_root/exercises/$(basename "$d")"; done
}
plant() {  # plant FILE PERL-SUBSTITUTION: edit the copy, fail if it did not change
  perl -0pi -CSD -Mutf8 -e "$2" "$plant_root/slides/$1"
  cmp -s "$SRC/$1" "$plant_root/slides/$1" && { echo "FAIL: could not plant into slides/$1 (update this check)"; exit 1; }
  return 0
}
expect_caught() {  # expect_caught WHAT PATTERN [DECK]: the copy's check, on deck DECK only (NN) if given
  local out
  if out=$(CHECK_TEXT_PLANTED=1 CHECK_TEXT_DECKS=${3:-} bash "$plant_root/slides/check_text.sh"); then
    echo "FAIL: the check misses a planted fault: $1"; exit 1
  fi
  grep -qE -- "$2" <<<"$out" || { echo "FAIL: planted $1, but the check does not name it: $out"; exit 1; }
}
fresh
CHECK_TEXT_PLANTED=1 bash "$plant_root/slides/check_text.sh" >/dev/null \
  || { echo "FAIL: the unplanted copy of slides/ does not pass (this check's copy is incomplete)"; exit 1; }
# 1. the answer of the last slide's notes (07: C is linear along n-hat) on the first slide, over two lines
plant 07_distance.md 's/(- its gradients \$\\nabla_\{\\vb\{p\}_1\} C\$)/$1; one projection is exact: \$C\$ is linear\n  along \$\\hat\{\\vb\{n\}\}\$/'
expect_caught "an answer on an earlier slide, over two lines" "07_distance\.md \(en\): the answer in the notes of .* is on the projected slide 'Distance constraint .*words '\\\$c is linear along'" 07
# 2. an answer's number (05: 2470 N/m) and formula (08: 1/(1 - d^2)) in the German edition
fresh
plant 05_mfn_limits.md 's/(- feineres Gitter = leichtere Partikel = kleineres \$\\Delta t\$)/$1: doppelt so fein, 2470\n  N\/m/'
expect_caught "an answer's number in German" "05_mfn_limits\.md \(de\): the answer .* on the projected slide 'Was das Framework misst' \(number '2470'\)" 05
fresh
plant 08_bending.md 's/(Das ist das Rezept aus Kapitel 7 mit)/Mit \$1\/(1 - d^2)\$: $1/'
expect_caught "an answer's formula in German" "08_bending\.md \(de\): the answer .* \(formula '1/\(1-d\^2\)'\)" 08
# 3. a derivation slide without its notes (06: stiffness per iteration, English notes cut)
fresh
plant 06_pbd.md 's/\*\*Derivation\*\* \(about 4 min\)\. Set up the requirement/Set up the requirement/'
expect_caught "a derivation slide without notes" "06_pbd\.md \(en\): the derivation slide 'Stiffness per iteration' has no notes" 06
# 4. an unmarked derivation (10: implicit Euler, the marks taken off)
fresh
plant 10_beyond.md 's/(## Implicit Euler: from the equation to the update \{\.en) \.derivation\}/$1}/; s/(## Implizites Euler-Verfahren: von der Gleichung zum Update \{\.de) \.derivation\}/$1}/'
expect_caught "an unmarked derivation slide" "10_beyond\.md \(en\): the slide 'Implicit Euler: from the equation to the update' shows 2 display formulas" 10
# 5. a lecture plan that disagrees with the decks (one more minute in lecture 1)
fresh
plant README.md 's/^(\| 1 \| [^\n]*\| )(\d+)( \|)$/$1 . ($2 + 1) . $3/me'
expect_caught "a lecture plan that disagrees" "slides/README\.md: a lecture plan row the decks do not give"
echo "planted: an answer on an earlier slide over two lines, an answer's number and formula (German), a derivation slide without notes, an unmarked derivation, a wrong lecture plan: all 6 caught"
