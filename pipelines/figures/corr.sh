#!/bin/bash
# corr.sh curve|shape CORR.h5:/ds DOM.h5:/ds T   -- see corr-shape.awk (needs FIT and A).
set -euo pipefail
mode=$1 corr=$2 dom=$3 T=$4
: "${FIT:?}"
awk -v T="$T" -v a="${A:-0.5}" -v mode="$mode" -f "$FIGSRC/corr-shape.awk" \
  <("$FIT" table --no-header "$dom") <("$FIT" table --no-header "$corr")
