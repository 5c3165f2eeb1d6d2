#!/usr/bin/env bash
# A run stopped by SIGTERM, or killed by SIGKILL after periodic checkpoints, then
# resumed, gives data bit-identical to the uninterrupted run (all datasets but provenance), with
# and without --unwrapped, for a driven gas (the drive's random numbers are part of the state), for
# rough particles and for a sheared box with its images.
# usage: resume_test.sh GG_SIM [sanitized]
# `sanitized` (the sanitizer build, where a run is ~10x slower): the effects' states are resumed
# from one scene that has them all, the three scenes of their own are left to the Release build.
set -euo pipefail
sim=$(realpath "$1")
mode=${2:-full}
# shellcheck source=stop_and_resume.sh
source "$(dirname "$(realpath "$0")")/stop_and_resume.sh"
# shellcheck source=../h5_same.sh
source "$(dirname "$(realpath "$0")")/../h5_same.sh"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
scene=(--dim 2 --L 200 --rho 0.37 --e 0.8 --tc 1e-5 --pressure --t-max 2000 --snapshots-per-decade 4 --velocities --quiet)

start=$(date +%s.%N)
"$sim" "${scene[@]}" -o full.h5
full_seconds=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')

same() { h5_same full.h5 "$1" /observables /particles; }  # the data of an output are the uninterrupted run's

# SIGTERM: stops at the next event, writes the output so far and a checkpoint, exits 1. A quarter
# of the uninterrupted run's time in: the machine's load may change by a factor of several between
# the two runs.
"$sim" "${scene[@]}" -o term.h5 & pid=$!
sleep "$(awk -v t="$full_seconds" 'BEGIN { print 0.25 * t }')"
kill -TERM "$pid"
status=0; wait "$pid" || status=$?
if [ "$status" -eq 0 ]; then echo "run finished before SIGTERM; test inconclusive, machine too fast?"; exit 1; fi
[ "$status" -eq 1 ] || { echo "SIGTERM: exit status $status, expected 1"; exit 1; }
[ -f term.h5.checkpoint.h5 ] || { echo "SIGTERM: no checkpoint written"; exit 1; }
h5ls term.h5/observables/kinetic_energy >/dev/null || { echo "SIGTERM: output not valid"; exit 1; }
stop_reason() { h5dump -a /parameters/stop_reason "$1" | grep -o '(0): "[a-z_]*"' | cut -d" " -f2; }
[ "$(stop_reason term.h5)" = '"interrupted"' ] || { echo "SIGTERM: output not marked interrupted: $(stop_reason term.h5)"; exit 1; }
"$sim" "${scene[@]}" -o term.h5 --resume term.h5.checkpoint.h5
same term.h5 || { echo "SIGTERM + resume differs from the uninterrupted run"; exit 1; }
[ "$(stop_reason term.h5)" = '"t_max"' ] || { echo "resumed run not marked complete: $(stop_reason term.h5)"; exit 1; }
[ ! -e term.h5.checkpoint.h5 ] || { echo "checkpoint left behind after a completed run"; exit 1; }

# SIGKILL at a random moment within 0.2 s after the first periodic checkpoint (timed from the
# checkpoint, not from the start: a fraction of the uninterrupted run's time fell after the end of a
# run that went faster than that one).
"$sim" "${scene[@]}" --checkpoint-every 0.2 -o kill.h5 & pid=$!
for _ in $(seq 3000); do [ -f kill.h5.checkpoint.h5 ] && break; sleep 0.01; done
sleep "$(awk -v r="$RANDOM" 'BEGIN { print 0.2 * r / 32767 }')"
kill -KILL "$pid" 2>/dev/null || { echo "run finished before SIGKILL; test inconclusive, machine too fast?"; exit 1; }
wait "$pid" || true
[ -f kill.h5.checkpoint.h5 ] || { echo "SIGKILL: no periodic checkpoint"; exit 1; }
[ ! -e kill.h5 ] || { echo "SIGKILL left an output file that looks complete"; exit 1; }
# A checkpoint is resumed only by the scene that wrote it: another one is refused (usage error, one
# line), nothing is written and the checkpoint is kept.
status=0; "$sim" "${scene[@]/0.8/0.7}" -o kill.h5 --resume kill.h5.checkpoint.h5 2> refused.txt || status=$?
[ "$status" -eq 2 ] || { echo "resume by another scene: exit status $status, expected 2"; exit 1; }
[ "$(wc -l < refused.txt)" -eq 1 ] && grep -q "another scene" refused.txt || { echo "resume by another scene: $(cat refused.txt)"; exit 1; }
[ -f kill.h5.checkpoint.h5 ] && [ ! -e kill.h5 ] || { echo "a refused resume touched the files"; exit 1; }
# The checkpoint holds its scene: resumed with -o alone, as well as with the whole command (above).
"$sim" --quiet -o kill.h5 --resume kill.h5.checkpoint.h5
same kill.h5 || { echo "SIGKILL + resume differs from the uninterrupted run"; exit 1; }

# A scene run uninterrupted, and stopped by SIGTERM a quarter of the way in, then resumed from the
# checkpoint alone: the two outputs agree bit for bit. usage: term_and_resume NAME SCENE...
term_and_resume() {
  local name=$1
  stop_and_resume "$@"
  h5_same "$name-full.h5" "$name-term.h5" /observables /particles ||
    { echo "$name: SIGTERM + resume differs from the uninterrupted run"; exit 1; }
}

if [ "$mode" = sanitized ]; then
  term_and_resume effects --dim 2 --L 120 --rho 0.3 --e 0.8 --tc 1e-5 --pressure --unwrapped --beta 0.5 \
    --T0-rot 0.5 --drive white-noise --drive-strength 0.2 --t-max 20 --snapshots-per-decade 4 --velocities --quiet
  echo "1 passed, 0 failed"
  exit 0
fi

# --unwrapped: the periodic images are part of the state (h5diff compares /particles/all/image).
term_and_resume unwrapped "${scene[@]}" --unwrapped
h5ls unwrapped-full.h5/particles/all/image/value >/dev/null || { echo "--unwrapped wrote no image"; exit 1; }
# A sheared box with --unwrapped: its images count the slides across the sliding edge too.
term_and_resume sheared --dim 2 --N 20000 --rho 0.3 --e 0.9 --shear-rate 0.05 --t-max 200 --snapshots 50,100,150,200 \
  --velocities --unwrapped --quiet
# --drive: the drive's generator, next kick time and energy put in are part of the state.
term_and_resume driven --dim 2 --L 150 --rho 0.1 --e 0.8 --drive white-noise --drive-strength 0.2 --t-max 300 \
  --snapshots-per-decade 4 --velocities --quiet
# Rough particles (--beta): the angular velocities are part of the state (the rotational energy and the
# snapshots' angular velocities are compared).
term_and_resume rough --dim 2 --L 120 --rho 0.37 --e 0.8 --tc 1e-5 --beta 0.5 --T0-rot 0.5 --t-max 1000 \
  --snapshots-per-decade 4 --velocities --quiet
h5ls rough-full.h5/particles/all/angular_velocity/value >/dev/null || { echo "--beta wrote no angular velocity"; exit 1; }
echo "1 passed, 0 failed"
