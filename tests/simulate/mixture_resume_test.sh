#!/usr/bin/env bash
# A mixture (--radii, --masses, --fractions) stopped by SIGTERM and resumed from its checkpoint with
# -o alone (the checkpoint holds the scene and every particle's radius, mass and species) gives data
# bit-identical to the uninterrupted run: positions, velocities, masses, radii, species and the
# species temperatures (all datasets but provenance). So does a run started from that mixture's
# output, whose scene names no mixture: its checkpoint names the effects its engine held.
# usage: mixture_resume_test.sh GG_SIM
set -euo pipefail
sim=$(realpath "$1")
# shellcheck source=stop_and_resume.sh
source "$(dirname "$(realpath "$0")")/stop_and_resume.sh"
# shellcheck source=../h5_same.sh
source "$(dirname "$(realpath "$0")")/../h5_same.sh"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
scene=(--dim 2 --N 50000 --rho 0.2 --e 0.95 --radii 0.5,0.7 --masses 1,3 --fractions 0.3,0.7 --pressure
       --t-max 3000 --snapshots 50,3000 --velocities --quiet)

# interrupted NAME SCENE...: stop_and_resume, then the two runs must be identical.
interrupted() {
  local name=$1
  stop_and_resume "$@"
  h5_same "$name-full.h5" "$name-term.h5" /observables /particles ||
    { echo "SIGTERM + resume of $name differs from the uninterrupted run"; exit 1; }
}
interrupted mixture "${scene[@]}"
# The same from the mixture's output, reheated to T0 = 1 on a new clock.
interrupted from-file --dim 2 --init mixture-full.h5 --T0 1 --e 0.95 --t-max 300 --snapshots 300 --velocities --quiet
