#!/bin/bash
# effect-shear.sh RUN.h5 PROFILE.h5 SCENE.ini (called by Makefile.study via pipelines/effects/effect-shear.mk)
# Uniform shear flow in 3D: the reduced shear rate a* = a / (chi nu0(n, T)) and the reduced pressure
# tensor P*_ab = P_ab / (n T) of one run against their steady values by Grad's method for the dilute
# granular gas (Santos, Garzo & Dufty, PRE 69, 061303 (2004); docs/PHYSICS.md "Uniform shear flow"),
#   zeta* = 5 (1 - e^2) / 12,  beta = (1 + e)(9 - 3 e) / 12,  P*_yy = P*_zz = 1 - zeta*/beta,
#   P*_xx = 1 + 2 zeta*/beta,  a*^2 = (3/2) zeta* beta^2 / (beta - zeta*),  P*_xy = -a* P*_yy / beta,
# with nu0 = (16/5) sqrt(pi) n sqrt(T) and chi of Carnahan-Starling; and the profiles along y (gg-velocity
# --profile y) against the linear flow a (y - L/2). The run's P includes the collisional transfer, O(phi)
# above the Boltzmann theory's. Writes $OUT/effect-shear.tsv (strain a* P*_xx P*_yy P*_zz P*_xy),
# .profile.tsv (height n/n u_x u_x_err T/T u_x_theory), .fits.tsv (the steady means from the first
# snapshot on, with Grad's values), .png and .svg.
set -euo pipefail
: "${FIT:?}" "${OUT:?}" "${FIGSRC:?}"
. "$FIGSRC/lib.sh"
run=$1 profile=$2 scene=$3
mkdir -p "$OUT"

[ "$(scene_value "$scene" dim)" = 3 ] || { echo "effect-shear.sh: the figure is drawn for 3D scenes (nu0 of spheres)" >&2; exit 2; }
a=$(scene_value "$scene" shear-rate) n=$(scene_value "$scene" rho) e=$(scene_value "$scene" e)
N=$(scene_value "$scene" N) from=$(scene_value "$scene" snapshots-from)

# Every sample time with E and the pressure tensor (the tensor has none at the first sample).
tables=$(mktemp -d)
trap 'rm -rf "$tables"' EXIT
for q in kinetic_energy pressure_xx pressure_yy pressure_zz pressure_xy; do
  "$FIT" table --no-header "$run:/observables/$q/value" > "$tables/$q"
done
awk -F'\t' -v OFS='\t' -v a="$a" -v n="$n" -v e="$e" -v from="$from" -v out="$OUT/effect-shear.fits.tsv.tmp" '
  FNR == 1 { file++ }
  file == 1 { E[$1] = $2; next }
  { P[file, $1] = $2; if (file == 2) t[++m] = $1 }
  END {
    pi = atan2(0, -1); phi = pi * n / 6; chi = (1 - phi / 2) / (1 - phi) ^ 3
    print "# sheared spheres, e = " e ", a = " a ", n = " n ": strain a* P*_xx P*_yy P*_zz P*_xy"
    for (k = 1; k <= m; ++k) {
      T = 2 * E[t[k]] / 3; s = a / (chi * 16 / 5 * sqrt(pi) * n * sqrt(T))
      row = a * t[k] OFS s
      for (f = 2; f <= 5; ++f) { x[f] = P[f, t[k]] / (n * T); row = row OFS x[f] }
      print row
      if (t[k] >= from) { c++; mean[1] += s; for (f = 2; f <= 5; ++f) mean[f] += x[f] }
    }
    z = 5 * (1 - e * e) / 12; b = (1 + e) * (9 - 3 * e) / 12
    g[1] = sqrt(1.5 * z * b * b / (b - z)); g[2] = 1 + 2 * z / b; g[3] = 1 - z / b; g[4] = g[3]; g[5] = -g[1] * g[3] / b
    split("a_star P_xx P_yy P_zz P_xy", name, " ")
    print "# Uniform shear flow (3D). Columns: quantity e value stderr t1 t2 note" > out
    for (f = 1; f <= 5; ++f) {
      print name[f], e, mean[f] / c, "nan", from, t[m], "mean over the samples from the first snapshot on" > out
      print name[f] "_grad", e, g[f], "nan", "-", "-", "steady value of Grad'\''s method (dilute: Boltzmann)" > out
    }
  }' "$tables/kinetic_energy" "$tables/pressure_xx" "$tables/pressure_yy" "$tables/pressure_zz" "$tables/pressure_xy" \
  > "$OUT/effect-shear.tsv.tmp"

# The profiles (u_x is the first of each velocity's three components).
column() { profile_column "$profile" "$1"; }
every_third() { awk 'NR % 3 == 1'; }
paste <(column position) <(column density) <(column velocity | every_third) <(column velocity_stderr | every_third) \
  <(column temperature) |
  awk -F'\t' -v OFS='\t' -v a="$a" -v n="$n" -v N="$N" '
    { y[++m] = $1; rho[m] = $2; u[m] = $3; du[m] = $4; T[m] = $5; Tsum += $5 }
    END {
      L = (N / n) ^ (1 / 3)
      print "# profile along y: height n/n u_x u_x_err T/T u_x_theory (a (y - L/2))"
      for (k = 1; k <= m; ++k) print y[k], rho[k] / n, u[k], du[k], T[k] / (Tsum / m), a * (y[k] - L / 2)
    }' > "$OUT/effect-shear.profile.tsv.tmp"
publish_as effect-shear
mv "$OUT/effect-shear.profile.tsv.tmp" "$OUT/effect-shear.profile.tsv"
plot_as effect-shear "e = '$e'; a = '$a'; \
  got = '$(awk -F'\t' '$1 !~ /_grad$/ && !/^#/ { printf "%s ", $3 }' "$OUT/effect-shear.fits.tsv")'; \
  grad = '$(awk -F'\t' '$1 ~ /_grad$/ { printf "%s ", $3 }' "$OUT/effect-shear.fits.tsv")'"
