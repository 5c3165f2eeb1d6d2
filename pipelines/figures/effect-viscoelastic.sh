#!/bin/bash
# effect-viscoelastic.sh RUN.h5 SCENE.ini (called by Makefile.study via pipelines/effects/effect-viscoelastic.mk)
# Viscoelastic particles in 3D: T(t) = 2 E / 3 of one cooling run against the kinetic theory of the dilute
# gas (Schwager & Poschel, PRE 57, 650 (1998); docs/PHYSICS.md "Viscoelastic particles"),
#   dT/dt = -(omega0(T) / 3) T <1 - eps(K g^(1/5))^2>,  omega0 = 4 sqrt(pi) n chi sqrt(T),
# the mean over impact speeds g with weight g^3 exp(-g^2 / 4T), chi of Carnahan-Starling, integrated
# here by RK4 from the run's T at t = 1. eps is the series 1 - 1.15344 kappa + 0.79826 kappa^2 (Ramirez
# et al. 1999), within 1e-3 of the Hertz law at the kappa < 0.1 of this scene. Writes
# $OUT/effect-viscoelastic.tsv (time T T_theory), .fits.tsv (the late exponents), .png and .svg.
set -euo pipefail
: "${FIT:?}" "${OUT:?}" "${FIGSRC:?}"
. "$FIGSRC/lib.sh"
run=$1 scene=$2
mkdir -p "$OUT"

[ "$(scene_value "$scene" dim)" = 3 ] || { echo "effect-viscoelastic.sh: the figure is drawn for 3D scenes (omega0 of spheres)" >&2; exit 2; }
K=$(scene_value "$scene" viscoelastic) rho=$(scene_value "$scene" rho)

"$FIT" table --no-header "$run:/observables/kinetic_energy/value" |
  awk -F'\t' -v OFS='\t' -v K="$K" -v n="$rho" -v out="$OUT/effect-viscoelastic.fits.tsv.tmp" '
    function loss(T,   gmax, dg, k, g, w, kap, eps, num, den) {
      gmax = 12 * sqrt(T); dg = gmax / 400; num = 0; den = 0
      for (k = 1; k <= 400; ++k) {
        g = (k - 0.5) * dg; w = g * g * g * exp(-g * g / (4 * T))
        kap = K * g ^ 0.2; eps = 1 - 1.15344 * kap + 0.79826 * kap * kap
        num += w * (1 - eps * eps); den += w
      }
      return num / den
    }
    function rate(T) { return -(c * sqrt(T) / 3) * T * loss(T) }
    # RK4 from the present T over [t0, t1] in steps of a hundredth of the time already elapsed.
    function advance(T, t0, t1,   h, steps, s, a, b, cc, d) {
      steps = 100; h = (t1 - t0) / steps
      for (s = 0; s < steps; ++s) {
        a = rate(T); b = rate(T + h / 2 * a); cc = rate(T + h / 2 * b); d = rate(T + h * cc)
        T += h / 6 * (a + 2 * b + 2 * cc + d)
      }
      return T
    }
    $1 >= 1 { t[++m] = $1; T[m] = 2 * $2 / 3 }
    END {
      pi = atan2(0, -1); phi = pi * n / 6
      c = 4 * sqrt(pi) * n * (1 - phi / 2) / (1 - phi) ^ 3
      print "# viscoelastic spheres, K = " K ", rho = " n ": time T T_theory"
      th[1] = T[1]; print t[1], T[1], th[1]
      for (k = 2; k <= m; ++k) { th[k] = advance(th[k - 1], t[k - 1], t[k]); print t[k], T[k], th[k] }
      # The late local exponents over the last factor 2 in time.
      for (k = m; k > 1 && t[k] > t[m] / 2; --k) a = k
      s_run = log(T[m] / T[a]) / log(t[m] / t[a]); s_th = log(th[m] / th[a]) / log(t[m] / t[a])
      print "# Viscoelastic particles (3D). Columns: quantity e value stderr t1 t2 note" > out
      print "late_exponent", "-", s_run, "nan", t[a], t[m], "d ln T / d ln t of the run" > out
      print "late_exponent_theory", "-", s_th, "nan", t[a], t[m], "the same of the kinetic theory (-5/3 asymptotically)" > out
      print "T_ratio_end", "-", T[m] / th[m], "nan", t[m], t[m], "T / T_theory at the end of the run" > out
    }' > "$OUT/effect-viscoelastic.tsv.tmp"
publish_as effect-viscoelastic
plot_as effect-viscoelastic "K = '$K'; \
  zr = '$(fits_column "$OUT/effect-viscoelastic.fits.tsv" late_exponent 3)'; \
  zt = '$(fits_column "$OUT/effect-viscoelastic.fits.tsv" late_exponent_theory 3)'; \
  $(awk -F'\t' '!/^#/ { t = $1; T = $3 } END { printf "te = %s; Te = %s", t, T }' "$OUT/effect-viscoelastic.tsv")"
