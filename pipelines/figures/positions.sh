#!/bin/bash
# positions.sh FILE.h5 FRAME: particle positions of one snapshot of a gg-sim H5MD file as "x y" (or "x"
# in 1D) lines, read with h5dump (hdf5-tools). FRAME counts from 0.
set -euo pipefail
file=$1 frame=$2
ds=/particles/all/position/value
# dimensions "T, N, d" from h5ls
dims=$(h5ls "$file$ds" | sed -n 's/.*Dataset {\([^}]*\)}.*/\1/p' | tr -d ' ')
IFS=, read -r nt np nd <<< "${dims%%/*}"
[ "$frame" -lt "$nt" ] || { echo "positions.sh: $file has $nt snapshots, no frame $frame" >&2; exit 1; }
tmp=$(mktemp); trap 'rm -f "$tmp"' EXIT
h5dump -d "$ds" -s "$frame,0,0" -c "1,$np,$nd" -y -w 0 -m '%.5g' -o "$tmp" "$file" > /dev/null
tr -s ', \n' '\n' < "$tmp" | awk -v d="$nd" 'NF { v[++k] = $1; if (k == d) { line = v[1]; for (j = 2; j <= d; ++j) line = line "\t" v[j]; print line; k = 0 } }'
