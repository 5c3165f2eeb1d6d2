#!/bin/bash
# cutoff_choice_test.sh SOURCE_DIR: the accuracy report's choice of the collapse cutoff
# (pipelines/accuracy/cutoff-choice.awk) on a hand-made table: each rule (2 sigma at a time, 1 sigma rms,
# collapse) fails one value, and the cheapest of the values that pass is chosen, not the study's own.
set -euo pipefail
src=$1
tsv=$(mktemp); trap 'rm -f "$tsv"' EXIT
k="cutoff (e=0.5, L=256, 3 runs)"
row() {  # value cpu quantity dev_sigma note
  printf '%s\t%s\t3\t%s\t0\t20\t%s\t0.01\t0.01\tref\t0\t0\t0.01\t%s\t%s\n' "$k" "$1" "$2" "$3" "$4" "$5"
}
{
  printf '# header\nknob\tvalue\truns\tcpu_sim_s\tcpu_ana_s\tdisk_MB\tquantity\tvalue\tstderr\treference\tref_value\tref_stderr\tdeviation\tdev_sigma\tnote\n'
  row "t_c = 1e-4 (study)" 20 "E(t) max rel. dev., 1 <= t <= 100" 0.5 "x; rms deviation in sigmas: 0.2"
  row "t_c = 1e-4 (study)" 20 "m(t) max rel. dev., 1 <= t <= 100" 1.9 "x; rms deviation in sigmas: 0.9"
  row "t_c = 1e-4 (study)" 20 zeta 3 ""                                     # a fit, not a curve: ignored
  row "t_c = 1e-3" 10 "m(t) max rel. dev., 100 < t <= 1000" -2.1 "rms deviation in sigmas: 0.5"
  row "delta = 1e-2" 5 "E(t) max rel. dev., 100 < t <= 1000" 1.5 "rms deviation in sigmas: 1.2"
  row "delta = 1e-3" 15 "E(t) max rel. dev., 1 <= t <= 100" 1.0 "rms deviation in sigmas: 0.3"
  row "delta = 1e-3" 15 "m(t) max rel. dev., 100 < t <= 1000" 1.2 "rms deviation in sigmas: 0.4"
  row "delta = 1e-4" 30 "m(t) max rel. dev., 1 <= t <= 100" 0.1 "rms deviation in sigmas: 0.1"
  row "none" 1 "collapse time" nan "3 of 3 runs collapsed"
  row "t_c = 1e-5 (ref)" 40 "m(t) max rel. dev., 1 <= t <= 100" 0 "rms deviation in sigmas: 0"
} > "$tsv"
out=$(awk -f "$src/pipelines/accuracy/cutoff-choice.awk" "$tsv")
fail=0
expect() { grep -qF -- "$1" <<< "$out" || { echo "missing: $1"; fail=1; }; }
expect "Against t_c = 1e-5 on the same seeds"
expect "t_c = 1e-4, 20.0 CPU s: passes (at most 1.9 sigma, 0.9 sigma rms)"
expect "t_c = 1e-3, 10.0 CPU s: fails: m(t) off by 2.1 sigma"
expect "delta = 1e-2, 5.0 CPU s: fails: E(t) off by 1.2 sigma rms"
expect "none, 1.0 CPU s: fails: runs collapse"
expect "**Cheapest that passes: delta = 1e-3** (15.0 CPU s; the study's t_c = 1e-4: 20.0 CPU s, passes)"
[ "$fail" = 0 ] || { echo "$out"; exit 1; }
echo "cutoff choice: every rule applied, cheapest passing value chosen"
