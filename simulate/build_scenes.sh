# Sourced by compare_builds.sh and instructions_per_collision.sh: the small scenes on which two builds of
# gg-sim are compared, covering 1D, 2D and 3D and every effect, aggregation, walls and the shear.
# One entry per scene: NAME|scene flags|compare_builds.sh's run length and outputs|callgrind's K1|K2
# (instructions_per_collision.sh counts between K1 and K2 collisions; aggregates run out of partners
# sooner, so theirs are smaller).
# shellcheck disable=SC2034  # used by the scripts that source this file
build_scenes=(
  "plain-2d|--dim 2 --N 3000 --rho 0.37 --e 0.9|--t-max 50 --snapshots 10,50 --velocities|20000|120000"
  "cutoff-1d|--dim 1 --N 2000 --rho 0.3 --e 0.5 --delta 1e-3|--t-max 100 --snapshots 100|20000|120000"
  "tc-pressure-unwrapped-3d|--dim 3 --N 3000 --rho 0.5 --e 0.5 --tc 1e-4 --pressure --unwrapped|--t-max 20 --snapshots 20|20000|120000"
  "rough-2d|--dim 2 --N 2000 --rho 0.1 --e 0.9 --beta 0.5 --T0-rot 0.5|--t-max 50 --snapshots 50 --velocities|20000|120000"
  "mixture-3d|--dim 3 --N 2000 --rho 0.3 --e 0.8 --radii 0.5,0.7 --masses 1,2|--t-max 20 --snapshots 20|20000|120000"
  "drive-2d|--dim 2 --N 2000 --rho 0.05 --e 0.8 --drive white-noise --drive-strength 0.1|--t-max 20 --snapshots 20|20000|120000"
  "aggregate-2d|--dim 2 --N 3000 --rho 0.1 --aggregate|--t-max 100 --snapshots 100|500|2500"
  "aggregate-1d|--dim 1 --N 2000 --rho 0.1 --aggregate|--t-max 100 --snapshots 100|500|1800"
  "walls-thermal-gravity-2d|--dim 2 --N 1000 --L 40 --walls 60 --e 0.9 --wall-T 1 --gravity 0.2|--t-max 50 --snapshots 50 --velocities|20000|120000"
  "walls-vibrated-3d|--dim 3 --N 1000 --L 12 --walls 30 --e 0.9 --wall-amplitude 0.1 --wall-frequency 2 --gravity 1|--t-max 20 --snapshots 20|20000|120000"
  "shear-2d|--dim 2 --N 2000 --rho 0.3 --e 0.9 --shear-rate 0.1|--t-max 20 --snapshots 20 --velocities|20000|120000"
  "viscoelastic-3d|--dim 3 --N 2000 --rho 0.1 --viscoelastic 0.05|--t-max 20 --snapshots 20|20000|120000"
  "impact-speed-2d|--dim 2 --N 2000 --rho 0.3 --e 0.7 --e-speed 0.5|--t-max 50 --snapshots 50 --velocities|20000|120000"
)
