#!/bin/bash
# fig4.sh "ES" "T..." "CORR..." "DOML..." "CORR_RUNS..." "DOM_RUNS..."   (called by Makefile.study)
# Paper Fig. 4: ensemble C(r,t) vs r/l for each e at a time in its late (scaling) regime.
# Writes $OUT/fig4.tsv (block per e: r r/l C), $OUT/fig4.fits.tsv (l, l_C/l, r_0/l per e with errors over
# runs, and the largest deviation between e) and $OUT/fig4.{png,svg}.
set -euo pipefail
: "${FIT:?}" "${OUT:?}" "${FIGSRC:?}"
read -r -a es <<< "$1"; read -r -a ts <<< "$2"; read -r -a corr <<< "$3"; read -r -a doml <<< "$4"
read -r -a cruns <<< "$5"; read -r -a druns <<< "$6"
mkdir -p "$OUT"
args=()
for i in "${!es[@]}"; do
  args+=("e = ${es[i]}, snapshot nearest t = ${ts[i]}, ensemble mean: r r/l C"
         "'$FIGSRC/corr.sh' curve '${corr[i]}:/average/mean' '${doml[i]}:/average/mean' '${ts[i]}'")
done
"$FIGSRC/blocks.sh" "${args[@]}" > "$OUT/fig4.tsv.tmp"
{
  printf '# Fig. 4 (SCALE=%s, T0 = 1): shape of C(r,t) vs r/l per e (mean +- standard error over runs). Columns: quantity e value stderr t1 t2 note\n' "${SCALE:-?}"
  for i in "${!es[@]}"; do "$FIGSRC/shape-stats.sh" "${es[i]}" "${ts[i]}" "${cruns[i]}" "${druns[i]}"; done > "$OUT/fig4.rows.tmp"
  cat "$OUT/fig4.rows.tmp"
  awk -v q=lC_over_l -v what="e" -v lab=e -f "$FIGSRC/collapse-metric.awk" "$OUT/fig4.rows.tmp"
  awk -v q=r0_over_l -v what="e" -v lab=e -f "$FIGSRC/collapse-metric.awk" "$OUT/fig4.rows.tmp"
} > "$OUT/fig4.fits.tsv.tmp"
rm -f "$OUT/fig4.rows.tmp"
tl=""; for i in "${!es[@]}"; do
  tl+="$(awk -F'\t' -v e="${es[i]}" '$1 == "l" && $2 == e { print $5 }' "$OUT/fig4.fits.tsv.tmp") "
done
mv "$OUT/fig4.tsv.tmp" "$OUT/fig4.tsv"; mv "$OUT/fig4.fits.tsv.tmp" "$OUT/fig4.fits.tsv"
"${GNUPLOT:-gnuplot}" -e "dir='$OUT'; n=${#es[@]}; es='${es[*]}'; ts='$tl'; figsrc='$FIGSRC'; scale='${SCALE:-}'" "$FIGSRC/fig4.gp"
