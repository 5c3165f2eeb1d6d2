#!/bin/bash
# compare_builds.sh OLD_GG_SIM NEW_GG_SIM [WORKDIR]
# Runs the same small scenes with two gg-sim binaries and compares their data: a change of the engine
# that is meant to keep every trajectory (a refactoring, a new effect that a scene does not use) must
# leave /observables, /particles and every value of /parameters but the provenance bit-identical
# (simulate/PERFORMANCE.md "How a decision is measured"). The scenes cover 1D, 2D and 3D and every effect,
# aggregation, walls and the shear included (a build older than an effect fails to run its scenes). Prints one line per scene and exits 1 if any differs.
set -uo pipefail
old=${1:?usage: compare_builds.sh OLD_GG_SIM NEW_GG_SIM [WORKDIR]}
new=${2:?usage: compare_builds.sh OLD_GG_SIM NEW_GG_SIM [WORKDIR]}
work=${3:-$(mktemp -d)}
mkdir -p "$work"
scenes=(
  "plain-2d|--dim 2 --N 3000 --rho 0.37 --e 0.9 --t-max 50 --snapshots 10,50 --velocities"
  "cutoff-1d|--dim 1 --N 2000 --rho 0.3 --e 0.5 --delta 1e-3 --t-max 100 --snapshots 100"
  "tc-pressure-unwrapped-3d|--dim 3 --N 3000 --rho 0.5 --e 0.5 --tc 1e-4 --pressure --unwrapped --t-max 20 --snapshots 20"
  "rough-2d|--dim 2 --N 2000 --rho 0.1 --e 0.9 --beta 0.5 --T0-rot 0.5 --t-max 50 --snapshots 50 --velocities"
  "mixture-3d|--dim 3 --N 2000 --rho 0.3 --e 0.8 --radii 0.5,0.7 --masses 1,2 --t-max 20 --snapshots 20"
  "drive-2d|--dim 2 --N 2000 --rho 0.05 --e 0.8 --drive white-noise --drive-strength 0.1 --t-max 20 --snapshots 20"
  "aggregate-2d|--dim 2 --N 3000 --rho 0.1 --aggregate --t-max 100 --snapshots 100"
  "aggregate-1d|--dim 1 --N 2000 --rho 0.1 --aggregate --t-max 100 --snapshots 100"
  "walls-thermal-gravity-2d|--dim 2 --N 1000 --L 40 --walls 60 --e 0.9 --wall-T 1 --gravity 0.2 --t-max 50 --snapshots 50 --velocities"
  "walls-vibrated-3d|--dim 3 --N 1000 --L 12 --walls 30 --e 0.9 --wall-amplitude 0.1 --wall-frequency 2 --gravity 1 --t-max 20 --snapshots 20"
  "shear-2d|--dim 2 --N 2000 --rho 0.3 --e 0.9 --shear-rate 0.1 --t-max 20 --snapshots 20 --velocities"
)
# attrs FILE: every attribute of /parameters but the provenance, one "name = value" block each.
attrs() {
  local name
  for name in $(h5dump -A -g /parameters "$1" | awk '/^   ATTRIBUTE "/ { gsub(/"/, "", $2); print $2 }'); do
    echo "$name"; h5dump -a "/parameters/$name" "$1" | tail -n +2
  done
}
failed=0
for scene in "${scenes[@]}"; do
  name=${scene%%|*} args=${scene#*|}
  verdict=identical
  # shellcheck disable=SC2086  # args is a list of flags
  if ! "$old" $args --seed 5 --quiet -o "$work/old-$name.h5" 2> "$work/old-$name.err" ||
     ! "$new" $args --seed 5 --quiet -o "$work/new-$name.h5" 2> "$work/new-$name.err"; then
    verdict="failed to run (see $work/*-$name.err)"
  else
    differs=()
    for group in /observables /particles; do
      h5diff -q "$work/old-$name.h5" "$work/new-$name.h5" "$group" > /dev/null 2>&1 || differs+=("$group")
    done
    [ "$(attrs "$work/old-$name.h5")" = "$(attrs "$work/new-$name.h5")" ] || differs+=(/parameters)
    [ ${#differs[@]} -eq 0 ] || verdict="differs in ${differs[*]}"
  fi
  printf '%-26s %s\n' "$name" "$verdict"
  [ "$verdict" = identical ] || failed=1
done
exit $failed
