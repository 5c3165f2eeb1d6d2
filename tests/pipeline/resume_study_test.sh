#!/bin/bash
# resume_study_test.sh SOURCE_DIR BUILD_DIR
# A study simulation stopped by SIGTERM resumes from its checkpoint when make is run again, and ends with
# the data of an uninterrupted run (Makefile.study + pipelines/sim-resume.sh). One ensemble member made
# longer with make variables (SCALE=quick L2=256 TMAX_0.9=3000: ~5 s), with the tools of BUILD_DIR:
#   1. the reference: make the run uninterrupted (in its own RUNS);
#   2. make it again elsewhere with CHECKPOINT_EVERY=0.25 and, after its first periodic checkpoint, send
#      SIGTERM to make alone (make passes it on): a checkpoint written on the signal is left, no output
#      that looks complete, and make -q says the run is still to do;
#      Then a partial output is put beside the checkpoint (what a launcher killed before its cleanup
#      leaves): make -q must still say the run is to do;
#   3. rerun make: it resumes; after its first periodic checkpoint, SIGTERM to every process of that make
#      (as at a job's time limit): the same checks;
#   4. rerun make: it resumes and completes; no checkpoint is left; h5diff of /observables and /particles
#      (and of the whole file but the provenance) against the reference finds no difference; make -q is
#      satisfied.
set -uo pipefail
# shellcheck source=../h5_same.sh
source "$(dirname "$(realpath "$0")")/../h5_same.sh"
src=$(cd "$1" && pwd) bin=$(cd "$2" && pwd)
[ -x "$bin/simulate/gg-sim" ] || { echo "FAIL: $bin/simulate/gg-sim is missing: build first" >&2; exit 1; }
for prog in make h5diff setsid; do
  command -v $prog > /dev/null || { echo "FAIL: $prog not found: run make -f Makefile.study deps" >&2; exit 1; }
done
tmp=$(mktemp -d "${TMPDIR:-/tmp}/gg-resume.XXXXXX")
job=""
cleanup() { [ -z "$job" ] || kill -KILL -- "-$job" 2> /dev/null; rm -rf "$tmp"; }
trap cleanup EXIT
fail() { echo "FAIL: $*" >&2; echo "(outputs kept in $tmp)" >&2; trap - EXIT; [ -z "$job" ] || kill -KILL -- "-$job" 2> /dev/null; exit 1; }
# Do not inherit the variables of a calling make.
unset MAKEFLAGS MFLAGS MAKEOVERRIDES MAKELEVEL GNUMAKEFLAGS

mk=(make -C "$src" -f Makefile.study --no-print-directory SCALE=quick BUILD="$bin" L2=256 TMAX_0.9=3000)
rel=quick/sim/ens/e0.9-L256-t3000/run1.h5
ref=$tmp/ref/$rel out=$tmp/runs/$rel ckpt=$tmp/runs/$rel.checkpoint.h5
now() { date +%s.%N; }
since() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.2f", b - a }'; }

# 1. reference
t0=$(now)
"${mk[@]}" RUNS="$tmp/ref" "$ref" > "$tmp/ref.log" 2>&1 || { cat "$tmp/ref.log" >&2; fail "the reference run failed"; }
[ -s "$ref" ] || fail "make wrote no $ref"
echo "reference run through make: $(since "$t0") s"

# interrupt LOG TARGET WHAT: make the run in the background, in a session of its own (job = its process
# group), with a checkpoint every 0.25 s; after its first periodic checkpoint send SIGTERM to TARGET (make:
# make alone, which passes it on; group: every process, as at a job's time limit) and check what is left:
# a checkpoint written on the signal, no output that looks complete, make -q: still to do.
# Returns 1 (nothing checked) if the run completed before the signal could stop it (a resumed run may
# have only a fraction of a second left after its first periodic checkpoint; a signal that comes after
# "done" may still stop make on its way out).
interrupt() {
  local log=$1 target=$2 what=$3 status=0 i
  touch "$tmp/started"
  setsid "${mk[@]}" RUNS="$tmp/runs" CHECKPOINT_EVERY=0.25 "$out" > "$log" 2>&1 &
  job=$!
  for ((i = 0; i < 1200; ++i)); do
    [ "$ckpt" -nt "$tmp/started" ] && break
    kill -0 "$job" 2> /dev/null || break
    sleep 0.05
  done
  touch "$tmp/signalled"
  if [ "$target" = make ]; then kill -TERM "$job" 2> /dev/null; else kill -TERM -- "-$job" 2> /dev/null; fi
  wait "$job" || status=$?
  job=""
  grep -q 'done in' "$log" && return 1
  [ "$status" != 0 ] || { cat "$log" >&2; fail "$what: make succeeded but the run did not complete"; }
  grep -q 'stopped (exit' "$log" || { cat "$log" >&2; fail "$what: the make log does not report a stopped run"; }
  [ "$ckpt" -nt "$tmp/signalled" ] || { cat "$log" >&2; fail "$what: no checkpoint written on the signal"; }
  [ ! -e "$out" ] || fail "$what: $out is left, which make would take for complete"
  "${mk[@]}" RUNS="$tmp/runs" -q "$out" && fail "$what: make -q takes the stopped run for done"
  echo "$what: checkpoint left ($(du -k "$ckpt" | cut -f1) kB), no output, make -q: still to do"
}

# 2. SIGTERM to make alone
interrupt "$tmp/run1.log" make "SIGTERM to make" || fail "the run completed before the signal could stop it"
# What a launcher killed before it could clean up leaves (srun at a time limit): a partial output beside
# the checkpoint. make must not take it for done (an output with a checkpoint beside it is unfinished).
echo partial > "$out"
"${mk[@]}" RUNS="$tmp/runs" -q "$out" && fail "make -q takes an output with a checkpoint beside it for done"

# 3. make again: it resumes; SIGTERM to every process
if interrupt "$tmp/run2.log" group "SIGTERM to every process of the rerun"; then
  grep -q 'resuming from' "$tmp/run2.log" || { cat "$tmp/run2.log" >&2; fail "the rerun of make did not resume"; }
  # 4. make again, to the end
  t0=$(now)
  "${mk[@]}" RUNS="$tmp/runs" "$out" > "$tmp/run3.log" 2>&1 || { cat "$tmp/run3.log" >&2; fail "the last rerun of make failed"; }
  echo "last rerun: $(since "$t0") s"
  grep -q 'resuming from' "$tmp/run3.log" || { cat "$tmp/run3.log" >&2; fail "the last rerun did not resume"; }
else
  echo "note: the rerun completed before the signal could stop it; second interruption skipped"
  grep -q 'resuming from' "$tmp/run2.log" || { cat "$tmp/run2.log" >&2; fail "the rerun of make did not resume"; }
fi
[ -s "$out" ] || fail "no $out after the reruns"
[ ! -e "$ckpt" ] || fail "checkpoint left after the run completed"
h5_same "$ref" "$out" /observables || fail "/observables differ from the uninterrupted run"
h5_same "$ref" "$out" /particles || fail "/particles differ from the uninterrupted run"
h5diff -q --exclude-path /parameters/provenance "$ref" "$out" || fail "the output differs from the uninterrupted run"
"${mk[@]}" RUNS="$tmp/runs" -q "$out" || fail "make -q: the completed run is still to do"
echo "resumed run identical to the uninterrupted one (h5diff /observables, /particles)"
echo "PASS"
