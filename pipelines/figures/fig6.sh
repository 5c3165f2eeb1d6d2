#!/bin/bash
# fig6.sh "ES" "ENERGY..." "THETA..." "HAFF..." ECOLLAPSE   (called by Makefile.study)
# Paper Fig. 6: ensemble E(t) per e, log-log, with the late power law E ~ t^-theta and Haff's law.
# Writes $OUT/fig6.tsv (block per e: time E stderr), $OUT/fig6.fits.tsv and $OUT/fig6.{png,svg}.
set -euo pipefail
: "${FIT:?}" "${OUT:?}" "${FIGSRC:?}" "${THETA_WINS:?}" "${COLLAPSE_WIN:?}"
read -r -a es <<< "$1"; read -r -a energy <<< "$2"; read -r -a theta <<< "$3"; read -r -a haff <<< "$4"
ecollapse=$5
read -r -a wins <<< "$THETA_WINS"; read -r c1 c2 <<< "$COLLAPSE_WIN"
mkdir -p "$OUT"
args=()
for i in "${!es[@]}"; do args+=("E(t) per particle, e = ${es[i]}, ensemble mean and standard error: time E stderr"
                                  "'$FIT' table '${energy[i]}:/average/mean' '${energy[i]}:/average/stderr'"); done
"$FIGSRC/blocks.sh" "${args[@]}" > "$OUT/fig6.tsv.tmp"
{
  printf '# Fig. 6 fits (SCALE=%s; rho = 0.37, T0 = 1; errors: %s over runs). Columns: quantity e value stderr t1 t2 note\n' \
    "${SCALE:-?}" "${ERRORS:-jackknife}"
  for i in "${!es[@]}"; do
    e=${es[i]} w1=${wins[i]%_*} w2=${wins[i]#*_}
    "$FIGSRC/fitrow.sh" theta "$e" "${theta[i]}" /fit/exponent /fit/exponent_stderr -1 "$w1" "$w2" \
      "late-window power law E = B t^-theta of the ensemble mean"
    "$FIGSRC/fitrow.sh" theta_amplitude "$e" "${theta[i]}" /fit/amplitude /fit/amplitude_stderr 1 "$w1" "$w2" "B of that fit"
    h1=$("$FIT" table --no-header "${haff[i]}:/fit/window" | head -1 | cut -f1)
    h2=$("$FIT" table --no-header "${haff[i]}:/fit/window" | tail -1 | cut -f1)
    "$FIGSRC/fitrow.sh" haff_t0 "$e" "${haff[i]}" /fit/t0 /fit/t0_stderr 1 "$h1" "$h2" \
      "Haff fit E = E0/(1+t/t0)^2 over the early window"
    "$FIGSRC/fitrow.sh" haff_E0 "$e" "${haff[i]}" /fit/E0 /fit/E0_stderr 1 "$h1" "$h2" "E0 of that fit"
    "$FIGSRC/fitrow.sh" haff_t0_enskog "$e" "${haff[i]}" /fit/t0_enskog - 1 - - \
      "Enskog t0 = 4/((1-e^2) omega0), omega0 = 2 sqrt(pi) rho g sqrt(T0), Henderson g"
    "$FIGSRC/fitrow.sh" haff_t0_ratio "$e" "${haff[i]}" /fit/t0_ratio /fit/t0_ratio_stderr 1 "$h1" "$h2" \
      "fitted t0 / Enskog t0 (1 = Haff's law with the Enskog rate)"
  done
  "$FIGSRC/fitrow.sh" theta_common all "$ecollapse" /fit/exponent /fit/exponent_stderr -1 "$c1" "$c2" \
    "common -exponent of all e over a common late window, one amplitude per e"
  "$FIT" table --no-header "$ecollapse:/fit/amplitude_ratio" "$ecollapse:/fit/amplitude_ratio_stderr" "$ecollapse:/fit/agree" |
    awk -F'\t' -v OFS='\t' -v es="${es[*]}" -v c1="$c1" -v c2="$c2" '
      BEGIN { split(es, e, " ") }
      { print "energy_amplitude_ratio", e[NR], sprintf("%.4g", $1), sprintf("%.3g", $2), c1, c2,
              "B(e)/B(" e[1] ") at the common exponent; gg-fit agree (2 sigma) = " $3 }'
} > "$OUT/fig6.fits.tsv.tmp"
get() { awk -F"\t" -v q="$1" -v c="$2" '$1 == q { printf "%s ", $c }' "$OUT/fig6.fits.tsv"; }
mv "$OUT/fig6.tsv.tmp" "$OUT/fig6.tsv"; mv "$OUT/fig6.fits.tsv.tmp" "$OUT/fig6.fits.tsv"
"${GNUPLOT:-gnuplot}" -e "dir='$OUT'; n=${#es[@]}; es='${es[*]}'; ths='$(get theta 3)'; bs='$(get theta_amplitude 3)'; t1s='$(get theta 5)'; t2s='$(get theta 6)'; t0s='$(get haff_t0 3)'; e0s='$(get haff_E0 3)'; figsrc='$FIGSRC'; scale='${SCALE:-}'" \
  "$FIGSRC/fig6.gp"
