#!/bin/bash
# effect-rough.sh RUN.h5 SCENE.ini (called by Makefile.study via pipelines/effects/effect-rough.mk)
# Rough particles in 2D: T_tr(t) = 2 E_tr / d and T_rot(t) = 2 E_rot / d_rot (d = 2, d_rot = 1) of one
# cooling run, and T_rot / T_tr against the steady ratio of the Maxwellian theory (docs/PHYSICS.md
# "Rough particles"). Writes $OUT/effect-rough.tsv (time T_tr T_rot T_rot/T_tr collisions per particle),
# $OUT/effect-rough.fits.tsv and $OUT/effect-rough.{png,svg}.
set -euo pipefail
: "${FIT:?}" "${OUT:?}" "${FIGSRC:?}"
. "$FIGSRC/lib.sh"
run=$1 scene=$2
mkdir -p "$OUT"

# The scene's e, beta and q (--inertia, else a uniform disk's 1/2).
e=$(scene_value "$scene" e); beta=$(scene_value "$scene" beta); q=$(scene_value "$scene" inertia); q=${q:-0.5}
[ "$(scene_value "$scene" dim)" = 2 ] || { echo "effect-rough.sh: the figure is drawn for 2D scenes (T_rot with d_rot = 1)" >&2; exit 2; }

# The steady ratio r of the mean field in 2D (a = 1 tangential direction, d_rot = 1, k = q (1 + beta) /
# (1 + q)): 2 <dE_rot> = r <dE_tr>, the positive root of c2 r^2 + c1 r + c0 = 0.
theory=$(awk -v e="$e" -v b="$beta" -v q="$q" 'BEGIN {
  k = q * (1 + b) / (1 + q)
  c2 = k * k / (2 * q); c1 = -(1 - e * e) - k + k * k / 2 - 2 * (-k / q + k * k / (2 * q * q)); c0 = -k * k / q
  printf "%.6g", (-c1 + sqrt(c1 * c1 - 4 * c2 * c0)) / (2 * c2) }')

{
  printf '# rough disks, e = %s, beta = %s, q = %s: time T_tr T_rot T_rot/T_tr collisions_per_particle\n' "$e" "$beta" "$q"
  "$FIT" table --no-header "$run:/observables/kinetic_energy/value" "$run:/observables/rotational_energy/value" \
    "$run:/observables/collisions_per_particle/value" |
    awk -F'\t' -v OFS='\t' '$2 > 0 { print $1, $2, 2 * $3, 2 * $3 / $2, $4 }'
} > "$OUT/effect-rough.tsv.tmp"

# The run's mean ratio over 10 to 40 collisions per particle (past the transient, before the
# homogeneous state gives way), as rough_test measures it.
mean=$(awk -F'\t' '!/^#/ && $5 >= 10 && $5 <= 40 { s += $4; n++ } END { print n ? sprintf("%.6g", s / n) : "nan" }' \
  "$OUT/effect-rough.tsv.tmp")
{
  printf '# Rough particles (2D, e = %s, beta = %s, q = %s). Columns: quantity e value stderr t1 t2 note\n' "$e" "$beta" "$q"
  printf 'ratio_theory\t%s\t%s\tnan\t-\t-\tsteady T_rot/T_tr of the Maxwellian mean field (Huthmann & Zippelius; Luding et al.)\n' "$e" "$theory"
  printf 'ratio_measured\t%s\t%s\tnan\t-\t-\tmean T_rot/T_tr over the samples at 10 to 40 collisions per particle\n' "$e" "$mean"
} > "$OUT/effect-rough.fits.tsv.tmp"
publish_as effect-rough
plot_as effect-rough "e = '$e'; beta = '$beta'; q = '$q'; r = '$theory'; m = '$mean'"
