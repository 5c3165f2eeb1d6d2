#!/bin/bash
# fig5.sh E "T1 T2 T3" CORR DOML CORR_RUNS DOM_RUNS   (called by Makefile.study)
# Paper Fig. 5: C(r,t) vs r at three times for one e (0.9); inset: vs r/l (self-similarity in time).
# Writes $OUT/fig5.tsv (block per time: r r/l C), $OUT/fig5.fits.tsv and $OUT/fig5.{png,svg}.
set -euo pipefail
: "${FIT:?}" "${OUT:?}" "${FIGSRC:?}"
e=$1; read -r -a ts <<< "$2"; corr=$3 doml=$4 cruns=$5 druns=$6
mkdir -p "$OUT"
args=()
for t in "${ts[@]}"; do
  args+=("e = $e, snapshot nearest t = $t, ensemble mean: r r/l C"
         "'$FIGSRC/corr.sh' curve '$corr:/average/mean' '$doml:/average/mean' '$t'")
done
"$FIGSRC/blocks.sh" "${args[@]}" > "$OUT/fig5.tsv.tmp"
{
  printf '# Fig. 5 (SCALE=%s, e = %s, T0 = 1): shape of C(r,t) vs r/l at several times (mean +- standard error over runs); the e column holds the requested time. Columns: quantity t value stderr t1 t2 note\n' "${SCALE:-?}" "$e"
  for t in "${ts[@]}"; do "$FIGSRC/shape-stats.sh" "$t" "$t" "$cruns" "$druns"; done > "$OUT/fig5.rows.tmp"
  cat "$OUT/fig5.rows.tmp"
  awk -v q=lC_over_l -v what="time" -v lab=time -f "$FIGSRC/collapse-metric.awk" "$OUT/fig5.rows.tmp"
  awk -v q=r0_over_l -v what="time" -v lab=time -f "$FIGSRC/collapse-metric.awk" "$OUT/fig5.rows.tmp"
} > "$OUT/fig5.fits.tsv.tmp"
rm -f "$OUT/fig5.rows.tmp"
tl=$(awk -F'\t' '$1 == "l" { printf "%s ", $5 }' "$OUT/fig5.fits.tsv.tmp")
mv "$OUT/fig5.tsv.tmp" "$OUT/fig5.tsv"; mv "$OUT/fig5.fits.tsv.tmp" "$OUT/fig5.fits.tsv"
"${GNUPLOT:-gnuplot}" -e "dir='$OUT'; n=${#ts[@]}; e='$e'; ts='$tl'; figsrc='$FIGSRC'; scale='${SCALE:-}'" "$FIGSRC/fig5.gp"
