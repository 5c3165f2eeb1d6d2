#!/bin/bash
# fig9.sh "ES" "ENERGY..." "MASS..." "LARGEST..." "HAFF..." "THETA..." "ZETA..." "ZETA_LARGEST..." "LOCAL..."
# (called by Makefile.study via pipelines/spheres/spheres.mk)
# Fig. 9: 3D inelastic hard spheres at eta = 0.288: (a) ensemble E(t) per e with Haff's law and the late
# power law t^-theta, (b) m(t) and the largest cluster with late power laws, (c) the local exponent of m.
# Writes $OUT/fig9.tsv (blocks: E per e, m per e, largest per e, local exponent per e),
# $OUT/fig9.fits.tsv and $OUT/fig9.{png,svg}.
set -euo pipefail
: "${FIT:?}" "${OUT:?}" "${FIGSRC:?}" "${THETA_WINS:?}" "${ZETA_WINS:?}" "${L3:?}"
. "$FIGSRC/lib.sh"
read -r -a es <<< "$1"; read -r -a energy <<< "$2"; read -r -a mass <<< "$3"; read -r -a largest <<< "$4"
read -r -a haff <<< "$5"; read -r -a theta <<< "$6"; read -r -a zeta <<< "$7"; read -r -a zetal <<< "$8"
read -r -a local <<< "$9"
read -r -a twins <<< "$THETA_WINS"; read -r -a zwins <<< "$ZETA_WINS"
mkdir -p "$OUT"

{
  per_e_blocks "${es[*]}" "${energy[*]}" "3D E(t) per particle" "ensemble mean and standard error: time E stderr" \
    /average/mean /average/stderr
  per_e_blocks "${es[*]}" "${mass[*]}" "3D m(t)" "ensemble mean and standard error: time m stderr" \
    /average/mean /average/stderr
  per_e_blocks "${es[*]}" "${largest[*]}" "3D largest cluster" "ensemble mean and standard error: time mass stderr" \
    /average/mean /average/stderr
  per_e_blocks "${es[*]}" "${local[*]}" "3D local exponent d ln m / d ln t (0.5-decade sliding fits)" "time z stderr" \
    /local_exponent/exponent /local_exponent/stderr
} > "$OUT/fig9.tsv.tmp"

{
  fits_header 9 "3D, rho = 0.55 (eta = 0.288), L = $L3, T0 = 1"
  for i in "${!es[@]}"; do
    e=${es[i]} t1=${twins[i]%_*} t2=${twins[i]#*_} z1=${zwins[i]%_*} z2=${zwins[i]#*_}
    haff_rows _3d "$e" "${haff[i]}" \
      "Enskog t0 = 6/((1-e^2) omega0), omega0 = 4 sqrt(pi) rho g sqrt(T0), Carnahan-Starling g"
    power_law_rows theta_3d "$e" "${theta[i]}" -1 "$t1" "$t2" \
      "late-window power law E = B t^-theta of the ensemble mean" "B of that fit"
    power_law_rows zeta_3d "$e" "${zeta[i]}" 1 "$z1" "$z2" \
      "late-window power law m = A t^zeta of the ensemble mean" "A of that fit"
    power_law_rows zeta_largest_3d "$e" "${zetal[i]}" 1 "$z1" "$z2" \
      "late-window power law of the ensemble largest cluster" "amplitude of that fit"
    # How much of the box the largest cluster holds at the end (finite size when it approaches 1).
    N=$(h5dump -a /parameters/N "${energy[i]}" | sed -n 's/^ *(0): *\([0-9]*\)$/\1/p')
    "$FIT" table --no-header "${largest[i]}:/average/mean" | tail -1 |
      awk -F'\t' -v OFS='\t' -v e="$e" -v N="$N" '
        { f = (N + 0 <= 0) ? "nan" : sprintf("%.4g", $2 / N)
          print "largest_fraction_3d", e, f, "nan", $1, $1, "largest cluster / N at t_max (N = " N ")" }'
  done
} > "$OUT/fig9.fits.tsv.tmp"

publish 9
get() { fits_column "$OUT/fig9.fits.tsv" "$@"; }
plot 9 "n=${#es[@]}; es='${es[*]}'; ths='$(get theta_3d 3)'; bs='$(get theta_3d_amplitude 3)'; t1s='$(get theta_3d 5)'; t2s='$(get theta_3d 6)'; t0s='$(get haff_t0_3d 3)'; e0s='$(get haff_E0_3d 3)'; zs='$(get zeta_3d 3)'; as='$(get zeta_3d_amplitude 3)'; z1s='$(get zeta_3d 5)'; z2s='$(get zeta_3d 6)'; zls='$(get zeta_largest_3d 3)'; als='$(get zeta_largest_3d_amplitude 3)'; L3='$L3'"
