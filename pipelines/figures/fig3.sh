#!/bin/bash
# fig3.sh "ES" "MASS..." "ZETA..." "LOCAL..." "ONSET..." MCOLLAPSE   (called by Makefile.study)
# Paper Fig. 3: ensemble m(t) per e, log-log, with the late-window power-law fits.
# Writes $OUT/fig3.tsv (blocks 0..k-1: time m stderr per e; blocks k..2k-1: local exponent per e),
# $OUT/fig3.fits.tsv and $OUT/fig3.{png,svg}.
set -euo pipefail
: "${FIT:?}" "${OUT:?}" "${FIGSRC:?}" "${ZETA_WINS:?}" "${COLLAPSE_WIN:?}"
. "$FIGSRC/lib.sh"
read -r -a es <<< "$1"; read -r -a mass <<< "$2"; read -r -a zeta <<< "$3"
read -r -a local <<< "$4"; read -r -a onset <<< "$5"; mcollapse=$6
read -r -a wins <<< "$ZETA_WINS"; read -r c1 c2 <<< "$COLLAPSE_WIN"
mkdir -p "$OUT"

{
  for i in "${!es[@]}"; do
    table_block "m(t), e = ${es[i]}, ensemble mean and standard error: time m stderr" \
      "${mass[i]}" /average/mean /average/stderr
  done
  for i in "${!es[@]}"; do
    table_block "local exponent d ln m / d ln t (0.5-decade sliding fits), e = ${es[i]}: time z stderr" \
      "${local[i]}" /local_exponent/exponent /local_exponent/stderr
  done
} > "$OUT/fig3.tsv.tmp"

{
  fits_header 3 "T0 = 1"
  for i in "${!es[@]}"; do
    e=${es[i]} w1=${wins[i]%_*} w2=${wins[i]#*_}
    power_law_rows zeta "$e" "${zeta[i]}" 1 "$w1" "$w2" \
      "late-window power law m = A t^zeta of the ensemble mean" "A of that fit"
    "$FIGSRC/fitrow.sh" onset_plateau_time "$e" "${onset[i]}" /onset/plateau_time /onset/plateau_time_stderr 1 - - \
      "m(t) leaves its early plateau: first time m > 1.1 x median of the first 5 snapshots (3 samples in a row)"
    "$FIGSRC/fitrow.sh" onset_asymptote_time "$e" "${onset[i]}" /onset/asymptote_time /onset/asymptote_time_stderr 1 - - \
      "start of the t^${ASYMPTOTE:-0.6} regime: local exponent within 0.1 of ${ASYMPTOTE:-0.6} (3 samples in a row)"
    # Crossover: the steepest growth, i.e. the largest local exponent up to the end of the late window
    # (later points can be finite-size merging events).
    "$FIT" table --no-header "${local[i]}:/local_exponent/exponent" "${local[i]}:/local_exponent/stderr" |
      awk -F'\t' -v OFS='\t' -v e="$e" -v tend="$w2" '
        $1 + 0 <= tend * 1.0001 && $2 !~ /nan/ && (best == "" || $2 + 0 > best) { best = $2 + 0; err = $3; t = $1 }
        END { if (best == "") print "crossover_peak_exponent", e, "nan", "nan", "-", "-", "no local exponent";
              else print "crossover_peak_exponent", e, sprintf("%.4g", best), sprintf("%.3g", err), t, t,
                         "largest local exponent before the end of the late window (the crossover growth)" }'
  done
  "$FIGSRC/fitrow.sh" collapse_exponent all "$mcollapse" /fit/exponent /fit/exponent_stderr 1 "$c1" "$c2" \
    "common exponent of all e over a common late window, one amplitude per e"
  ratio_rows amplitude_ratio A "$mcollapse" "${es[*]}" "$c1" "$c2"
} > "$OUT/fig3.fits.tsv.tmp"

publish 3
get() { fits_column "$OUT/fig3.fits.tsv" "$@"; }   # fit lines for the plot: e, zeta, amplitude, window
plot 3 "n=${#es[@]}; es='$(get zeta 2)'; zs='$(get zeta 3)'; as='$(get zeta_amplitude 3)'; t1s='$(get zeta 5)'; t2s='$(get zeta 6)'"
