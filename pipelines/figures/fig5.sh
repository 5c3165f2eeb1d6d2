#!/bin/bash
# fig5.sh E "T1 T2 T3" CORR DOML CORR_RUNS DOM_RUNS   (called by Makefile.study)
# Paper Fig. 5: C(r,t) vs r at three times for one e (0.9); inset: vs r/l (self-similarity in time).
# Writes $OUT/fig5.tsv (block per time: r r/l C), $OUT/fig5.fits.tsv and $OUT/fig5.{png,svg}.
set -euo pipefail
: "${FIT:?}" "${OUT:?}" "${FIGSRC:?}"
. "$FIGSRC/lib.sh"
e=$1; read -r -a ts <<< "$2"; corr=$3 doml=$4 cruns=$5 druns=$6
mkdir -p "$OUT"
for t in "${ts[@]}"; do curve_block "$e" "$t" "$corr" "$doml"; done > "$OUT/fig5.tsv.tmp"
{
  printf '# Fig. 5 (SCALE=%s, e = %s, T0 = 1): shape of C(r,t) vs r/l at several times (mean +- standard error over runs); the e column holds the requested time. Columns: quantity t value stderr t1 t2 note\n' "${SCALE:-?}" "$e"
  for t in "${ts[@]}"; do "$FIGSRC/shape-stats.sh" "$t" "$t" "$cruns" "$druns"; done | shape_fits time
} > "$OUT/fig5.fits.tsv.tmp"
publish 5
plot 5 "n=${#ts[@]}; e='$e'; ts='$(fits_column "$OUT/fig5.fits.tsv" l 5)'"
