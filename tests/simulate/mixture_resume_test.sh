#!/usr/bin/env bash
# A mixture (--radii, --masses, --fractions) stopped by SIGTERM and resumed from its checkpoint with
# -o alone (the checkpoint holds the scene and every particle's radius, mass and species) gives data
# bit-identical to the uninterrupted run: positions, velocities, masses, radii, species and the
# species temperatures (all datasets but provenance). So does a run started from that mixture's
# output, whose scene names no mixture: its checkpoint names the effects its engine held.
# usage: mixture_resume_test.sh GG_SIM
set -euo pipefail
sim=$(realpath "$1")
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
scene=(--dim 2 --N 50000 --rho 0.2 --e 0.95 --radii 0.5,0.7 --masses 1,3 --fractions 0.3,0.7 --pressure
       --t-max 3000 --snapshots 50,3000 --velocities --quiet)

# interrupted NAME SCENE...: the scene run to full-NAME.h5, and again to NAME.h5 stopped by SIGTERM a
# quarter of the way (by the first run's time) and resumed: the two must be identical.
interrupted() {
  local name=$1; shift
  local start full_seconds pid status report
  start=$(date +%s.%N)
  "$sim" "$@" -o "full-$name.h5"
  full_seconds=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')
  "$sim" "$@" -o "$name.h5" & pid=$!
  sleep "$(awk -v t="$full_seconds" 'BEGIN { print 0.25 * t }')"
  kill -TERM "$pid"
  status=0; wait "$pid" || status=$?
  if [ "$status" -eq 0 ]; then echo "$name: run finished before SIGTERM; test inconclusive, machine too fast?"; exit 1; fi
  [ -f "$name.h5.checkpoint.h5" ] || { echo "$name: SIGTERM: no checkpoint written"; exit 1; }
  "$sim" --quiet -o "$name.h5" --resume "$name.h5.checkpoint.h5"
  # h5diff exits 0 on datasets of other shapes ("not comparable"): that counts as a difference here.
  report=$(h5diff -c "full-$name.h5" "$name.h5" /observables /observables 2>&1 &&
           h5diff -c "full-$name.h5" "$name.h5" /particles /particles 2>&1) &&
    ! grep -qi "not comparable" <<< "$report" ||
    { echo "SIGTERM + resume of $name differs from the uninterrupted run"; exit 1; }
}
interrupted mixture "${scene[@]}"
# The same from the mixture's output, reheated to T0 = 1 on a new clock.
interrupted from-file --dim 2 --init full-mixture.h5 --T0 1 --e 0.95 --t-max 300 --snapshots 300 --velocities --quiet
