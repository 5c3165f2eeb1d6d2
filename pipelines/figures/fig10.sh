#!/bin/bash
# fig10.sh "BAM_MASS BAM_ENERGY BAM_ZETA BAM_THETA" "ES" "MASS..." "ENERGY..." "ZETA..." "THETA..."
# (called by Makefile.study via pipelines/bam/bam.mk)
# Fig. 10: the ballistic aggregation model (BAM) against the inelastic gas in 2D: (a) the mean mass
# m(t), (b) the energy E(t), each with its late power law, and the paper's hyperscaling relation
# 2 zeta + d theta = 2d (eq. 5) evaluated from both. Writes $OUT/fig10.tsv (blocks: BAM m, BAM E, then
# the gas's m per e and E per e), $OUT/fig10.fits.tsv and $OUT/fig10.{png,svg}.
set -euo pipefail
: "${FIT:?}" "${OUT:?}" "${FIGSRC:?}" "${L_BAM:?}" "${BAM_ZETA_WIN:?}" "${BAM_THETA_WIN:?}" "${ZETA_WINS:?}" \
  "${THETA_WINS:?}"
. "$FIGSRC/lib.sh"
read -r bmass benergy bzeta btheta <<< "$1"
read -r -a es <<< "$2"; read -r -a mass <<< "$3"; read -r -a energy <<< "$4"
read -r -a zeta <<< "$5"; read -r -a theta <<< "$6"
read -r -a zwins <<< "$ZETA_WINS"; read -r -a twins <<< "$THETA_WINS"
read -r z1 z2 <<< "$BAM_ZETA_WIN"; read -r t1 t2 <<< "$BAM_THETA_WIN"
mkdir -p "$OUT"

{
  table_block "BAM, mean mass m = N0/N(t): ensemble mean and standard error: time m stderr" "$bmass" \
    /average/mean /average/stderr
  table_block "BAM, E(t) per unit mass: ensemble mean and standard error: time E stderr" "$benergy" \
    /average/mean /average/stderr
  per_e_blocks "${es[*]}" "${mass[*]}" "inelastic gas m(t)" "ensemble mean and standard error: time m stderr" \
    /average/mean /average/stderr
  per_e_blocks "${es[*]}" "${energy[*]}" "inelastic gas E(t)" "ensemble mean and standard error: time E stderr" \
    /average/mean /average/stderr
} > "$OUT/fig10.tsv.tmp"

# hyper_row NAME E ZETA_ROW THETA_ROW NOTE: 2 zeta + d theta (d = 2) with its standard error from the two
# fits' (independent fits of different quantities: errors added in quadrature, an upper bound if
# they correlate positively).
hyper_row() {
  awk -F'\t' -v OFS='\t' -v q="$1" -v e="$2" -v note="$5" '
    NR == 1 { z = $3; sz = $4; zw = $5 "-" $6 } NR == 2 { th = $3; st = $4 }
    END {
      ok = (z !~ /nan|inf/ && th !~ /nan|inf/)
      v = ok ? sprintf("%.6g", 2 * z + 2 * th) : "nan"
      s = (ok && sz !~ /nan|inf/ && st !~ /nan|inf/) ? sprintf("%.3g", sqrt(4 * sz * sz + 4 * st * st)) : "nan"
      print q, e, v, s, "-", "-", note
    }' <(printf '%s\n' "$3") <(printf '%s\n' "$4")
}

{
  fits_header 10 "2D: BAM rho = 0.1, L = $L_BAM; inelastic gas as Figs. 3 and 6"
  bz=$("$FIGSRC/fitrow.sh" zeta_bam bam "$bzeta" /fit/exponent /fit/exponent_stderr 1 "$z1" "$z2" \
        "BAM: late-window power law m = A t^zeta of the ensemble mean mass")
  bt=$("$FIGSRC/fitrow.sh" theta_bam bam "$btheta" /fit/exponent /fit/exponent_stderr -1 "$t1" "$t2" \
        "BAM: late-window power law E = B t^-theta of the ensemble E(t)")
  printf '%s\n%s\n' "$bz" "$bt"
  "$FIGSRC/fitrow.sh" zeta_bam_amplitude bam "$bzeta" /fit/amplitude /fit/amplitude_stderr 1 "$z1" "$z2" "A of that fit"
  "$FIGSRC/fitrow.sh" theta_bam_amplitude bam "$btheta" /fit/amplitude /fit/amplitude_stderr 1 "$t1" "$t2" "B of that fit"
  hyper_row hyperscaling_bam bam "$bz" "$bt" "BAM: 2 zeta + d theta (d = 2; eq. 5 says 2d = 4)"
  for i in "${!es[@]}"; do
    e=${es[i]}
    gz=$("$FIGSRC/fitrow.sh" zeta_gas "$e" "${zeta[i]}" /fit/exponent /fit/exponent_stderr 1 \
          "${zwins[i]%_*}" "${zwins[i]#*_}" "inelastic gas: m(t) power law (Fig. 3)")
    gt=$("$FIGSRC/fitrow.sh" theta_gas "$e" "${theta[i]}" /fit/exponent /fit/exponent_stderr -1 \
          "${twins[i]%_*}" "${twins[i]#*_}" "inelastic gas: E(t) power law (Fig. 6)")
    printf '%s\n%s\n' "$gz" "$gt"
    hyper_row hyperscaling_gas "$e" "$gz" "$gt" "inelastic gas: 2 zeta + d theta (d = 2)"
  done
} > "$OUT/fig10.fits.tsv.tmp"

publish 10
get() { fits_column "$OUT/fig10.fits.tsv" "$@"; }
plot 10 "n=${#es[@]}; es='${es[*]}'; zb='$(get zeta_bam 3)'; ab='$(get zeta_bam_amplitude 3)'; tb='$(get theta_bam 3)'; bb='$(get theta_bam_amplitude 3)'; z1='$z1'; z2='$z2'; t1='$t1'; t2='$t2'; hb='$(get hyperscaling_bam 3)'; hbs='$(get hyperscaling_bam 4)'; L='$L_BAM'"
