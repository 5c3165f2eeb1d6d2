#!/bin/bash
# fig4.sh "ES" "T..." "CORR..." "DOML..." "CORR_RUNS..." "DOM_RUNS..."   (called by Makefile.study)
# Paper Fig. 4: ensemble C(r,t) vs r/l for each e at a time in its late (scaling) regime.
# Writes $OUT/fig4.tsv (block per e: r r/l C), $OUT/fig4.fits.tsv (l, l_C/l, r_0/l per e with errors over
# runs, and the largest deviation between e) and $OUT/fig4.{png,svg}.
set -euo pipefail
: "${FIT:?}" "${OUT:?}" "${FIGSRC:?}"
. "$FIGSRC/lib.sh"
read -r -a es <<< "$1"; read -r -a ts <<< "$2"; read -r -a corr <<< "$3"; read -r -a doml <<< "$4"
read -r -a cruns <<< "$5"; read -r -a druns <<< "$6"
mkdir -p "$OUT"
for i in "${!es[@]}"; do curve_block "${es[i]}" "${ts[i]}" "${corr[i]}" "${doml[i]}"; done > "$OUT/fig4.tsv.tmp"
{
  printf '# Fig. 4 (SCALE=%s, T0 = 1): shape of C(r,t) vs r/l per e (mean +- standard error over runs). Columns: quantity e value stderr t1 t2 note\n' "${SCALE:-?}"
  for i in "${!es[@]}"; do "$FIGSRC/shape-stats.sh" "${es[i]}" "${ts[i]}" "${cruns[i]}" "${druns[i]}"; done | shape_fits e
} > "$OUT/fig4.fits.tsv.tmp"
publish 4
plot 4 "n=${#es[@]}; es='${es[*]}'; ts='$(fits_column "$OUT/fig4.fits.tsv" l 5)'"
