#!/bin/bash
# fig7.sh ENERGY MASS THETA ZETA LOCAL_E LOCAL_M   (called by Makefile.study)
# Paper Fig. 7: 1D, e = 0.5, rho = 0.3, delta = 0.005: (a) E(t) with t^-2/3, (b) m(t).
# Writes $OUT/fig7.tsv (blocks: E, m, local exponents of E and m), $OUT/fig7.fits.tsv, $OUT/fig7.{png,svg}.
set -euo pipefail
: "${FIT:?}" "${OUT:?}" "${FIGSRC:?}" "${EWIN:?}" "${MWIN:?}"
energy=$1 mass=$2 theta=$3 zeta=$4 le=$5 lm=$6
read -r e1 e2 <<< "$EWIN"; read -r m1 m2 <<< "$MWIN"
mkdir -p "$OUT"
"$FIGSRC/blocks.sh" \
  "1D E(t) per particle, ensemble mean and standard error: time E stderr" \
  "'$FIT' table '$energy:/average/mean' '$energy:/average/stderr'" \
  "1D m(t), ensemble mean and standard error: time m stderr" \
  "'$FIT' table '$mass:/average/mean' '$mass:/average/stderr'" \
  "local exponent d ln E / d ln t: time z stderr" \
  "'$FIT' table '$le:/local_exponent/exponent' '$le:/local_exponent/stderr'" \
  "local exponent d ln m / d ln t: time z stderr" \
  "'$FIT' table '$lm:/local_exponent/exponent' '$lm:/local_exponent/stderr'" > "$OUT/fig7.tsv.tmp"
{
  printf '# Fig. 7 fits (SCALE=%s; 1D, e = 0.5, rho = 0.3, delta = 0.005, T0 = 1; errors: %s over runs). Columns: quantity e value stderr t1 t2 note\n' \
    "${SCALE:-?}" "${ERRORS:-jackknife}"
  "$FIGSRC/fitrow.sh" theta_1d 0.5 "$theta" /fit/exponent /fit/exponent_stderr -1 "$e1" "$e2" "E = B t^-theta, ensemble mean"
  "$FIGSRC/fitrow.sh" theta_1d_amplitude 0.5 "$theta" /fit/amplitude /fit/amplitude_stderr 1 "$e1" "$e2" "B of that fit"
  "$FIGSRC/fitrow.sh" zeta_1d 0.5 "$zeta" /fit/exponent /fit/exponent_stderr 1 "$m1" "$m2" "m = A t^zeta, ensemble mean"
  "$FIGSRC/fitrow.sh" zeta_1d_amplitude 0.5 "$zeta" /fit/amplitude /fit/amplitude_stderr 1 "$m1" "$m2" "A of that fit"
  # Does the growth freeze? The largest m(t) and the exponent of m over the last decade of the run.
  "$FIT" table --no-header "$mass:/average/mean" "$mass:/average/stderr" | awk -F'\t' -v OFS='\t' '
    $2 !~ /nan/ { t[++n] = $1; m[n] = $2; s[n] = $3; if (best == "" || $2 + 0 > best) { best = $2 + 0; bs = $3; bt = $1 } }
    END {
      print "m_max_1d", 0.5, sprintf("%.5g", best), sprintf("%.3g", bs), bt, bt, "largest ensemble m(t) and its time"
      j = n; while (j > 1 && t[j - 1] > t[n] / 10) j--
      z = log(m[n] / m[j]) / log(t[n] / t[j])
      print "zeta_1d_last_decade", 0.5, sprintf("%.4g", z), "nan", t[j], t[n], "ln(m(t2)/m(t1))/ln(t2/t1) over the last decade (freezing: ~0)"
    }'
} > "$OUT/fig7.fits.tsv.tmp"
get() { awk -F'\t' -v q="$1" -v c="$2" '$1 == q { printf "%s", $c }' "$OUT/fig7.fits.tsv"; }
mv "$OUT/fig7.tsv.tmp" "$OUT/fig7.tsv"; mv "$OUT/fig7.fits.tsv.tmp" "$OUT/fig7.fits.tsv"
"${GNUPLOT:-gnuplot}" -e "dir='$OUT'; th='$(get theta_1d 3)'; b='$(get theta_1d_amplitude 3)'; e1=$e1; e2=$e2; z='$(get zeta_1d 3)'; a='$(get zeta_1d_amplitude 3)'; m1=$m1; m2=$m2; figsrc='$FIGSRC'; scale='${SCALE:-}'" \
  "$FIGSRC/fig7.gp"
