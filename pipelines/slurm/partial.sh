#!/bin/bash
# partial.sh DIR...: remove the simulation outputs that a stopped gg-sim left behind, so that make runs
# them again instead of taking them for finished.
#
# When gg-sim gets SIGTERM (a job's time limit, scancel) it writes a checkpoint X.h5.checkpoint.h5, then
# the output X.h5 with everything recorded so far, and exits 1. Under make, srun may return (and make
# give up on the target) before that output appears, so it stays, looking complete (seen with a job
# that hit its time limit: a run1.h5 ending at t = 30 of 1000). gg-sim removes the checkpoint only when
# a run completes, so an output with a checkpoint beside it is such a leftover. The checkpoint is kept
# (ensemble.sbatch resumes from it; make's rerun starts over and removes it when done).
# Called by study.sbatch, analyze.sbatch and submit.sh before they run make (make slurm-partial).
set -euo pipefail
n=0
for d in "$@"; do
  [ -d "$d" ] || continue
  while IFS= read -r -d '' c; do
    out=${c%.checkpoint.h5}
    if [ -e "$out" ]; then
      echo "partial.sh: $out is what a stopped run left ($c beside it): removed, to be run again" >&2
      rm -f "$out"
      n=$((n + 1))
    fi
  done < <(find "$d" -name '*.h5.checkpoint.h5' -print0)
done
[ "$n" = 0 ] || echo "partial.sh: $n incomplete simulation output(s) removed" >&2
