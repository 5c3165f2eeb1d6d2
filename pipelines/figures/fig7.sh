#!/bin/bash
# fig7.sh ENERGY MASS THETA ZETA LOCAL_E LOCAL_M   (called by Makefile.study)
# Paper Fig. 7: 1D, e = 0.5, rho = 0.3, delta = 0.005: (a) E(t) with t^-2/3, (b) m(t).
# Writes $OUT/fig7.tsv (blocks: E, m, local exponents of E and m), $OUT/fig7.fits.tsv, $OUT/fig7.{png,svg}.
set -euo pipefail
: "${FIT:?}" "${OUT:?}" "${FIGSRC:?}" "${EWIN:?}" "${MWIN:?}"
. "$FIGSRC/lib.sh"
energy=$1 mass=$2 theta=$3 zeta=$4 le=$5 lm=$6
read -r e1 e2 <<< "$EWIN"; read -r m1 m2 <<< "$MWIN"
mkdir -p "$OUT"
{
  table_block "1D E(t) per particle, ensemble mean and standard error: time E stderr" "$energy" /average/mean /average/stderr
  table_block "1D m(t), ensemble mean and standard error: time m stderr" "$mass" /average/mean /average/stderr
  table_block "local exponent d ln E / d ln t: time z stderr" "$le" /local_exponent/exponent /local_exponent/stderr
  table_block "local exponent d ln m / d ln t: time z stderr" "$lm" /local_exponent/exponent /local_exponent/stderr
} > "$OUT/fig7.tsv.tmp"
{
  fits_header 7 "1D, e = 0.5, rho = 0.3, delta = 0.005, T0 = 1"
  power_law_rows theta_1d 0.5 "$theta" -1 "$e1" "$e2" "E = B t^-theta, ensemble mean" "B of that fit"
  power_law_rows zeta_1d 0.5 "$zeta" 1 "$m1" "$m2" "m = A t^zeta, ensemble mean" "A of that fit"
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
publish 7
get() { fits_column "$OUT/fig7.fits.tsv" "$1" 3; }
plot 7 "th='$(get theta_1d)'; b='$(get theta_1d_amplitude)'; e1=$e1; e2=$e2; z='$(get zeta_1d)'; a='$(get zeta_1d_amplitude)'; m1=$m1; m2=$m2"
