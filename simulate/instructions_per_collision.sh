#!/bin/bash
# instructions_per_collision.sh GG_SIM OUTDIR: callgrind instructions per collision of each scene of
# build_scenes.sh (its flags, without compare_builds.sh's run length and outputs): (Ir(K2) - Ir(K1)) /
# (K2 - K1), the start and the output cancelling in the difference (simulate/PERFORMANCE.md "How a decision
# is measured"). Deterministic, so two builds compare on a loaded machine; valgrind takes several minutes
# for the thirteen scenes.
set -euo pipefail
sim=$1 out=$2
mkdir -p "$out"
. "$(dirname "${BASH_SOURCE[0]}")/build_scenes.sh"
ir() {  # ir NAME K ARGS...: total instructions
  local name=$1 k=$2; shift 2
  # A snapshot time the run never reaches: a scene part that keeps its data in the snapshots
  # (--unwrapped) is refused in a run that takes none, and this one takes none, so the count is the engine's.
  valgrind --tool=callgrind --callgrind-out-file="$out/$name-$k.cg" "$sim" "$@" --t-max inf --max-collisions "$k" \
    --snapshots 1e300 --seed 5 --quiet -o "$out/$name-$k.h5" > /dev/null 2>&1
  rm -f "$out/$name-$k.h5"
  awk '/^summary:/ { print $2 }' "$out/$name-$k.cg"
}
for s in "${build_scenes[@]}"; do
  IFS='|' read -r name args _ k1 k2 <<< "$s"
  # shellcheck disable=SC2086
  a=$(ir "$name" "$k1" $args); b=$(ir "$name" "$k2" $args)
  printf '%-26s %10.1f\n' "$name" "$(echo "($b - $a) / ($k2 - $k1)" | bc -l)"
done
