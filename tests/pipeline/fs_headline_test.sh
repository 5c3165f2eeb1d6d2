#!/bin/bash
# fs_headline_test.sh SOURCE_DIR: the finite-size study's headline verdict (pipelines/figures/fs-headline.awk)
# on hand-made statement rows: it is read in the paper's length l at the largest box where l has a verdict,
# even where m has one at a larger box; without l in l_C, then in m before t_g; a quantity without
# statements is "not measured"; no statements give "undecided". And the summary's sentence
# (summary-finite-size.awk) carries the word, the box and the quantity.
set -euo pipefail
src=$1
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
row() { printf '%s\tall\t%s\tnan\t-\t-\t%s\n' "$1" "$2" "${3:-note}"; }
headline() { awk -f "$src/pipelines/figures/fs-headline.awk" -v es="0.5 0.7 0.9" "$1"; }
# l rejected at L = 64 only; l_C without statements at 128; m supported at 128 (a larger box).
{
  row fs_l_statement_exponent_L64 yes; row fs_l_statement_amplitude_L64 rejected
  row fs_l_statement_shift_L64 no "one master curve l(t / c(e)) collapses every e within errors: no; c(e) constant over the range of l: no"
  row fs_l_statement_energy_L64 no
  row fs_l_statement_exponent_L128 n/a "fewer than 3 runs with l(t) for some e"
  row fs_lC_statement_exponent_L64 n/a "fewer than 3 runs with l_C(t) for some e"
  row fs_statement_exponent_L64 yes; row fs_statement_amplitude_L64 undecided
  row fs_statement_exponent_L128 yes; row fs_statement_amplitude_L128 supported
  row def_g1w1rc0.4c8m1_statement_amplitude_L128 supported
} > "$dir/a.tsv"
got=$(headline "$dir/a.tsv")
[ "$(cut -f1,3,5 <<< "$got")" = "$(printf 'fs_verdict\trejected\t64')" ] || fail "l's verdict at L = 64 expected, got: $got"
grep -q '; read in l; l: (1) late exponents agree: yes, (2) equal-time amplitude = 1: rejected, (3) one master curve: no; c(e) constant over the range of l: no, at equal energy: no; l_C: not measured; m (before t_g): (1) late exponents agree: yes, (2) equal-time amplitude = 1: undecided' <<< "$got" ||
  fail "the note does not give every quantity at L = 64: $got"
# Without l: l_C; without l and l_C: m at its largest box.
grep -v '^fs_l_' "$dir/a.tsv" > "$dir/b.tsv"
{ cat "$dir/b.tsv"; row fs_lC_statement_exponent_L128 no; row fs_lC_statement_amplitude_L128 undecided; } > "$dir/c.tsv"
[ "$(headline "$dir/c.tsv" | cut -f3,5)" = "$(printf 'undecided\t128')" ] || fail "l_C's verdict at L = 128 expected: $(headline "$dir/c.tsv")"
[ "$(headline "$dir/b.tsv" | cut -f3,5)" = "$(printf 'supported\t128')" ] || fail "m's verdict at L = 128 expected: $(headline "$dir/b.tsv")"
headline "$dir/b.tsv" | grep -q 'read in m (before t_g)' || fail "the note does not say it is read in m"
# No statement with a verdict: undecided, and the summary says so.
row fs_l_statement_exponent_L64 n/a > "$dir/d.tsv"
[ "$(headline "$dir/d.tsv" | cut -f3,5)" = "$(printf 'undecided\t-')" ] || fail "undecided expected: $(headline "$dir/d.tsv")"
# The summary's sentence.
{ printf 'fs_runs_L64\t0.5\t3\tnan\t-\t300\tcomplete\n'; headline "$dir/a.tsv"; } > "$dir/fig8.fits.tsv"
awk -f "$src/pipelines/figures/summary-finite-size.awk" "$dir/fig8.fits.tsv" |
  grep -q '^\*\*Verdict: e-independence of the late amplitude (q(e)/q(0.5) = 1 at equal times) is rejected\*\* at the largest box where it has a verdict (L = 64), read in l\. l: (1)' ||
  fail "the summary's headline does not carry the verdict read in l at L = 64"
echo PASS
