#!/usr/bin/perl
# key_expressions.pl LABEL FILE KEYS [ALLOW]: one line per key expression of KEYS (TASK<TAB>REGEX per
# line; tests/instructor/keys/derivations.tsv) found in FILE, after its text is written in the plain
# notation of the keys ("w₁" is "w1", "Δt²" is "Δt^2", "−" is "-", "·" is "*", "×" is " x ", "**p**" is
# "p", whitespace is one space); exit 1 if any. With ALLOW (TASK<TAB>FORMULA per line, the original
# slides' own formulas), FILE is Markdown with LaTeX: that is written plainly too (\frac{a}{b} is a/(b),
# \vb{p}_1 is p1, \sum is Σ) and the allowed formulas are cut first. LABEL "-" and FILE "@LIST": every
# "LABEL<TAB>FILE" line of LIST, in one run. Used by derivation_hints_check.sh and leak_test.sh.
use strict;
use warnings;
use utf8;

my ($label, $file, $keys, $allow) = @ARGV;
my $br = qr/(\{(?:[^{}]++|(?-1))*+\})/;  # a balanced {...}
sub frac { my ($num, $den) = map { substr($_, 1, -1) } @_; $num =~ s/^\s+|\s+$//g;
           ($num =~ /^[\w\\\x27.]+$/ ? $num : "($num)") . "/($den)" }
sub plain {  # TEXT, TEX: the text in the plain notation of the keys
  my ($t, $tex) = @_;
  if ($tex) {  # \frac{a}{b} -> a/(b), \vb{p}_1 -> p1, \sum -> Σ, ^{1/n} -> ^1/n, `code` -> code
    1 while $t =~ s/\\[dt]?frac\s*$br\s*$br/frac($1, $2)/e;
    my %sym = (Delta => "Δ", nabla => "∇", sum => "Σ", varphi => "φ", phi => "φ", lambda => "λ",
               alpha => "α", sqrt => "√", cdot => "·", times => "×", sin => "sin", arccos => "arccos");
    $t =~ s/\\(Delta|nabla|sum|varphi|phi|lambda|alpha|sqrt|cdot|times|sin|arccos)(?![a-zA-Z])/$sym{$1}/g;
    $t =~ s/\\(?:vb|mathbf|boldsymbol|bm|vec|hat|tilde|bar|mathrm|text|textbf|operatorname|left|right|[bB]igg?[lr]?)(?![a-zA-Z])//g;
    $t =~ s/\\(?:q?quad(?![a-zA-Z])|[,;:! ])/ /g; $t =~ s/\\\|/|/g; $t =~ s/[{}\$`]//g;
  }
  $t =~ s/\*\*//g; $t =~ tr/₀₁₂₃₄₅₆₇₈₉ᵢⱼₕₛ/0123456789ijhs/; $t =~ s/²/^2/g; $t =~ s/ⁿ/^n/g; $t =~ s/½/1\/2/g;
  $t =~ s/−/-/g; $t =~ s/·/*/g; $t =~ s/×/ x /g; $t =~ s/\s+/ /g;
  $t =~ s/_(\w)/$1/g if $tex;
  return $t;
}
local $/;
# LABEL "-" and FILE "@LIST": every "LABEL<TAB>FILE" line of LIST, in one perl (the framework sources)
my @items = $file =~ /^@(.*)/s ? do { open(my $l, "<", $1) or die "$1: $!"; map { [split /\t/] } split /\n/, <$l> }
                               : ([$label, $file]);
my @allowed;
if (defined $allow) {  # the allowed formulas, spacing-tolerant
  open(my $al, "<", $allow) or die "$allow: $!";
  for (split /\n/, <$al>) {
    my (undef, $formula) = split /\t/, $_, 2; next unless length($formula // "");
    (my $p = plain($formula, 1)) =~ s/\s+//g;
    push @allowed, join "\\s*", map { quotemeta } split //, $p;
  }
}
open(my $k, "<", $keys) or die "$keys: $!"; my @keys = map { [split /\t/, $_, 2] } grep { !/^#/ && /\t/ } split /\n/, <$k>;  # comments and blank lines skipped
my $bad = 0;
for my $item (@items) {
  my ($lab, $path) = @$item;
  open(my $f, "<", $path) or die "$path: $!"; my $t = plain(<$f>, defined $allow);
  $t =~ s/$_/ [allowed] /g for @allowed;
  for (@keys) {
    my ($task, $re) = @$_;
    if ($t =~ /$re/) { print "$lab: prints the answer of derivation task $task (\x27$&\x27, key /$re/)\n"; $bad = 1 }
  }
}
exit $bad
