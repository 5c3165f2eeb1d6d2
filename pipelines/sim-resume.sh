#!/bin/bash
# sim-resume.sh GG_SIM [gg-sim flags ...] -o OUT
# Runs one gg-sim command so that a run stopped part way continues where it stopped instead of starting
# over. Every simulation of Makefile.study runs through it, and so does every task of the Slurm job
# arrays (pipelines/slurm/ensemble.sbatch): one way of resuming for both.
#
# gg-sim writes its checkpoint OUT.checkpoint.h5 (or the --checkpoint FILE given) when SIGINT or SIGTERM
# stops it and every --checkpoint-every seconds, and removes it when the run completes; so a checkpoint
# means an unfinished run. This script
#   - resumes from that checkpoint when there is one (adds --resume): the data are bit-identical to an
#     uninterrupted run. gg-sim refuses a checkpoint written with other flags, another scene or another
#     version of gg-sim (exit status 2, nothing simulated); this script then says how to start over;
#   - passes SIGINT, SIGTERM and SIGHUP on to gg-sim, which stops at its next event, writes the checkpoint
#     and the output so far and exits 1: whoever stops this script (make on Ctrl-C or SIGTERM, Slurm at a
#     time limit or scancel, sbatch --signal=B:TERM) gets the checkpoint;
#   - removes OUT when gg-sim fails or is stopped (it then holds the samples so far and would look
#     complete), keeping the checkpoint; the exit status is gg-sim's;
#   - prints one line on stderr when it resumes, when the run stops or fails, and when it is done.
# With -o - (stdout) there is no checkpoint beside the output: the command runs as given.
set -euo pipefail
me=sim-resume.sh
[ $# -ge 1 ] || { echo "usage: $me GG_SIM [gg-sim flags ...] -o OUT" >&2; exit 2; }

out="" ckpt=""
args=("$@")
for ((i = 1; i < ${#args[@]}; ++i)); do
  case ${args[i]} in
    -o|--output) out=${args[i + 1]:-} ;;
    --output=*) out=${args[i]#--output=} ;;
    --checkpoint) ckpt=${args[i + 1]:-} ;;
    --checkpoint=*) ckpt=${args[i]#--checkpoint=} ;;
    --resume|--resume=*) echo "$me: --resume is this script's to add (it resumes from the checkpoint itself)" >&2; exit 2 ;;
  esac
done
if [ -z "$out" ] || [ "$out" = - ]; then exec "$@"; fi
[ -n "$ckpt" ] || ckpt=$out.checkpoint.h5   # gg-sim's default (SimConfig::checkpoint_path)

cmd=("$@")
resumed=0
if [ -e "$ckpt" ]; then
  echo "$me: resuming from $ckpt" >&2
  rm -f "$out"   # what the stopped run wrote: not complete
  cmd+=(--resume "$ckpt")
  resumed=1
fi

start=$(date +%s%N)
"${cmd[@]}" &
pid=$!
# A signal interrupts `wait`; gg-sim is then still writing its checkpoint, so wait again until it is gone.
for sig in INT TERM HUP; do
  # shellcheck disable=SC2064   # the signal and pid are fixed now
  trap "kill -$sig $pid 2> /dev/null || true" "$sig"
done
status=0
wait "$pid" || status=$?
while kill -0 "$pid" 2> /dev/null; do
  status=0
  wait "$pid" || status=$?
done
trap - INT TERM HUP

if [ "$status" != 0 ]; then
  rm -f "$out"
  if [ "$resumed" = 1 ] && [ "$status" = 2 ] && [ -e "$ckpt" ]; then
    echo "$me: gg-sim cannot resume from $ckpt (see above); if the scene, the flags or gg-sim changed since" \
         "it was written, remove it to start over: rm $ckpt" >&2
  elif [ -e "$ckpt" ]; then
    echo "$me: $out stopped (exit $status); the same command resumes from $ckpt" >&2
  else
    echo "$me: $out failed (exit $status)" >&2
  fi
  exit "$status"
fi
awk -v out="$out" -v t0="$start" -v t1="$(date +%s%N)" -v r="$resumed" \
  'BEGIN { printf "sim-resume.sh: %s done in %.2f s%s\n", out, (t1 - t0) / 1e9, r ? " (resumed)" : "" }' >&2
