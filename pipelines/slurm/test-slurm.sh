#!/bin/bash
# test-slurm.sh: the study through a real (single-node) Slurm gives the same results as a local run.
# Called by `make -f Makefile.study test-slurm` (not part of `make test`: CI runs it after it, .ci/run); needs root (or sudo
# for apt-get and the daemons) and about 2 minutes on 2 cores.
#
#   1. installs Debian's slurm-wlm if missing (apt-get);
#   2. runs SCALE=quick locally (reference), in a temporary directory;
#   3. starts a private single-node Slurm (cluster.sh: slurmctld + slurmd, config/state/logs in the
#      temporary directory, auth/none, or munge with --munge);
#   4. runs SCALE=quick inside an allocation with LAUNCH='srun -n1 -c1 --exact' (pipelines/slurm/study.sbatch,
#      the documented batch script) and checks that every simulation ran as a job step; then cancels such
#      a job in the middle (what its time limit does) and reruns it: it must finish the same simulations
#      (the stopped ones resumed from their checkpoints);
#   5. runs SCALE=quick as job arrays + dependent analysis job (submit.sh --wait) and checks that the
#      analysis job ran no simulation; resubmits and checks that nothing is simulated again;
#   6. interrupts an array task twice (SIGTERM to all its processes as at a time limit, then to the batch
#      shell only as with sbatch --signal=B:TERM@T) and checks that it leaves no output that looks
#      complete, and that resubmitting resumes from the checkpoint to the same result;
#   7. compares every simulation and analysis output (h5diff: every dataset and attribute except
#      /parameters/provenance) and every figure table with the reference. Each run works in its own
#      directory of symlinks to the project (RUNS=runs, FIGURES=figures), so the file names recorded
#      in the outputs are the same, too;
#   8. stops the daemons it started, by PID, also on failure or Ctrl-C (trap), and removes the temporary
#      directory (kept on failure, or with --keep).
# Environment: SELF (study makefile, default Makefile.study), BUILD (default build).
set -euo pipefail
exec 7>&1 8>&2   # the caller's stdout/stderr, for cleanup (a trap runs inside redirections in force)
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
self=${SELF:-Makefile.study}
build=${BUILD:-build}
keep=0 munge=()
for a in "$@"; do
  case $a in
    --keep) keep=1 ;;
    --munge) munge=(--munge) ;;
    *) echo "test-slurm.sh: unknown option $a (--keep, --munge)" >&2; exit 2 ;;
  esac
done
# The makes below are ours: no jobserver or command-line variables of a calling make.
unset MAKEFLAGS MFLAGS MAKELEVEL MAKEOVERRIDES
[ -f "$self" ] && [ -d pipelines/slurm ] || { echo "test-slurm.sh: run from the project root" >&2; exit 2; }
ncpu=$(nproc)
[ "$ncpu" -le 2 ] || ncpu=2   # a small node is enough, and keeps the test light on a big machine

say() { printf '\n=== test-slurm: %s\n' "$*" >&2; }
fail() { echo "test-slurm: FAIL: $*" >&2; exit 1; }
sudo=""; [ "$(id -u)" = 0 ] || sudo=sudo

# ------------------------------------------------------------------------------------------------ 1. slurm
if ! command -v slurmctld > /dev/null || ! command -v slurmd > /dev/null || ! command -v sbatch > /dev/null; then
  say "installing slurm-wlm (Debian package)"
  $sudo apt-get update
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends slurm-wlm
fi
command -v h5diff > /dev/null || fail "h5diff not found (make -f $self deps installs hdf5-tools)"
[ -x "$build/simulate/gg-sim" ] || fail "$build/simulate/gg-sim missing (make -f $self build)"

tmp=$(mktemp -d "${TMPDIR:-/tmp}/gg-test-slurm.XXXXXX")
ok=0 child=""
# run CMD...: CMD in its own process group, waited for interruptibly, so that a signal to this script
# ends it at once (cleanup stops the whole group, by its id).
run() {
  setsid "$@" & child=$!
  local status=0
  wait "$child" || status=$?
  child=""
  return "$status"
}
cleanup() {
  local status=$?
  trap - EXIT INT TERM HUP
  exec 1>&7 2>&8
  if [ -n "$child" ]; then kill -TERM -- -"$child" 2> /dev/null || true; wait "$child" 2> /dev/null || true; fi
  if [ -f "$tmp/cluster/pids" ]; then
    if [ -n "$sudo" ]; then $sudo "$here/cluster.sh" stop "$tmp/cluster" || true
    else "$here/cluster.sh" stop "$tmp/cluster" || true; fi
  fi
  if [ "$ok" = 1 ] && [ "$keep" = 0 ]; then rm -rf "$tmp"
  else echo "test-slurm: files kept in $tmp (logs: $tmp/cluster/log, $tmp/*/logs)" >&2; fi
  exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
trap 'exit 129' HUP

root=$(pwd)
selfabs=$(realpath "$self") selfname=$(basename "$self")
build=$(cd "$build" && pwd)   # absolute: the runs below work in other directories
export GG_SIM=$build/simulate/gg-sim   # for ensemble.sbatch submitted by hand (submit.sh sets it itself)
q=(SCALE=quick BUILD="$build" RUNS=runs FIGURES=figures)
# workdir NAME: $tmp/NAME, a view of the project (symlinks to every top-level entry but runs/figures).
workdir() {
  local d=$tmp/$1 f
  mkdir -p "$d"
  ln -s "$selfabs" "$d/$selfname"
  for f in "$root"/*; do
    case $(basename "$f") in runs|figures) continue ;; esac
    [ -e "$d/$(basename "$f")" ] || ln -s "$f" "$d/$(basename "$f")"
  done
  echo "$d"
}
in_queue() { [ -n "$(squeue -h -j "$1" -o %A 2> /dev/null)" ]; }  # in_queue ID: the job is pending or running
# wait_job ID: until the job (all tasks of an array) has left the queue; true if every part COMPLETED.
wait_job() {
  while in_queue "$1"; do sleep 0.5; done
  local states
  states=$(scontrol -o show job "$1" | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p' | sort -u)
  [ "$states" = COMPLETED ] || { echo "test-slurm: job $1 ended: $states" >&2; return 1; }
}
sbatch_wait() {  # sbatch ARGS...: submit, wait, true if completed
  local id
  id=$(sbatch --parsable "$@" | cut -d';' -f1)
  wait_job "$id"
}
mk=(make --no-print-directory -f "$selfname")
grep -qE '^[[:space:]]*-?include[[:space:]].*pipelines/slurm/slurm\.mk' "$self" || mk+=(-f pipelines/slurm/slurm.mk)

# --------------------------------------------------------------------------------------- 2. local reference
say "local reference run (make -j$ncpu SCALE=quick figures summary)"
t0=$(date +%s)
cd "$(workdir local)"
run "${mk[@]}" -j"$ncpu" "${q[@]}" figures summary > "$tmp/local.log" 2>&1 ||
  { tail -n 30 "$tmp/local.log" >&2; fail "local run failed (log: $tmp/local.log)"; }
echo "local run: $(( $(date +%s) - t0 )) s" >&2
nsims=$(find "$tmp/local/runs/quick/sim" -name 'run*.h5' | wc -l)
[ "$nsims" -gt 0 ] || fail "the local run made no simulation outputs"

# ---------------------------------------------------------------------------------------------- 3. cluster
say "starting a single-node Slurm with $ncpu CPUs"
$sudo "$here/cluster.sh" start "$tmp/cluster" --cpus "$ncpu" ${munge[@]+"${munge[@]}"}
export SLURM_CONF=$tmp/cluster/slurm.conf
sinfo >&2

steps_launched() { grep -c 'launch task StepId=' "$tmp/cluster/log/slurmd.log" || true; }

# ------------------------------------------------------------------------------- 4. srun inside an allocation
say "SCALE=quick in one allocation: study.sbatch, LAUNCH='srun -n1 -c1 --exact'"
cd "$(workdir srun)"
s0=$(steps_launched)
t0=$(date +%s)
sbatch_wait --nodes=1 --ntasks="$ncpu" --ntasks-per-node="$ncpu" --cpus-per-task=1 --time=30 \
  --output="$tmp/srun/job.out" pipelines/slurm/study.sbatch "${q[@]}" ||
  { tail -n 30 "$tmp/srun/job.out" >&2; fail "study.sbatch failed (log: $tmp/srun/job.out)"; }
echo "allocation run: $(( $(date +%s) - t0 )) s" >&2
nsteps=$(( $(steps_launched) - s0 ))
nlaunch=$(grep -c 'srun -n1 -c1 --exact .*gg-sim' "$tmp/srun/job.out" || true)
echo "simulations launched through srun: $nlaunch; job steps started by slurmd: $nsteps" >&2
[ "$nlaunch" = "$nsims" ] || fail "expected $nsims simulations through srun, the make log shows $nlaunch"
[ "$nsteps" = "$nsims" ] || fail "expected $nsims job steps, slurmd started $nsteps"

say "a cancelled allocation (as at its time limit) leaves nothing make takes for finished"
cd "$(workdir cancel)"
id=$(sbatch --parsable --nodes=1 --ntasks="$ncpu" --ntasks-per-node="$ncpu" --cpus-per-task=1 --time=30 \
       --output="$tmp/cancel/job1.out" pipelines/slurm/study.sbatch "${q[@]}" sims)
# cancel once a few simulations are done and others are running
for ((i = 0; i < 600; ++i)); do
  [ "$(find runs -name 'run*.h5' 2> /dev/null | wc -l)" -ge 3 ] && break
  in_queue "$id" || break
  sleep 0.05
done
# On a fast machine the job may have ended first: scancel then answers "Invalid job id", and the
# rerun below simply finds everything done.
scancel "$id" 2> /dev/null || echo "test-slurm: note: job $id ended before scancel" >&2
wait_job "$id" 2> /dev/null || true   # CANCELLED: expected
left=$(find runs -name 'run*.h5.checkpoint.h5' | wc -l)
echo "cancelled with $(find runs -name 'run*.h5' | wc -l) of $nsims outputs present, $left of them from stopped runs" >&2
sbatch_wait --nodes=1 --ntasks="$ncpu" --ntasks-per-node="$ncpu" --cpus-per-task=1 --time=30 \
  --output="$tmp/cancel/job2.out" pipelines/slurm/study.sbatch "${q[@]}" sims ||
  { tail -n 30 "$tmp/cancel/job2.out" >&2; fail "the rerun after the cancel failed"; }
grep 'resuming from' "$tmp/cancel/job2.out" >&2 || true
[ -z "$(find runs -name '*.checkpoint.h5')" ] || fail "checkpoints left after the rerun: $(find runs -name '*.checkpoint.h5')"
echo "ok: rerun completed the study's simulations (compared below)" >&2

# ------------------------------------------------------------------------------------ 5. job arrays + afterok
say "SCALE=quick as job arrays + dependent analysis job (submit.sh --wait)"
cd "$(workdir array)"
t0=$(date +%s)
# CHECKPOINT_EVERY=1: periodic checkpoints during the array runs must not change the results either.
CHECKPOINT_EVERY=1 SUBMIT_POLL=0.5 run pipelines/slurm/submit.sh -f "$selfname" --wait --logs "$tmp/array/logs" \
  --analyze-opts "--cpus-per-task=$ncpu" "${q[@]}" > "$tmp/array/submit.out" 2> "$tmp/array/submit.log" ||
  { cat "$tmp/array/submit.log" >&2; tail -n 30 "$tmp"/array/logs/* >&2; fail "submit.sh --wait failed"; }
cat "$tmp/array/submit.log" >&2
echo "arrays + analysis: $(( $(date +%s) - t0 )) s" >&2
narrays=$(grep -c '^submit.sh: job array' "$tmp/array/submit.log" || true)
ndone=$(grep -l 'done in' "$tmp"/array/logs/gg-*_*.out | wc -l)
[ "$ndone" = "$nsims" ] || fail "expected $nsims array tasks to run a simulation, $ndone did"
alog=$(ls "$tmp"/array/logs/gg-analyze-quick-*.out)
! grep -q 'simulate/gg-sim' "$alog" || fail "the analysis job ran simulations (see $alog)"
grep -q 'fig7' "$alog" || fail "the analysis job made no figures (see $alog)"
"${mk[@]}" -q "${q[@]}" sims || fail "make still has simulations to run after the arrays"
echo "ok: $narrays arrays, $ndone array tasks, analysis job ran no simulation" >&2

say "resubmitting: nothing may be simulated again"
before=$(find "$tmp/array/runs" -name 'run*.h5' -newer "$tmp/array/submit.out" | wc -l)
SUBMIT_POLL=0.5 run pipelines/slurm/submit.sh -f "$selfname" --wait --logs "$tmp/array/logs2" \
  --analyze-opts "--cpus-per-task=$ncpu" "${q[@]}" \
  > /dev/null 2> "$tmp/array/resubmit.log" || { cat "$tmp/array/resubmit.log" >&2; fail "resubmission failed"; }
grep -q 'every simulation is done already' "$tmp/array/resubmit.log" || fail "resubmission submitted simulations"
after=$(find "$tmp/array/runs" -name 'run*.h5' -newer "$tmp/array/submit.out" | wc -l)
[ "$before" = "$after" ] || fail "resubmission rewrote simulation outputs"
# The array script itself skips complete runs, too (a user resubmitting an array by hand).
ens=$(find "$tmp/array/runs/quick/sim/ens" -mindepth 1 -maxdepth 1 -type d | sort | head -n1)
e=$(basename "$ens" | sed 's/^e\([0-9.]*\)-L\([0-9]*\)-t\([0-9]*\)$/\1 \2 \3/')
read -r ee LL tt <<< "$e"
sbatch_wait --array=1-2 --output="$tmp/array/logs2/byhand-%a.out" pipelines/slurm/ensemble.sbatch \
  "$ens" pipelines/scenes/fig3-e"$ee".ini --L "$LL" --t-max "$tt" || fail "ensemble.sbatch by hand failed"
[ "$(grep -l 'is complete, skipping' "$tmp"/array/logs2/byhand-*.out | wc -l)" = 2 ] ||
  fail "ensemble.sbatch reran complete runs (see $tmp/array/logs2/byhand-*.out)"
echo "ok: nothing resubmitted, complete runs skipped" >&2

# -------------------------------------------------------------------------------- 6. interrupted array task
say "array tasks stopped by SIGTERM resume from their checkpoints"
# A run long enough to be caught twice (~5-10 s): fig3 e = 0.9, L = 256, t_max = 2000, a checkpoint
# every second. Task 1 gets SIGTERM on every process (what the time limit does), task 2 on the batch
# shell only (what sbatch --signal=B:TERM@T does; the script forwards it), task 3 finishes the run.
ires=$tmp/interrupt
mkdir -p "$ires"
irun=(pipelines/scenes/fig3-e0.9.ini --L 256 --t-max 2000)
ckpt=$ires/ens/run7.h5.checkpoint.h5
run "$build/simulate/gg-sim" --scene "${irun[@]}" --seed 7 --quiet -o "$ires/reference.h5"
interrupted=0
for mode in --full --batch; do
  n=$((interrupted + 1))
  touch "$ires/mark"; sleep 0.01
  jid=$(CHECKPOINT_EVERY=1 sbatch --parsable --array=7 --output="$ires/task-$n.out" pipelines/slurm/ensemble.sbatch \
          "$ires/ens" "${irun[@]}" | cut -d';' -f1)
  # after a checkpoint of this task (so that it is past the equilibration), or once the task has
  # ended (a fast machine runs it in a second or two: then there is nothing to interrupt)
  for ((i = 0; i < 600; ++i)); do [ "$ckpt" -nt "$ires/mark" ] && break; in_queue "$jid" || break; sleep 0.05; done
  scancel "$mode" --signal=TERM "$jid" 2> /dev/null || echo "test-slurm: note: task $n ended before scancel" >&2
  wait_job "$jid" 2> /dev/null || true   # FAILED: expected
  cat "$ires/task-$n.out" >&2
  grep -q 'done in' "$ires/task-$n.out" && break   # finished before the signal (a fast machine)
  grep -q 'stopped (exit' "$ires/task-$n.out" || fail "task $n (scancel $mode) did not report a stop"
  [ ! -e "$ires/ens/run7.h5" ] || fail "task $n left run7.h5, which make would take for complete"
  [ -e "$ckpt" ] || fail "task $n left no checkpoint"
  [ "$n" = 1 ] || grep -q 'resuming from' "$ires/task-$n.out" || fail "task $n did not resume"
  interrupted=$n
done
if [ ! -e "$ires/ens/run7.h5" ]; then
  n=$((interrupted + 1))
  sbatch_wait --array=7 --output="$ires/task-$n.out" pipelines/slurm/ensemble.sbatch "$ires/ens" "${irun[@]}" ||
    { cat "$ires/task-$n.out" >&2; fail "the resubmitted task failed"; }
  cat "$ires/task-$n.out" >&2
  grep -q 'resuming from' "$ires/task-$n.out" || fail "the resubmitted task did not resume"
fi
[ ! -e "$ckpt" ] || fail "the checkpoint is still there after the run completed"
h5diff -q --exclude-path /parameters/provenance "$ires/reference.h5" "$ires/ens/run7.h5" ||
  fail "the interrupted + resumed run differs from an uninterrupted one"
[ "$interrupted" = 2 ] || echo "test-slurm: note: only $interrupted of 2 interruptions happened (the run was too fast)" >&2
echo "ok: $interrupted interruptions (SIGTERM to all, to the batch shell), no output left behind, resumed to the uninterrupted result" >&2

# ------------------------------------------------------------------------------------------- 7. compare
say "comparing with the local reference (h5diff without the provenance)"
# (A finite-size result also keeps each analysis tool's parameters, provenance included, under its group.)
noprov=(--exclude-path /parameters/provenance --exclude-path /simulation/provenance)
for g in correlation domains velocity; do noprov+=(--exclude-path "/$g/parameters/provenance"); done
compare() {  # compare <tree> [sim]: every .h5 of the reference (or its simulations), the same path under <tree>
  local other=$1 only=${2:-} n=0 f rel
  while read -r f; do
    [ -z "$only" ] || [[ $f == "$tmp/local/runs/quick/sim/"* ]] || continue
    rel=${f#"$tmp/local/runs/"}
    [ -e "$tmp/$other/runs/$rel" ] || fail "$other: $rel missing"
    # Provenance (when, where, which command) differs by design: the tool's own, and the simulation's
    # that a finite-size result copies.
    h5diff -q "${noprov[@]}" "$f" "$tmp/$other/runs/$rel" > /dev/null 2>&1 ||
      { h5diff "${noprov[@]}" "$f" "$tmp/$other/runs/$rel" | tail -n 5 >&2;
        fail "$other: $rel differs from the local run"; }
    n=$((n + 1))
  done < <(find "$tmp/local/runs" -name '*.h5' | sort)
  local extra
  extra=$(comm -13 <(cd "$tmp/local/runs" && find . -name '*.h5' | sort) \
                   <(cd "$tmp/$other/runs" && find . -name '*.h5' | sort))
  [ -z "$extra" ] || fail "$other: outputs the local run does not have: $extra"
  if [ -n "$only" ]; then
    echo "ok: $other: the $n simulation outputs identical to the local run" >&2
    return
  fi
  for f in "$tmp"/local/figures/*.tsv "$tmp"/local/figures/summary.md; do
    cmp -s "$f" "$tmp/$other/figures/$(basename "$f")" || fail "$other: figures/$(basename "$f") differs"
  done
  echo "ok: $other: $n HDF5 files ($nsims simulations, the rest analyses), $(ls "$tmp"/local/figures/*.tsv | wc -l) figure tables and summary.md identical to the local run" >&2
}
compare srun
compare array
compare cancel sim

ok=1
say "PASSED"
