#!/bin/bash
# shell-pipeline.sh [BUILD_DIR]: the tools chained with '-' (an HDF5 file image through each pipe; stdout
# carries only data, messages go to stderr). No HDF5 file is written to disk; the third example keeps its
# two small text tables in temporary files to print them side by side. A few seconds on one core.
#
#   gg-sim ... -o -  |  gg-cluster - -o -  |  gg-fit power-law -:/cluster/mean_mass ... -o -  |  gg-fit table -
set -euo pipefail
B=${1:-build}
SIM=$B/simulate/gg-sim CLUSTER=$B/analyze/gg-cluster CORRELATE=$B/analyze/gg-correlate
DOMAINS=$B/analyze/gg-domains FIT=$B/analyze/gg-fit
scene=$(dirname "$0")/../scenes/fig3-e0.5.ini   # 2D, rho = 0.37, e = 0.5, tc = 1e-4, log-spaced snapshots

echo "1. m(t) of one e = 0.5 run (L = 128) and its power law over 30 <= t <= 300:"
"$SIM" --scene "$scene" --L 128 --t-max 300 --seed 7 --quiet -o - |
  "$CLUSTER" - -o - --rho-c 0.5 |
  "$FIT" power-law -:/cluster/mean_mass --window 30 300 -o - |
  "$FIT" table -:/fit/exponent -:/fit/exponent_stderr -:/fit/amplitude

echo
echo "2. E(t) of the same run straight from the simulation: theta over 30 <= t <= 300 (E ~ t^-theta):"
"$SIM" --scene "$scene" --L 128 --t-max 300 --seed 7 --quiet -o - |
  "$FIT" power-law -:/observables/kinetic_energy/value --window 30 300

echo
echo "3. one simulation, two analyses (tee): correlation length l_C(t) and domain length l(t), last 3 snapshots:"
tmp=$(mktemp); trap 'rm -f "$tmp" "$tmp.l"' EXIT
"$SIM" --scene "$scene" --L 128 --t-max 300 --seed 7 --quiet -o - |
  tee >("$CORRELATE" - -o - | "$FIT" table --no-header -:/correlation/length > "$tmp") |
  "$DOMAINS" - -o - | "$FIT" table --no-header -:/domains/length | tail -3 > "$tmp.l"
wait
sleep 0.2   # the process substitution may finish just after the main pipeline
paste <(tail -3 "$tmp") <(cut -f2 "$tmp.l") | awk 'BEGIN { print "# t\tl_C\tl" } { print }'
