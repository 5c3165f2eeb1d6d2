#!/usr/bin/env bash
# A run stopped twice by SIGTERM and resumed twice lists its three pieces in its output
# (/parameters/provenance/pieces): contiguous t ranges from 0 to t_max, each piece's CPU seconds and
# this build's git hash; its data stay those of the uninterrupted run. A resume by another build of
# gg-sim (the same program with one byte more) is refused in one line and touches nothing, unless
# --allow-other-build is given, which the piece records.
# usage: run_pieces_test.sh GG_SIM
set -euo pipefail
sim=$(realpath "$1")
# shellcheck source=../h5_same.sh
source "$(dirname "$(realpath "$0")")/../h5_same.sh"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
scene=(--dim 2 --L 200 --rho 0.37 --e 0.8 --tc 1e-5 --t-max 3000 --quiet)
fail() { echo "run_pieces_test: $*"; exit 1; }

"$sim" "${scene[@]}" -o full.h5

# Runs `$@` in the background until its first periodic checkpoint (a new file: checkpoints are
# written under another name and renamed), then stops it with SIGTERM.
stop_after_checkpoint() {
  local out=$1 pid status old; shift
  old=$(stat -c %i "$out.checkpoint.h5" 2>/dev/null || echo none)
  "$@" --checkpoint-every 0.2 -o "$out" & pid=$!
  for _ in $(seq 3000); do [ "$(stat -c %i "$out.checkpoint.h5" 2>/dev/null || echo none)" != "$old" ] && break; sleep 0.01; done
  kill -TERM "$pid" 2>/dev/null || fail "the run ended before SIGTERM; give it a longer --t-max"
  status=0; wait "$pid" || status=$?
  [ "$status" -eq 1 ] || fail "SIGTERM: exit status $status, expected 1"
}
# attr FILE NAME: a field of the pieces (an attribute or a dataset), its elements one per line.
attr() {
  local at=/parameters/provenance/pieces/$2
  { h5dump -a "$at" "$1" 2>/dev/null || h5dump -d "$at" "$1"; } | awk '/DATA \{/ { on = 1; next } on && /^ *\}/ { exit }
    on { sub(/^ *\([0-9]+\): */, ""); gsub(/"/, ""); gsub(/, */, "\n"); printf "%s\n", $0 }' | sed '/^$/d'
}

stop_after_checkpoint run.h5 "$sim" "${scene[@]}"
stop_after_checkpoint run.h5 "$sim" --quiet --resume run.h5.checkpoint.h5
"$sim" --quiet -o run.h5 --resume run.h5.checkpoint.h5
h5_same full.h5 run.h5 /observables /particles || fail "the resumed run's data differ from the uninterrupted run"

mapfile -t t_start < <(attr run.h5 t_start)
mapfile -t t_end < <(attr run.h5 t_end)
mapfile -t cpu < <(attr run.h5 cpu_seconds)
mapfile -t hash < <(attr run.h5 git_hash)
mapfile -t other < <(attr run.h5 other_build)
[ "${#t_start[@]}" -eq 3 ] || fail "3 pieces expected, the output lists ${#t_start[@]}"
awk -v a="${t_start[0]}" 'BEGIN { exit !(a == 0) }' || fail "the first piece starts at t = ${t_start[0]}, not 0"
for k in 0 1; do
  awk -v e="${t_end[k]}" -v s="${t_start[k + 1]}" 'BEGIN { exit !(e == s && e > 0 && e < 3000) }' ||
    fail "piece $((k + 1)) ends at t = ${t_end[k]}, piece $((k + 2)) starts at ${t_start[k + 1]}"
done
awk -v e="${t_end[2]}" 'BEGIN { exit !(e == 3000) }' || fail "the last piece ends at t = ${t_end[2]}, not t_max"
for k in 0 1 2; do
  awk -v c="${cpu[k]}" 'BEGIN { exit !(c > 0 && c < 3600) }' || fail "piece $((k + 1)) took ${cpu[k]} CPU seconds"
  [ "${other[k]}" = 0 ] || fail "piece $((k + 1)) is marked as another build's"
done
version_hash=$("$sim" --version | grep -o '[0-9a-f]\{12\}\(-dirty\)\?' | head -1)
[ "${hash[0]}" = "$version_hash" ] && [ "${hash[2]}" = "$version_hash" ] ||
  fail "the pieces name build ${hash[0]}, gg-sim --version says $version_hash"

# Another build: refused in one line (exit 2), the checkpoint and the output so far untouched.
cp "$sim" other-gg-sim && printf '\0' >> other-gg-sim
stop_after_checkpoint again.h5 "$sim" "${scene[@]}"
before=$(cat again.h5 again.h5.checkpoint.h5 | md5sum)
status=0; ./other-gg-sim --quiet -o again.h5 --resume again.h5.checkpoint.h5 2> refused.txt || status=$?
[ "$status" -eq 2 ] || fail "resume by another build: exit status $status, expected 2"
[ "$(wc -l < refused.txt)" -eq 1 ] && grep -q -- "--allow-other-build" refused.txt || fail "refusal: $(cat refused.txt)"
[ "$(cat again.h5 again.h5.checkpoint.h5 | md5sum)" = "$before" ] || fail "a refused resume changed the files"
./other-gg-sim --quiet -o again.h5 --resume again.h5.checkpoint.h5 --allow-other-build
mapfile -t other < <(attr again.h5 other_build)
mapfile -t exe < <(attr again.h5 executable)
[ "${other[*]}" = "0 1" ] || fail "--allow-other-build: other_build = ${other[*]}, expected 0 1"
[ "${exe[0]}" != "${exe[1]}" ] && [ "${#exe[0]}" -eq 16 ] || fail "the pieces' executables: ${exe[*]}"
echo "run_pieces_test: 3 pieces contiguous, CPU ${cpu[*]} s, another build refused and allowed"
