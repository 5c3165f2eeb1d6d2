#!/bin/bash
# fig3.sh "ES" "MASS..." "ZETA..." "LOCAL..." "ONSET..." MCOLLAPSE   (called by Makefile.study)
# Paper Fig. 3: ensemble m(t) per e, log-log, with the late-window power-law fits.
# Writes $OUT/fig3.tsv (blocks 0..k-1: time m stderr per e; blocks k..2k-1: local exponent per e),
# $OUT/fig3.fits.tsv and $OUT/fig3.{png,svg}.
set -euo pipefail
: "${FIT:?}" "${OUT:?}" "${FIGSRC:?}" "${ZETA_WINS:?}" "${COLLAPSE_WIN:?}"
read -r -a es <<< "$1"; read -r -a mass <<< "$2"; read -r -a zeta <<< "$3"
read -r -a local <<< "$4"; read -r -a onset <<< "$5"; mcollapse=$6
read -r -a wins <<< "$ZETA_WINS"; read -r c1 c2 <<< "$COLLAPSE_WIN"
mkdir -p "$OUT"
n=${#es[@]}

args=()
for i in "${!es[@]}"; do args+=("m(t), e = ${es[i]}, ensemble mean and standard error: time m stderr"
                                  "'$FIT' table '${mass[i]}:/average/mean' '${mass[i]}:/average/stderr'"); done
for i in "${!es[@]}"; do args+=("local exponent d ln m / d ln t (0.5-decade sliding fits), e = ${es[i]}: time z stderr"
                                  "'$FIT' table '${local[i]}:/local_exponent/exponent' '${local[i]}:/local_exponent/stderr'"); done
"$FIGSRC/blocks.sh" "${args[@]}" > "$OUT/fig3.tsv.tmp"

{
  printf '# Fig. 3 fits (SCALE=%s; T0 = 1; errors: %s over runs). Columns: quantity e value stderr t1 t2 note\n' \
    "${SCALE:-?}" "${ERRORS:-jackknife}"
  for i in "${!es[@]}"; do
    e=${es[i]} w1=${wins[i]%_*} w2=${wins[i]#*_}
    "$FIGSRC/fitrow.sh" zeta "$e" "${zeta[i]}" /fit/exponent /fit/exponent_stderr 1 "$w1" "$w2" \
      "late-window power law m = A t^zeta of the ensemble mean"
    "$FIGSRC/fitrow.sh" zeta_amplitude "$e" "${zeta[i]}" /fit/amplitude /fit/amplitude_stderr 1 "$w1" "$w2" "A of that fit"
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
  "$FIT" table --no-header "$mcollapse:/fit/amplitude_ratio" "$mcollapse:/fit/amplitude_ratio_stderr" "$mcollapse:/fit/agree" |
    awk -F'\t' -v OFS='\t' -v es="${es[*]}" -v c1="$c1" -v c2="$c2" '
      BEGIN { split(es, e, " ") }
      { print "amplitude_ratio", e[NR], sprintf("%.4g", $1), sprintf("%.3g", $2), c1, c2,
              "A(e)/A(" e[1] ") at the common exponent; gg-fit agree (2 sigma) = " $3 }'
} > "$OUT/fig3.fits.tsv.tmp"

# Fit lines for the plot: e, zeta, amplitude, window.
fe=$(awk -F'\t' '$1 == "zeta" { printf "%s ", $2 }' "$OUT/fig3.fits.tsv.tmp")
fz=$(awk -F'\t' '$1 == "zeta" { printf "%s ", $3 }' "$OUT/fig3.fits.tsv.tmp")
fa=$(awk -F'\t' '$1 == "zeta_amplitude" { printf "%s ", $3 }' "$OUT/fig3.fits.tsv.tmp")
f1=$(awk -F'\t' '$1 == "zeta" { printf "%s ", $5 }' "$OUT/fig3.fits.tsv.tmp")
f2=$(awk -F'\t' '$1 == "zeta" { printf "%s ", $6 }' "$OUT/fig3.fits.tsv.tmp")
mv "$OUT/fig3.tsv.tmp" "$OUT/fig3.tsv"
mv "$OUT/fig3.fits.tsv.tmp" "$OUT/fig3.fits.tsv"
"${GNUPLOT:-gnuplot}" -e "dir='$OUT'; n=$n; es='$fe'; zs='$fz'; as='$fa'; t1s='$f1'; t2s='$f2'; scale='${SCALE:-}'; figsrc='$FIGSRC'" \
  "$FIGSRC/fig3.gp"
