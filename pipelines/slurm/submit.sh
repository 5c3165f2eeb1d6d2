#!/bin/bash
# submit.sh: run the study on a Slurm cluster as job arrays (one per ensemble, array index = seed) and
# one dependent job (afterok on every array) that runs the analyses and figures.
#
#   pipelines/slurm/submit.sh [options] [MAKE VARIABLES]
#   pipelines/slurm/submit.sh SCALE=paper
#   pipelines/slurm/submit.sh --sbatch '--account=proj --partition=cpu' --array-opts '--time=2:00:00' SCALE=paper
#   make -f Makefile.study slurm-submit SCALE=paper SLURM_SUBMIT_OPTS='--wait'
#
# MAKE VARIABLES (SCALE=..., RUNS=..., FIGURES=..., BUILD=..., NRUN=..., analysis options) are passed to
# every make call, here and in the analysis job, exactly as to `make -f Makefile.study`.
# Options:
#   -f MAKEFILE          the study makefile (default Makefile.study; slurm.mk is added if it does not include it)
#   --sbatch 'OPTS'      sbatch options for every job (account, partition, QOS, ...)
#   --array-opts 'OPTS'  sbatch options for the simulation arrays only (e.g. --time=, --mem=)
#   --analyze-opts 'OPTS' sbatch options for the analysis job only (its script asks for 4 CPUs)
#   --logs DIR           job logs (default RUNS/SCALE/slurm-logs)
#   --wait               wait for the analysis job; exit 0 if it completed (poll: SUBMIT_POLL s, default 10)
#   --dry-run            print the sbatch commands, submit nothing
#
# What it submits is what `make` would run: it asks make for the simulation commands still to run
# (make -n sims, with a marker as LAUNCH: `MARKER pipelines/sim-resume.sh GG_SIM ... -o OUT`), groups them
# by ensemble (same command but the seed, output OUTDIR/run<seed>.h5), and submits
# pipelines/slurm/ensemble.sbatch once per ensemble with --array=<those seeds>. So the arrays write
# exactly the files make expects, finished runs are never submitted again, and rerunning submit.sh after
# a failure (time limit, node failure) submits only what is missing: make counts a run with a checkpoint
# beside its output as unfinished, and the task resumes from that checkpoint (sim-resume.sh, as make does). The tools are built first, here (on the
# submit host: the build directory must be on a filesystem the compute nodes share).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
die() { echo "submit.sh: $*" >&2; exit 2; }

makefile=Makefile.study sbatch_opts="" array_opts="" analyze_opts="" logs="" wait=0 dry=0
vars=()
while [ $# -gt 0 ]; do
  case $1 in
    -f) makefile=$2; shift 2 ;;
    --sbatch) sbatch_opts=$2; shift 2 ;;
    --array-opts) array_opts=$2; shift 2 ;;
    --analyze-opts) analyze_opts=$2; shift 2 ;;
    --logs) logs=$2; shift 2 ;;
    --wait) wait=1; shift ;;
    --dry-run) dry=1; shift ;;
    -h|--help) sed -n '2,/^set -euo/p' "${BASH_SOURCE[0]}" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    *=*) vars+=("$1"); shift ;;
    *) die "unknown argument '$1' (see --help)" ;;
  esac
done
[ -f "$makefile" ] || die "no $makefile here: run from the project root (or give -f MAKEFILE)"
command -v sbatch > /dev/null || [ "$dry" = 1 ] || die "sbatch not found (not on a Slurm submit host?)"
# A make started from a make recipe must not inherit its jobserver or its command-line variables.
unset MAKEFLAGS MFLAGS MAKELEVEL MAKEOVERRIDES
mk=(make --no-print-directory -f "$makefile")
grep -qE '^[[:space:]]*-?include[[:space:]].*pipelines/slurm/slurm\.mk' "$makefile" ||
  mk+=(-f "$here/slurm.mk")

# The value make uses for a variable (command line, environment or default).
mkvar() { "${mk[@]}" ${vars[@]+"${vars[@]}"} slurm-print-"$1" | sed -n 's/^SLURM-VAR=//p'; }
runs=$(mkvar RUNS) scale=$(mkvar SCALE)
[ -n "$logs" ] || logs=$runs/$scale/slurm-logs

echo "submit.sh: building the tools if needed (make slurm-tools)" >&2
[ "$dry" = 1 ] || "${mk[@]}" ${vars[@]+"${vars[@]}"} slurm-tools >&2

# Simulation commands make would run, one per line (continuation lines joined).
marker=__GG_SLURM_LAUNCH__
cmds=$("${mk[@]}" ${vars[@]+"${vars[@]}"} -n LAUNCH="$marker" sims | sed -e ':a' -e '/\\$/{N; s/\\\n//; ba' -e '}' |
       grep -E "^[[:space:]]*${marker}[[:space:]]" || true)

# Group by ensemble: key = OUTDIR, SCENE, wrapper and gg-sim paths, the checkpoint interval (passed to
# ensemble.sbatch as CHECKPOINT_EVERY) and every flag but --seed/-o/--quiet.
declare -A seeds=()
order=()
while read -r line; do
  [ -n "$line" ] || continue
  case $line in *\'*|*\"*|*\\*) die "cannot parse (quotes): $line" ;; esac
  read -ra w <<< "$line"
  resume=${w[1]} sim=${w[2]:-} scene="" seed="" out="" every=600 flags=()
  [ "$(basename "$resume")" = sim-resume.sh ] || die "not a simulation through sim-resume.sh: $line"
  for ((i = 3; i < ${#w[@]}; ++i)); do
    case ${w[i]} in
      --scene) scene=${w[++i]} ;;
      --seed) seed=${w[++i]} ;;
      -o|--output) out=${w[++i]} ;;
      --checkpoint-every) every=${w[++i]} ;;
      --quiet) ;;
      *) flags+=("${w[i]}") ;;
    esac
  done
  [ -n "$scene" ] && [ -n "$seed" ] && [ -n "$out" ] || die "no --scene/--seed/-o in: $line"
  [ "$(basename "$out")" = "run$seed.h5" ] ||
    die "output $out is not OUTDIR/run<seed>.h5: ensemble.sbatch cannot write it (line: $line)"
  key="$(dirname "$out") $scene $resume $sim $every ${flags[*]}"
  if [ -z "${seeds[$key]+x}" ]; then order+=("$key"); seeds[$key]=$seed
  else seeds[$key]+=",$seed"; fi
done <<< "$cmds"

ranges() {  # 1,2,3,5,7,8 -> 1-3,5,7-8
  tr ',' '\n' <<< "$1" | sort -n | awk 'NR == 1 { a = b = $1; next }
    $1 == b + 1 { b = $1; next } { out = out (a == b ? a : a "-" b) ","; a = b = $1 }
    END { print out (a == b ? a : a "-" b) }'
}
submit() {  # sbatch ARGS... -> job id (or a placeholder in a dry run)
  if [ "$dry" = 1 ]; then
    echo "sbatch $*" >&2; echo DRYRUN
  else
    sbatch --parsable "$@" | cut -d';' -f1
  fi
}
[ "$dry" = 1 ] || mkdir -p "$logs"
ids=()
for key in ${order[@]+"${order[@]}"}; do
  read -ra k <<< "$key"
  outdir=${k[0]} scene=${k[1]} resume=${k[2]} sim=${k[3]} every=${k[4]}
  name=gg-$(basename "$(dirname "$outdir")")-$(basename "$outdir")
  # shellcheck disable=SC2086
  id=$(GG_SIM=$sim GG_SIM_RESUME=$resume CHECKPOINT_EVERY=$every \
       submit --array="$(ranges "${seeds[$key]}")" --job-name="$name" --output="$logs/%x-%A_%a.out" \
         $sbatch_opts $array_opts "$here/ensemble.sbatch" "$outdir" "$scene" "${k[@]:5}")
  echo "submit.sh: job array $id: $outdir/run{$(ranges "${seeds[$key]}")}.h5" >&2
  ids+=("$id")
done
[ ${#ids[@]} -gt 0 ] || echo "submit.sh: every simulation is done already; submitting the analysis only" >&2

dep=()
[ ${#ids[@]} -eq 0 ] || dep=(--dependency="afterok:$(IFS=:; echo "${ids[*]}")" --kill-on-invalid-dep=yes)
# shellcheck disable=SC2086
aid=$(STUDY_MAKEFILE=$makefile submit ${dep[@]+"${dep[@]}"} \
        --job-name=gg-analyze-"$scale" --output="$logs/%x-%j.out" $sbatch_opts $analyze_opts \
        "$here/analyze.sbatch" ${vars[@]+"${vars[@]}"})
echo "submit.sh: analysis job $aid${ids[*]:+ (after ${ids[*]})}; logs in $logs" >&2
echo "$aid"
[ "$wait" = 1 ] && [ "$dry" = 0 ] || exit 0

# --wait: poll until the analysis job has left the queue (it is cancelled if an array fails:
# --kill-on-invalid-dep), every SUBMIT_POLL seconds (default 10), then report how it ended.
while [ -n "$(squeue -h -j "$aid" -o %A 2> /dev/null)" ]; do sleep "${SUBMIT_POLL:-10}"; done
state=$(scontrol -o show job "$aid" 2> /dev/null | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p' | head -n1)
if [ "$state" = COMPLETED ]; then
  echo "submit.sh: analysis job $aid completed" >&2
  exit 0
fi
echo "submit.sh: analysis job $aid ended ${state:-in an unknown state (no longer known to slurmctld)}" >&2
for id in ${ids[@]+"${ids[@]}"}; do
  scontrol -o show job "$id" 2> /dev/null | sed -n 's/^JobId=[0-9]* ArrayJobId=\([0-9]*\) ArrayTaskId=\([0-9,-]*\) .*JobState=\([A-Z_]*\).*/  array \1_\2: \3/p' >&2
done
exit 1
