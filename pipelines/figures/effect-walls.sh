#!/bin/bash
# effect-walls.sh PROFILE.h5 SCENE.ini (called by Makefile.study via pipelines/effects/effect-walls.mk)
# Walls and gravity in 2D: the density n(y) and temperature T(y) of an elastic gas over a thermal wall,
# averaged over the run's snapshots (gg-velocity --profile y), against the hydrostatic balance
# dp/dy = -n g with Henderson's hard-disk pressure p = n T (1 + eta^2/8) / (1 - eta)^2 at T = T_w, and
# against the barometric profile of an ideal gas (docs/PHYSICS.md "Walls and gravity"). Both theories
# hold the run's N / L disks per unit length between the floor's and the ceiling's contact heights.
# Writes $OUT/effect-walls.tsv (height n n_err T T_err n_henderson n_barometric), .fits.tsv, .png, .svg.
set -euo pipefail
: "${OUT:?}" "${FIGSRC:?}"
. "$FIGSRC/lib.sh"
profile=$1 scene=$2
mkdir -p "$OUT"

[ "$(scene_value "$scene" dim)" = 2 ] || { echo "effect-walls.sh: the figure is drawn for 2D scenes (Henderson's disks)" >&2; exit 2; }
N=$(scene_value "$scene" N) L=$(scene_value "$scene" L) H=$(scene_value "$scene" walls) g=$(scene_value "$scene" gravity) Tw=$(scene_value "$scene" wall-T)

column() { profile_column "$profile" "$1"; }
paste <(column position) <(column density) <(column density_stderr) <(column temperature) \
  <(column temperature_stderr) > "$OUT/effect-walls.tsv.tmp.in"

# The two theories at each slab centre: n' = -n g / (T d(n Z)/dn) integrated by RK4 from the floor's
# contact height 1/2 to H - 1/2 (Z = 1 for the ideal gas), the density at the floor set by bisection so
# that the column holds N / L disks per unit length; then, over the run's slabs from 3 diameters above
# the floor (a dense fluid layers against the wall) to where n falls below 0.02, each theory's chi^2 per
# slab with the profile's standard errors (about 1 for a theory that describes the data).
awk -F'\t' -v OFS='\t' -v N="$N" -v L="$L" -v H="$H" -v g="$g" -v T="$Tw" -v out="$OUT/effect-walls.fits.tsv.tmp" '
  function slope(n, ideal,   eta, Z, dZ) {
    if (ideal) return 1
    eta = pi * n / 4; Z = (1 + eta * eta / 8) / ((1 - eta) ^ 2)
    dZ = (eta / 4) / ((1 - eta) ^ 2) + 2 * (1 + eta * eta / 8) / ((1 - eta) ^ 3)
    return Z + eta * dZ
  }
  function f(n, ideal) { return -n * g / (T * slope(n, ideal)) }
  # Integrates from n0; returns the column total, and fills at[] at the slab centres if fill.
  function column(n0, ideal, fill,   n, z, total, a, b, c, d, next_n, k) {
    n = n0; z = 0.5; total = 0; k = 1
    while (z < H - 0.5) {
      while (fill && k <= rows && y[k] <= z + h / 2) at[k++] = n
      a = f(n, ideal); b = f(n + h / 2 * a, ideal); c = f(n + h / 2 * b, ideal); d = f(n + h * c, ideal)
      next_n = n + h / 6 * (a + 2 * b + 2 * c + d)
      total += h / 2 * (n + next_n); n = next_n; z += h
    }
    return total
  }
  function profile(ideal, into,   lo, hi, mid, it, k) {
    lo = 0; hi = ideal ? 10 : 4 / pi
    for (it = 0; it < 60; ++it) { mid = (lo + hi) / 2; if (column(mid, ideal, 0) < N / L) lo = mid; else hi = mid }
    delete at; column((lo + hi) / 2, ideal, 1)
    for (k = 1; k <= rows; ++k) into[k] = (k in at) ? at[k] : 0
  }
  { rows++; y[rows] = $1; line[rows] = $0; n_run[rows] = $2; err[rows] = $3 }
  END {
    pi = atan2(0, -1); h = 1e-3
    profile(0, hs); profile(1, ba)
    print "# elastic disks over a thermal wall (T_w = " T ", g = " g ", N = " N ", L = " L ", H = " H "): height n n_err T T_err n_henderson n_barometric"
    for (k = 1; k <= rows; ++k) {
      print line[k], hs[k], ba[k]
      if (y[k] >= 3 && hs[k] > 0.02 && err[k] > 0) {
        ch += ((n_run[k] - hs[k]) / err[k]) ^ 2; cb += ((n_run[k] - ba[k]) / err[k]) ^ 2; m++
      }
    }
    print "# Walls and gravity (2D). Columns: quantity e value stderr t1 t2 note" > out
    print "henderson_chi2", 1, ch / m, "nan", "-", "-", "chi^2 per slab of n against hydrostatics with Henderson pressure, " m " slabs from 3 diameters up where n > 0.02" > out
    print "barometric_chi2", 1, cb / m, "nan", "-", "-", "chi^2 per slab of n against the barometric profile, the same slabs" > out
  }' "$OUT/effect-walls.tsv.tmp.in" > "$OUT/effect-walls.tsv.tmp"
rm -f "$OUT/effect-walls.tsv.tmp.in"
publish_as effect-walls
plot_as effect-walls "Tw = '$Tw'; g = '$g'; \
  ch = '$(fits_column "$OUT/effect-walls.fits.tsv" henderson_chi2 3)'; \
  cb = '$(fits_column "$OUT/effect-walls.fits.tsv" barometric_chi2 3)'"
