#!/bin/bash
# fig6.sh "ES" "ENERGY..." "THETA..." "HAFF..." ECOLLAPSE   (called by Makefile.study)
# Paper Fig. 6: ensemble E(t) per e, log-log, with the late power law E ~ t^-theta and Haff's law.
# Writes $OUT/fig6.tsv (block per e: time E stderr), $OUT/fig6.fits.tsv and $OUT/fig6.{png,svg}.
set -euo pipefail
: "${FIT:?}" "${OUT:?}" "${FIGSRC:?}" "${THETA_WINS:?}" "${COLLAPSE_WIN:?}"
. "$FIGSRC/lib.sh"
read -r -a es <<< "$1"; read -r -a energy <<< "$2"; read -r -a theta <<< "$3"; read -r -a haff <<< "$4"
ecollapse=$5
read -r -a wins <<< "$THETA_WINS"; read -r c1 c2 <<< "$COLLAPSE_WIN"
mkdir -p "$OUT"

for i in "${!es[@]}"; do
  table_block "E(t) per particle, e = ${es[i]}, ensemble mean and standard error: time E stderr" \
    "${energy[i]}" /average/mean /average/stderr
done > "$OUT/fig6.tsv.tmp"

{
  fits_header 6 "rho = 0.37, T0 = 1"
  for i in "${!es[@]}"; do
    e=${es[i]} w1=${wins[i]%_*} w2=${wins[i]#*_}
    power_law_rows theta "$e" "${theta[i]}" -1 "$w1" "$w2" \
      "late-window power law E = B t^-theta of the ensemble mean" "B of that fit"
    haff_rows "" "$e" "${haff[i]}" "Enskog t0 = 4/((1-e^2) omega0), omega0 = 2 sqrt(pi) rho g sqrt(T0), Henderson g"
  done
  "$FIGSRC/fitrow.sh" theta_common all "$ecollapse" /fit/exponent /fit/exponent_stderr -1 "$c1" "$c2" \
    "common -exponent of all e over a common late window, one amplitude per e"
  ratio_rows energy_amplitude_ratio B "$ecollapse" "${es[*]}" "$c1" "$c2"
} > "$OUT/fig6.fits.tsv.tmp"

publish 6
get() { fits_column "$OUT/fig6.fits.tsv" "$@"; }
plot 6 "n=${#es[@]}; es='${es[*]}'; ths='$(get theta 3)'; bs='$(get theta_amplitude 3)'; t1s='$(get theta 5)'; t2s='$(get theta 6)'; t0s='$(get haff_t0 3)'; e0s='$(get haff_E0 3)'"
