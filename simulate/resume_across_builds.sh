#!/bin/bash
# resume_across_builds.sh OLD_GG_SIM NEW_GG_SIM
# A change that must keep the checkpoint format (the scene's fingerprint, the keys a --resume reads
# back) is checked with the build before it: OLD's checkpoints (periodic, then SIGTERM) resume with
# NEW (--allow-other-build) to the data of OLD's uninterrupted run, bit for bit; NEW's checkpoint of
# the same scene holds the same fingerprint, byte for byte; and a resume with another --e is refused
# by both builds with the same line. Two scenes: a drawn start, and a start from a file with
# --continue (whose fingerprint holds T0_given and continue). Takes about a minute; exits 1 on the
# first difference.
set -euo pipefail
old=$(realpath "${1:?usage: resume_across_builds.sh OLD_GG_SIM NEW_GG_SIM}")
new=$(realpath "${2:?usage: resume_across_builds.sh OLD_GG_SIM NEW_GG_SIM}")
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"

# Runs BUILD SCENE... with a checkpoint every second to OUT, and stops it by SIGTERM a second after
# its first checkpoint. usage: interrupted BUILD OUT SCENE...
interrupted() {
  local build=$1 out=$2 pid; shift 2
  "$build" "$@" --checkpoint-every 1 -o "$out" & pid=$!
  for _ in $(seq 3000); do [ -f "$out.checkpoint.h5" ] && break; sleep 0.01; done
  sleep 1
  kill -TERM "$pid" 2>/dev/null || { echo "$out: the run ended before SIGTERM; give it a longer --t-max"; exit 1; }
  wait "$pid" || true
}
fingerprint() { h5dump -a /checkpoint/scene "$1" | grep -o '(0): ".*"'; }

# usage: check NAME SCENE...
check() {
  local name=$1; shift
  "$old" "$@" -o "$name-full.h5"
  interrupted "$old" "$name-old.h5" "$@"
  interrupted "$new" "$name-new.h5" "$@"
  [ "$(fingerprint "$name-old.h5.checkpoint.h5")" = "$(fingerprint "$name-new.h5.checkpoint.h5")" ] ||
    { echo "$name: the builds' fingerprints differ"; exit 1; }
  local refused_old refused_new
  refused_old=$("$old" --quiet -o x.h5 --resume "$name-old.h5.checkpoint.h5" --e 0.7 2>&1 || true)
  refused_new=$("$new" --quiet -o x.h5 --resume "$name-old.h5.checkpoint.h5" --allow-other-build --e 0.7 2>&1 || true)
  [ "$refused_old" = "$refused_new" ] || { echo "$name: refused otherwise: '$refused_old' / '$refused_new'"; exit 1; }
  "$new" --quiet -o "$name-old.h5" --resume "$name-old.h5.checkpoint.h5" --allow-other-build
  h5diff "$name-full.h5" "$name-old.h5" /observables /observables && h5diff "$name-full.h5" "$name-old.h5" /particles /particles ||
    { echo "$name: the old build's checkpoint resumed by the new build differs from the old build's run"; exit 1; }
  echo "$name: same fingerprint; same refusal; the old checkpoint resumes with the new build to the old run's data"
}
"$old" --dim 2 --N 30000 --rho 0.3 --e 0.9 --t-max 5 --snapshots 5 --velocities --quiet -o start.h5
check drawn --dim 2 --L 300 --rho 0.37 --e 0.8 --tc 1e-5 --pressure --t-max 10000 --snapshots-per-decade 4 --velocities --quiet
check continued --init start.h5 --continue --e 0.8 --tc 1e-5 --t-max 10000 --snapshots-per-decade 4 --velocities --quiet
