#!/bin/bash
# effect-driven.sh "ES" "RUNS" (called by Makefile.study via pipelines/effects/effect-driven.mk)
# The driven gas (gg-sim --drive white-noise) from T0 to its steady state, one run per e: T(t) (in 2D
# T = E per particle) beside the steady temperature of the Enskog energy balance,
#   2 XI^2 = (1 - e^2) omega1 T^(3/2) (1 + 3 a2 / 16) / d,  omega1 = 2 sqrt(pi) rho g(sigma) (Henderson),
# a2 of van Noije & Ernst (docs/PHYSICS.md "Driven gas"). The steady T measured is the mean of the
# samples over the second half of the run. Writes $OUT/effect-driven.{tsv,fits.tsv,png,svg}.
set -euo pipefail
: "${FIT:?}" "${OUT:?}" "${FIGSRC:?}"
. "$FIGSRC/lib.sh"
read -r -a es <<< "$1"; read -r -a runs <<< "$2"
mkdir -p "$OUT"
attr() { h5dump -a "/parameters/$1" "$2" | sed -n 's/^ *(0): *"\{0,1\}\([^"]*\)"\{0,1\}$/\1/p'; }

for i in "${!es[@]}"; do
  block "e = ${es[i]}: time T" "$FIT" table "${runs[i]}:/observables/kinetic_energy/value"
done > "$OUT/effect-driven.tsv.tmp"

{
  printf '# Driven gas (SCALE=%s; 2D, one run per e). Columns: quantity e value stderr t1 t2 note\n' "${SCALE:-?}"
  for i in "${!es[@]}"; do
    e=${es[i]}; run=${runs[i]}
    xi=$(attr drive_strength "$run"); rho=$(attr rho "$run"); tmax=$(attr t_max "$run")
    "$FIT" table --no-header "$run:/observables/kinetic_energy/value" |
      awk -F'\t' -v OFS='\t' -v e="$e" -v xi="$xi" -v rho="$rho" -v t2="$tmax" '
        $1 >= t2 / 2 { n++; s += $2; ss += $2 * $2 }
        END {
          pi = atan2(0, -1); eta = pi * rho / 4; d = 2
          g = (1 - 7 * eta / 16) / ((1 - eta) ^ 2)
          a2 = 16 * (1 - e) * (1 - 2 * e * e) / (73 + 56 * d - 3 * e * (35 + 8 * d) + 30 * e * e * (1 - e))
          T = (2 * d * xi * xi / ((1 - e * e) * 2 * sqrt(pi) * rho * g * (1 + 3 * a2 / 16))) ^ (2 / 3)
          m = s / n; sd = sqrt((ss / n - m * m) / (n - 1))
          print "steady_T", e, m, sd, t2 / 2, t2, "mean T over the second half (stderr: sample scatter / sqrt(n))"
          print "steady_T_enskog", e, T, "-", "-", "-", "Enskog energy balance with the Sonine a2"
          print "steady_T_ratio", e, m / T, sd / T, t2 / 2, t2, "measured / Enskog (1: kinetic theory holds)"
        }'
  done
} > "$OUT/effect-driven.fits.tsv.tmp"
publish_as effect-driven
plot_as effect-driven "n = ${#es[@]}; es = '${es[*]}'; \
  tts = '$(fits_column "$OUT/effect-driven.fits.tsv" steady_T_enskog 3)'; \
  ratios = '$(fits_column "$OUT/effect-driven.fits.tsv" steady_T_ratio 3)'"
