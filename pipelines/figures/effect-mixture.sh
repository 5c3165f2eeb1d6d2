#!/bin/bash
# effect-mixture.sh RUN.h5 (called by Makefile.study via pipelines/effects/effect-mixture.mk)
# The mixture effect: a binary mixture cooling homogeneously. Writes $OUT/effect-mixture.tsv (one block:
# time T_1 T_2 T_1/T_2 from /observables/temperature_species) and $OUT/effect-mixture.{png,svg}, with
# Garzo & Dufty's ratio of the cooling state (PRE 60, 5706 (1999), Maxwellian approximation, chi_ij = 1;
# docs/PHYSICS.md "Mixtures") for the run's e, masses, radii and fractions as a horizontal line.
set -euo pipefail
: "${FIT:?}" "${OUT:?}" "${FIGSRC:?}"
run=$1
mkdir -p "$OUT"

# attr NAME: the run's /parameters attribute NAME as text.
attr() { h5dump -a "/parameters/$1" "$run" | awk '/\(0\)/ { sub(/.*\(0\): */, ""); gsub(/"/, ""); print; exit }'; }
e=$(attr e); dim=$(attr dim); masses=$(attr masses); radii=$(attr radii); fractions=$(attr fractions)

# zeta_1 = zeta_2 solved for gamma = T_1/T_2 by bisection in log gamma; a radius not given is 1/2 and a
# mass not given (2R)^d, fractions not given are equal.
ratio=$(awk -v e="$e" -v d="$dim" -v ms="$masses" -v rs="$radii" -v fs="$fractions" '
  function zeta(i, T1, T2,   j, z, s, mu, Ti, Tj) {
    z = 0
    for (j = 1; j <= 2; j++) {
      s = r[i] + r[j]; mu = m[j] / (m[i] + m[j]); Ti = (i == 1 ? T1 : T2); Tj = (j == 1 ? T1 : T2)
      z += x[j] * s ^ (d - 1) * mu * (1 + e) * sqrt(Ti / m[i] + Tj / m[j]) * (2 - mu * (1 + e) * (1 + m[i] * Tj / (m[j] * Ti)))
    }
    return z
  }
  function gap(g) { return zeta(1, g, 1) - zeta(2, g, 1) }
  BEGIN {
    for (i = 1; i <= 2; i++) { r[i] = 0.5; x[i] = 0.5 }
    if (rs != "") split(rs, r, ",")
    if (fs != "") split(fs, x, ",")
    if (ms != "") split(ms, m, ","); else for (i = 1; i <= 2; i++) m[i] = (2 * r[i]) ^ d
    lo = 0.05; hi = 20
    for (k = 0; k < 200; k++) { mid = sqrt(lo * hi); if ((gap(mid) > 0) == (gap(lo) > 0)) lo = mid; else hi = mid }
    printf "%.6f\n", sqrt(lo * hi)
  }')

{
  printf '# species temperatures (docs/DESIGN.md "Mixtures"); Garzo-Dufty T_1/T_2 = %s: time T_1 T_2 T_1/T_2\n' "$ratio"
  "$FIT" table "$run:/observables/temperature_species/value" | awk -F'\t' '
    /^#/ || NF < 3 { next }
    $2 == 0 { t = $1; T1 = $3 } $2 == 1 { if (T1 > 0 && $3 > 0) printf "%s\t%s\t%s\t%.6g\n", t, T1, $3, T1 / $3 }'
} > "$OUT/effect-mixture.tsv.tmp"
mv "$OUT/effect-mixture.tsv.tmp" "$OUT/effect-mixture.tsv"

"${GNUPLOT:-gnuplot}" -e "dir='$OUT'; figsrc='$FIGSRC'; gd=$ratio; e='$e'; masses='$masses'" "$FIGSRC/effect-mixture.gp"
