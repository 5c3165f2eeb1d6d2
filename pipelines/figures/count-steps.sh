#!/bin/bash
# count-steps.sh L E RUN...   (called by fig8.sh for the cells that run past FS_STEP_FROM)
# Does the cluster count fall in a step the runs share, and do the pieces of resumed runs make it?
# Per run r and each interval i between consecutive snapshots from t = FS_STEP_FROM on, the local exponent
# of its cluster count d_ri = ln(N_r(t_i+1) / N_r(t_i)) / ln(t_i+1 / t_i), and its excess over the two
# neighbouring intervals x_ri = d_ri - (d_r,i-1 + d_r,i+1) / 2. The runs are independent, so a step they
# share stands out of their scatter: the mean of x over runs against its standard error (R - 1 dof). A step
# made by resuming would sit at a piece boundary (the t where one piece of a run ends and the next begins,
# from collect.sh's .info), so each interval also counts the runs with a boundary inside (t_i, t_i+1].
# Prints one fits row per interval: fs_count_step_L<L>, e, mean d, its stderr, t_i, t_i+1, and a note
# "excess X +- S; fall P%; B of R runs have a piece boundary inside"; then the verdict row
# fs_count_step_verdict_L<L> (count-steps.awk: the largest |excess| / error, Bonferroni over the
# intervals, and the step it finds half the time). Fewer than 3 runs: nothing.
# Environment: FIT, FS_STEP_FROM.
set -euo pipefail
: "${FIT:?}" "${FS_STEP_FROM:?}"
L=$1 e=$2; shift 2
[ "$#" -ge 3 ] || exit 0
for r in "$@"; do
  "$FIT" table --no-header "$r:/cluster/count" | awk -v r="$r" '{ print "n", r, $1, $2 }'
  awk -F'\t' -v r="$r" '$1 == "piece" { sub(/^t=/, "", $5); split($5, t, /[.][.]/); print "b", r, t[2] }' "${r%.h5}.info"
done | awk -v L="$L" -v e="$e" -v from="$FS_STEP_FROM" -f "$(dirname "$0")/count-steps.awk"
