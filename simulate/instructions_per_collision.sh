#!/bin/bash
# instructions_per_collision.sh GG_SIM OUTDIR: callgrind instructions per collision of each of
# compare_builds.sh's scenes (t-max and snapshots dropped): (Ir(K2) - Ir(K1)) / (K2 - K1), the start and the
# output cancelling in the difference (simulate/PERFORMANCE.md "How a decision is measured"). Deterministic, so
# two builds compare on a loaded machine; valgrind takes several minutes for the eleven scenes.
set -euo pipefail
sim=$1 out=$2
mkdir -p "$out"
scenes=(
  "plain-2d|--dim 2 --N 3000 --rho 0.37 --e 0.9|20000|120000"
  "cutoff-1d|--dim 1 --N 2000 --rho 0.3 --e 0.5 --delta 1e-3|20000|120000"
  "tc-pressure-unwrapped-3d|--dim 3 --N 3000 --rho 0.5 --e 0.5 --tc 1e-4 --pressure --unwrapped|20000|120000"
  "rough-2d|--dim 2 --N 2000 --rho 0.1 --e 0.9 --beta 0.5 --T0-rot 0.5|20000|120000"
  "mixture-3d|--dim 3 --N 2000 --rho 0.3 --e 0.8 --radii 0.5,0.7 --masses 1,2|20000|120000"
  "drive-2d|--dim 2 --N 2000 --rho 0.05 --e 0.8 --drive white-noise --drive-strength 0.1|20000|120000"
  "aggregate-2d|--dim 2 --N 3000 --rho 0.1 --aggregate|500|2500"
  "aggregate-1d|--dim 1 --N 2000 --rho 0.1 --aggregate|500|1800"
  "walls-thermal-gravity-2d|--dim 2 --N 1000 --L 40 --walls 60 --e 0.9 --wall-T 1 --gravity 0.2|20000|120000"
  "walls-vibrated-3d|--dim 3 --N 1000 --L 12 --walls 30 --e 0.9 --wall-amplitude 0.1 --wall-frequency 2 --gravity 1|20000|120000"
  "shear-2d|--dim 2 --N 2000 --rho 0.3 --e 0.9 --shear-rate 0.1|20000|120000"
)
ir() {  # ir NAME K ARGS...: total instructions
  local name=$1 k=$2; shift 2
  valgrind --tool=callgrind --callgrind-out-file="$out/$name-$k.cg" "$sim" "$@" --t-max inf --max-collisions "$k" \
    --seed 5 --quiet -o "$out/$name-$k.h5" > /dev/null 2>&1
  rm -f "$out/$name-$k.h5"
  awk '/^summary:/ { print $2 }' "$out/$name-$k.cg"
}
for s in "${scenes[@]}"; do
  IFS='|' read -r name args k1 k2 <<< "$s"
  # shellcheck disable=SC2086
  a=$(ir "$name" "$k1" $args); b=$(ir "$name" "$k2" $args)
  printf '%-26s %10.1f\n' "$name" "$(echo "($b - $a) / ($k2 - $k1)" | bc -l)"
done
