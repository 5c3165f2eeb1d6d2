#!/bin/bash
# count_steps_test.sh SOURCE_DIR: the search for a step in the cluster count that the runs share
# (pipelines/figures/count-steps.awk) on hand-made counts: 8 runs of N = 1000 (t / 100)^(-0.4), each with
# its own 3% noise per snapshot (so the exponent's error over 8 runs is ~0.05, the excess's ~0.08), log-spaced by 10^(1/8). Without a step, every interval's exponent is -0.4
# and none stands out of the runs' scatter; with N falling by a factor 0.7 between t = 10^4 and 1.33e4 in
# every run, that interval's excess over its neighbours is ln(0.7) / ln(10^(1/8)) = -1.239, far outside its
# error, the mean count falls 1 - 0.7 x 10^(-0.05) = 37.6% there, and the runs whose pieces end inside it
# are counted (a run's last piece ends the run, not a boundary). The summary names that interval.
set -euo pipefail
src=$1
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
# counts STEP [SEED]: the input lines, N falling by the factor 1 - STEP past t = 1e4 (STEP = 0: none); runs
# 1-3 have a piece ending at t = 1.2e4, every run one ending at 1e5.
counts() {
  # Park-Miller's generator, exact in any awk's doubles, so that every awk draws the same noise.
  awk -v step="$1" -v seed="${2:-12345}" 'function uniform() { seed = (seed * 16807) % 2147483647; return seed / 2147483647 }
  BEGIN {
    for (r = 1; r <= 8; r++) {
      for (i = 0; i <= 24; i++) {
        t = 100 * 10^(i / 8); z = 0; for (j = 0; j < 12; j++) z += uniform(); z -= 6
        print "n", "run" r, t, 1000 * (t / 100)^(-0.4) * exp(0.03 * z) * (t > 1.0001e4 ? 1 - step : 1)
      }
      if (r <= 3) print "b", "run" r, 1.2e4
      print "b", "run" r, 1e5
    }
  }'
}
steps() { counts "$@" | awk -v L=64 -v e=0.9 -v from=1000 -f "$src/pipelines/figures/count-steps.awk"; }
# field ROW NAME: the excess ("X +- S") or the runs with a boundary ("B of R") of a row's note.
excess() { grep -o 'intervals [^;]*' <<< "$1" | awk '{ print $2, $4 }'; }

steps 0 > "$dir/flat.tsv"
[ "$(grep -c $'^fs_count_step_L64\t' "$dir/flat.tsv")" = 16 ] || fail "16 intervals from t = 1000 to 1e5 expected: $(wc -l < "$dir/flat.tsv")"
while IFS=$'\t' read -r name e d s t1 t2 note; do
  [ "$name" = fs_count_step_L64 ] && [ "$e" = 0.9 ] || fail "row name or e wrong: $name $e"
  awk -v d="$d" -v s="$s" 'BEGIN { exit !(d > -0.4 - 3 * s && d < -0.4 + 3 * s && s > 0.025 && s < 0.1) }' ||
    fail "exponent -0.4 within 3 errors (~0.05) expected over [$t1, $t2]: $d +- $s"
  read -r x xs <<< "$(excess "$note")"
  [ -z "$x" ] || awk -v x="$x" -v s="$xs" 'BEGIN { exit !((x < 0 ? -x : x) < 4 * s) }' ||
    fail "no step expected over [$t1, $t2]: excess $x +- $xs"
  grep -q '; 0 of 8 runs have a piece boundary inside$' <<< "$note" || [ "$t1" = 10000 ] ||
    fail "no piece boundary expected over [$t1, $t2]: $note"
done < <(grep $'^fs_count_step_L64\t' "$dir/flat.tsv")
# The pieces: 1.2e4 lies in (1e4, 1.33e4] for runs 1-3; the runs' ends at 1e5 are not boundaries.
grep -P '\t10000\t13335.2\t' "$dir/flat.tsv" | grep -q '; 3 of 8 runs have a piece boundary inside$' ||
  fail "3 of 8 runs with a boundary expected over [1e4, 1.33e4]: $(grep -P '\t10000\t' "$dir/flat.tsv")"
grep -P '\t74989.4\t100000\t' "$dir/flat.tsv" | grep -q '; 0 of 8 runs' || fail "a run's end counted as a boundary"

steps 0.3 > "$dir/step.tsv"
row=$(grep -P '\t10000\t13335.2\t' "$dir/step.tsv")
read -r x xs <<< "$(excess "$row")"
awk -v x="$x" -v s="$xs" 'BEGIN { exit !(x > -1.239 - 3 * s && x < -1.239 + 3 * s && -x > 8 * s) }' ||
  fail "the step's excess -1.239 (within 3 errors, beyond 8) expected: $x +- $xs"
grep -Eq 'the mean count falls 3[5-9]\.[0-9]%' <<< "$row" || fail "a fall of 37.6% (35-40) expected: $row"
# Its neighbours see half the step with the other sign.
read -r x xs <<< "$(excess "$(grep -P '\t7498.94\t10000\t' "$dir/step.tsv")")"
awk -v x="$x" -v s="$xs" 'BEGIN { exit !(x > 0.62 - 3 * s && x < 0.62 + 3 * s) }' || fail "the interval before the step: excess +0.62 expected, got $x"
# The verdict row: no step in the flat counts, the step found where it is.
grep -q $'^fs_count_step_verdict_L64\t0.9\t.*a step the runs share: no;' "$dir/flat.tsv" || fail "no step expected: $(tail -1 "$dir/flat.tsv")"
grep -q $'^fs_count_step_verdict_L64\t0.9\t[0-9.e-]*\tnan\t10000\t13335.2\t.*a step the runs share: yes;' "$dir/step.tsv" ||
  fail "the step at t = 1e4 expected: $(tail -1 "$dir/step.tsv")"
# Its error rates over 300 ensembles each: a step found where there is none in at most 10% (Bonferroni
# at 5%: at most 5% in expectation); a step at the size the verdict states (an extra fall of 10% here)
# found about half the time, and one of 15% in at least 80%.
rate() { local k hits=0; for k in $(seq 1 300); do steps "$1" "$((1000 + 7 * k))" | tail -1 | grep -q 'share: yes' && hits=$((hits + 1)); done; echo "$hits"; }
grep -q 'an extra fall of 10% over one interval' "$dir/flat.tsv" || fail "a detectable step of 10% expected: $(tail -1 "$dir/flat.tsv")"
false_hits=$(rate 0) half=$(rate 0.10) hits=$(rate 0.15)
echo "a step where there is none: $false_hits of 300; a 10% step: $half of 300; a 15% step: $hits of 300"
[ "$half" -ge 90 ] && [ "$half" -le 210 ] || fail "a 10% step found in $half of 300 ensembles (about half expected)"
[ "$false_hits" -le 30 ] || fail "false steps in $false_hits of 300 ensembles (at most 30)"
[ "$hits" -ge 240 ] || fail "a 15% step found in $hits of 300 ensembles only (at least 240)"
# The summary's paragraph gives the verdict and the table.
{ printf 'fs_runs_L64\t0.9\t8\tnan\t-\t100000\tcomplete\n'; printf 'fs_verdict\tall\tundecided\tnan\t-\t-\tno statements\n'; cat "$dir/step.tsv"; } > "$dir/fits.tsv"
awk -f "$src/pipelines/figures/summary-finite-size.awk" "$dir/fits.tsv" |
  grep -Eq 'The largest \|excess\| / error is [0-9.e+]+, over t = 10000-13335.2, of 15 intervals \(Student t, 7 dof; Bonferroni: family-wise p = [0-9.e-]+\); a step the runs share: yes;' ||
  fail "the summary does not name the step: $(awk -f "$src/pipelines/figures/summary-finite-size.awk" "$dir/fits.tsv" | grep -A3 Steps)"
echo "count-steps: no step found where there is none, the planted one found with its size and boundaries"
