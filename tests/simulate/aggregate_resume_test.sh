#!/usr/bin/env bash
# An aggregating run (--aggregate, the ballistic aggregation model) stopped by SIGTERM and resumed from
# its checkpoint gives data bit-identical to the uninterrupted run, in 1D, 2D and 3D: the checkpoint
# holds the masses and radii, which start particle each one merged into, and the cells as the last
# regrid left them. SIGTERM is sent once a periodic checkpoint holds fewer than half the particles, so
# the run is stopped part way whatever the machine's speed, after merges and regrids.
# usage: aggregate_resume_test.sh GG_SIM
set -euo pipefail
sim=$(realpath "$1")
# shellcheck source=../h5_same.sh
source "$(dirname "$(realpath "$0")")/../h5_same.sh"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"

# Two outputs hold the same data, bit for bit (all but provenance).
same() { h5_same "$1" "$2" /observables /particles; }

check() {  # DIM: one scene in that dimension, uninterrupted and stopped + resumed
  local d=$1 scene N
  case $d in
    1) N=400000 scene=(--dim 1 --N $N --rho 0.3 --aggregate --t-max 3e4 --samples-per-decade 10 --snapshots 10,3e4) ;;
    2) N=150000 scene=(--dim 2 --N $N --rho 0.1 --aggregate --t-max 3e3 --samples-per-decade 10 --snapshots 10,3e3) ;;
    3) N=100000 scene=(--dim 3 --N $N --rho 0.05 --aggregate --t-max 1e3 --samples-per-decade 10 --snapshots 10,1e3) ;;
  esac
  scene+=(--velocities --seed 3 --quiet)
  "$sim" "${scene[@]}" -o full$d.h5
  "$sim" "${scene[@]}" --checkpoint-every 0.2 -o term$d.h5 & pid=$!
  # Stopped once a periodic checkpoint holds fewer than half the particles: the engine has then
  # dropped the merged ones and rebuilt its cells at least once (a checkpoint is replaced whole, so
  # reading one while the run goes on is safe).
  local n
  for _ in $(seq 6000); do
    n=$( (h5ls term$d.h5.checkpoint.h5/checkpoint/t 2> /dev/null || true) | sed -n 's/.*{\([0-9]*\)}.*/\1/p')
    [ -n "$n" ] && [ "$n" -lt $((N / 2)) ] && break
    kill -0 "$pid" 2> /dev/null || break
    sleep 0.01
  done
  kill -TERM "$pid" 2> /dev/null || { echo "${d}D: run finished before SIGTERM; test inconclusive"; exit 1; }
  status=0; wait "$pid" || status=$?
  [ "$status" -eq 1 ] || { echo "${d}D: SIGTERM: exit status $status, expected 1"; exit 1; }
  [ -f term$d.h5.checkpoint.h5 ] || { echo "${d}D: SIGTERM: no checkpoint written"; exit 1; }
  "$sim" --quiet -o term$d.h5 --resume term$d.h5.checkpoint.h5
  same full$d.h5 term$d.h5 || { echo "${d}D: SIGTERM + resume of an aggregating run differs from the uninterrupted run"; exit 1; }
  [ ! -e term$d.h5.checkpoint.h5 ] || { echo "${d}D: checkpoint left behind after a completed run"; exit 1; }
}
for d in 1 2 3; do check "$d"; done
