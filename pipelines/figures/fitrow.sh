#!/bin/bash
# fitrow.sh NAME E FILE.h5 VALUE_DS ERR_DS [FACTOR [T1 T2 [NOTE]]]
# One row of a figure's fits table (tab-separated):  NAME  E  value*FACTOR  stderr*|FACTOR|  T1  T2  NOTE
# read from a gg-fit output with `gg-fit table` (scalar datasets; ERR_DS may be '-' for none).
# Undefined numbers stay 'nan' here; figure scripts and summary.sh decide how to show them.
set -euo pipefail
name=$1 e=$2 file=$3 vds=$4 eds=$5 factor=${6:-1} t1=${7:--} t2=${8:--} note=${9:-}
FIT=${FIT:?set FIT to the gg-fit binary}
if [ "$eds" = - ]; then
  row=$("$FIT" table --no-header "$file:$vds")
  row="$row	nan"
else
  row=$("$FIT" table --no-header "$file:$vds" "$file:$eds")
fi
awk -F'\t' -v OFS='\t' -v n="$name" -v e="$e" -v f="$factor" -v t1="$t1" -v t2="$t2" -v note="$note" '
  NR == 1 {
    v = ($1 ~ /nan|inf/) ? $1 : sprintf("%.6g", $1 * f)
    s = ($2 ~ /nan|inf/) ? $2 : sprintf("%.3g", $2 * (f < 0 ? -f : f))
    print n, e, v, s, t1, t2, note
  }' <<< "$row"
