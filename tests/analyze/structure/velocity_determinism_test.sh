#!/usr/bin/env bash
# gg-velocity is deterministic (docs/DESIGN.md "Conventions of every tool"): run twice on the same
# H5MD file (once to a file, once through stdout), every dataset and attribute of /velocity is
# bit-identical, the flow, vorticity and density fields of --fields included (the input's name is an
# attribute of /velocity, so both runs read the same path). The run of another seed must differ, so
# that the comparison is seen to catch a difference.
# usage: velocity_determinism_test.sh GG_SIM GG_VELOCITY
set -euo pipefail
# shellcheck source=../../h5_same.sh
source "$(dirname "$(realpath "$0")")/../../h5_same.sh"
sim=$(realpath "$1")
velocity=$(realpath "$2")
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"

# A clustering 2D gas with a flow field to correlate: 2000 disks, e = 0.5, three snapshots.
for seed in 1 2; do
  "$sim" --dim 2 --N 2000 --rho 0.35 --e 0.5 --seed "$seed" --t-max 30 --snapshots 1,10,30 --velocities --quiet \
    -o "sim$seed.h5"
done
"$velocity" sim1.h5 --fields --quiet -o a.h5
"$velocity" sim1.h5 --fields --quiet -o - > b.h5
"$velocity" sim2.h5 --fields --quiet -o c.h5

same() { h5_same "$1" "$2" /velocity; }  # exact, no tolerance
for ds in a2 C_L tail_A flow vorticity rho_loc; do
  h5ls "a.h5/velocity/$ds" > /dev/null || { echo "a.h5 has no /velocity/$ds"; exit 1; }
done
same a.h5 b.h5 || { echo "gg-velocity gave different /velocity on the same input:"; h5diff -c a.h5 b.h5 /velocity /velocity | head -20; exit 1; }
if same a.h5 c.h5; then echo "the comparison found no difference between two different runs"; exit 1; fi
echo "gg-velocity: /velocity bit-identical on the same input, different on another"
