#!/bin/bash
# scaling.sh: how the study's time scales with the number of CPUs, measured through a private single-node
# Slurm (cluster.sh), and projected to P nodes from the ensemble sizes and run costs of a larger scale.
# Called by `make -f Makefile.study slurm-scaling [SLURM_SCALING_OPTS='...']`; needs root.
#
#   pipelines/slurm/scaling.sh [--scale quick] [--cpus '1 2'] [--repeat 2 (0: projection only)] [--cores 32]
#                              [--project 'SCALE=paper' --project 'SCALE=paper L2=4096 FIG2_L=4096 NRUN=20']
#
# For each CPU count c and repetition, one batch job with c CPUs runs, in a fresh RUNS directory,
#   make -jc LAUNCH='srun -n1 -c1 --exact /usr/bin/time ...' SCALE=... sims     (the simulations, job steps)
#   make -jc SCALE=... figures summary                                           (analyses, fits, plots)
# and records both wall times (inside the job, so queueing is not counted) and every run's own time.
# The same two makes also run outside Slurm with -j1 and -jc to show the overhead of srun; there each
# simulation runs under setsid, as a Slurm task does (with the kernel's autogroup scheduling, CPU time is
# shared between sessions: without it a local make -j2 competes for the CPUs as one process would).
# Projection: `make plan <project variables>` gives each ensemble's runs and CPU seconds (plan.sh's cost
# model); the runs are dealt longest-first to C CPUs (C/--cores nodes), as the scheduler would start
# them, and the wall time of the simulations is that schedule's makespan.
# Environment: SELF (study makefile, default Makefile.study), BUILD (default build).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
self=${SELF:-Makefile.study}
build=$(cd "${BUILD:-build}" && pwd)
scale=quick cpus="1 2" repeat=2 projects=() cores=32
while [ $# -gt 0 ]; do
  case $1 in
    --scale) scale=$2; shift 2 ;;
    --cpus) cpus=$2; shift 2 ;;
    --repeat) repeat=$2; shift 2 ;;
    --project) projects+=("$2"); shift 2 ;;
    --cores) cores=$2; shift 2 ;;
    *) echo "scaling.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
unset MAKEFLAGS MFLAGS MAKELEVEL MAKEOVERRIDES
mk=(make --no-print-directory -f "$self")
grep -qE '^[[:space:]]*-?include[[:space:]].*pipelines/slurm/slurm\.mk' "$self" || mk+=(-f "$here/slurm.mk")
maxc=0
for c in $cpus; do [ "$c" -le "$maxc" ] || maxc=$c; done
[ "$maxc" -le "$(nproc)" ] || { echo "scaling.sh: this machine has only $(nproc) CPUs" >&2; exit 2; }
timer=()
[ -x /usr/bin/time ] && timer=(/usr/bin/time -a -f '%e,%U,%S')
[ ${#projects[@]} -gt 0 ] || projects=("SCALE=paper" "SCALE=paper L2=4096 FIG2_L=4096 NRUN=20")

tmp=$(mktemp -d "${TMPDIR:-/tmp}/gg-scaling.XXXXXX")
cleanup() {
  local status=$?
  trap - EXIT INT TERM HUP
  [ ! -f "$tmp/cluster/pids" ] || "$here/cluster.sh" stop "$tmp/cluster" || true
  rm -rf "$tmp"
  exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
trap 'exit 129' HUP

now() { date +%s.%N; }
runcpu() { [ -f "$1" ] && awk -F, '{ s += $2 + $3 } END { printf "%.1f", s }' "$1" || echo nan; }  # CPU s of the runs
results=$tmp/results.tsv   # mode cpus rep sims_s analysis_s runs_cpu_s
: > "$results"
load0=$(cut -d' ' -f1-3 /proc/loadavg)
echo "scaling.sh: load average at start: $load0" >&2

# One measurement of c CPUs, repetition r: outside Slurm, or in a batch job of c CPUs.
measure_local() {
  local c=$1 r=$2 runs=$tmp/local-c$1-r$2 t0 t1 t2
  t0=$(now)
  "${mk[@]}" -j"$c" SCALE="$scale" BUILD="$build" RUNS="$runs/runs" FIGURES="$runs/figures" \
    LAUNCH="setsid ${timer[*]:+${timer[*]} -o $runs/times}" sims > "$runs.log" 2>&1 || { tail "$runs.log" >&2; exit 1; }
  t1=$(now)
  "${mk[@]}" -j"$c" SCALE="$scale" BUILD="$build" RUNS="$runs/runs" FIGURES="$runs/figures" \
    figures summary >> "$runs.log" 2>&1 || { tail "$runs.log" >&2; exit 1; }
  t2=$(now)
  echo "local $c $r $(awk -v a="$t0" -v b="$t1" -v c="$t2" 'BEGIN { printf "%.1f %.1f", b - a, c - b }') $(runcpu "$runs/times")" >> "$results"
  tail -n1 "$results" >&2
  cp "$runs/times" "$tmp/times-local-c$c-r$r" 2> /dev/null || true
  rm -rf "$runs" "$runs.log"
}
measure_slurm() {
  local c=$1 r=$2 runs=$tmp/slurm-c$1-r$2 id line
  mkdir -p "$runs"
  cat > "$runs/job.sh" <<JOB
#!/bin/bash
set -euo pipefail
cd '$(pwd)'
t0=\$(date +%s.%N)
${mk[*]} -j$c SCALE=$scale BUILD=$build RUNS=$runs/runs FIGURES=$runs/figures \\
  LAUNCH='srun -n1 -c1 --exact ${timer[*]:+${timer[*]} -o $runs/times}' sims
t1=\$(date +%s.%N)
${mk[*]} -j$c SCALE=$scale BUILD=$build RUNS=$runs/runs FIGURES=$runs/figures figures summary
t2=\$(date +%s.%N)
echo "TIMES \$t0 \$t1 \$t2"
JOB
  id=$(sbatch --parsable --nodes=1 --ntasks="$c" --cpus-per-task=1 --output="$runs/job.out" "$runs/job.sh")
  while [ -n "$(squeue -h -j "$id" -o %A)" ]; do sleep 0.5; done
  line=$(grep '^TIMES ' "$runs/job.out") || { tail "$runs/job.out" >&2; exit 1; }
  echo "slurm $c $r $(echo "$line" | awk '{ printf "%.1f %.1f", $3 - $2, $4 - $3 }') $(runcpu "$runs/times")" >> "$results"
  tail -n1 "$results" >&2
  cp "$runs/times" "$tmp/times-slurm-c$c-r$r" 2> /dev/null || true
  rm -rf "$runs"
}
# Interleaved (every repetition measures every case), so that a change of the machine's other load
# affects all cases alike.
measure() {
  "$here/cluster.sh" start "$tmp/cluster" --cpus "$maxc"
  export SLURM_CONF=$tmp/cluster/slurm.conf
  local r c
  for ((r = 1; r <= repeat; ++r)); do
    for c in $(printf '%s\n' 1 $cpus | sort -un); do
      measure_local "$c" "$r"
      measure_slurm "$c" "$r"
    done
  done
  "$here/cluster.sh" stop "$tmp/cluster"
  echo "scaling.sh: load average at end: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
}
[ "$repeat" = 0 ] || measure

# ------------------------------------------------------------------------------------------------ report
nsims=$("${mk[@]}" SCALE="$scale" RUNS="$tmp/none" -n LAUNCH=__X__ sims | grep -c __X__ || true)
[ "$repeat" = 0 ] || {
echo
echo "## Measured: SCALE=$scale ($nsims simulations), single-node Slurm, $repeat repetitions"
echo
echo "Load average (other work on the machine) at start / end: $load0 / $(cut -d' ' -f1-3 /proc/loadavg)."
echo "Median (best) of the repetitions. 'ideal': the runs' CPU times (user + system, median over the"
echo "repetitions, Slurm, 1 CPU) dealt longest-first to the CPUs: the wall time on CPUs of one's own."
echo
echo "| where | CPUs (make -j) | simulations, wall [s] | speed-up | ideal [s] | CPU time of the runs [s] | analyses + figures, wall [s] |"
echo "|---|---|---|---|---|---|---|"
# ideal makespan per CPU count from the per-run times
ideal=""
if ls "$tmp"/times-slurm-c1-r* > /dev/null 2>&1; then
  for c in $(printf '%s\n' 1 $cpus | sort -un); do
    ideal="$ideal $c=$(paste -d, "$tmp"/times-slurm-c1-r* | awk -F, -v c="$c" -v reps="$repeat" '
      { for (i = 0; i < reps; ++i) v[i + 1] = $(3 * i + 2) + $(3 * i + 3)
        for (i = 1; i <= reps; ++i) for (j = i + 1; j <= reps; ++j) if (v[j] < v[i]) { t = v[i]; v[i] = v[j]; v[j] = t }
        r[NR] = reps % 2 ? v[(reps + 1) / 2] : (v[reps / 2] + v[reps / 2 + 1]) / 2 }
      END { n = NR
        for (i = 1; i <= n; ++i) for (j = i + 1; j <= n; ++j) if (r[j] > r[i]) { t = r[i]; r[i] = r[j]; r[j] = t }
        for (i = 1; i <= n; ++i) { b = 1; for (s = 2; s <= c; ++s) if (l[s] < l[b]) b = s; l[b] += r[i] }
        m = 0; for (s = 1; s <= c; ++s) if (l[s] > m) m = l[s]; printf "%.1f", m }')"
  done
fi
awk -v ideal="$ideal" '{ key = $1 " " $2; n[key]++; s[key, n[key]] = $4; a[key, n[key]] = $5; u[key, n[key]] = $6
       if (!(key in seen)) { seen[key]; order[++k] = key } }
  function best(arr, key, m,   i, b) { b = arr[key, 1]; for (i = 2; i <= m; ++i) if (arr[key, i] < b) b = arr[key, i]; return b }
  function median(arr, key, m,   i, j, t, v) {
    for (i = 1; i <= m; ++i) v[i] = arr[key, i]
    for (i = 1; i <= m; ++i) for (j = i + 1; j <= m; ++j) if (v[j] < v[i]) { t = v[i]; v[i] = v[j]; v[j] = t }
    return m % 2 ? v[(m + 1) / 2] : (v[m / 2] + v[m / 2 + 1]) / 2 }
  END {
    for (i = 1; i <= k; ++i) { key = order[i]; split(key, f, " ")
      ms[key] = median(s, key, n[key]); ma[key] = median(a, key, n[key]); mu[key] = median(u, key, n[key])
      bs[key] = best(s, key, n[key]); ba[key] = best(a, key, n[key]) }
    m = split(ideal, I, " "); for (i = 1; i <= m; ++i) { split(I[i], kv, "="); id[kv[1]] = kv[2] }
    for (i = 1; i <= k; ++i) { key = order[i]; split(key, f, " ")
      base = ms[f[1] " 1"]; bbase = bs[f[1] " 1"]
      printf "| %s | %d | %.1f (%.1f) | %.2f (%.2f) | %s | %.1f | %.1f (%.1f) |\n",
             (f[1] == "local" ? "local (no Slurm)" : "Slurm, srun steps"), f[2], ms[key], bs[key],
             base / ms[key], bbase / bs[key], (f[2] in id ? id[f[2]] : "-"), mu[key], ma[key], ba[key] } }' <(sort -k1,1 -k2,2n -k3,3n "$results")
echo
echo "Raw (where, CPUs, repetition, simulations s, analyses s, CPU s of the runs):"
sed 's/^/    /' "$results"
if ls "$tmp"/times-slurm-c1-* > /dev/null 2>&1; then
  echo
  awk -F, '{ c = $2 + $3; s += c; w += $1; if (c > m) m = c; n++ } END {
    printf "Per simulation (Slurm, 1 CPU, first repetition): %d runs, CPU time %.1f s in all, longest %.1f s,\n", n, s, m
    printf "mean %.2f s; their wall times add up to %.1f s (the CPUs were shared with other work).\n", s / n, w }' \
    "$tmp"/times-slurm-c1-r1
fi
}

project() {  # project MAKE-VARIABLES...
  echo
  echo "## Projection: $* (simulations; plan.sh cost model, +-50%)"
  echo
  "${mk[@]}" plan "$@" RUNS="$tmp/none" 2> /dev/null | awk -v cores="$cores" '
  /^ +fig[0-9-]+:/ && NF >= 6 { runs = $(NF - 3); cost = $NF / runs
    label = $1; for (i = 2; i <= NF - 5; ++i) label = label " " $i
    for (i = 0; i < runs; ++i) c[++n] = cost; total += $NF
    if (cost > longest) longest = cost
    printf "- %s (N = %d, t_max = %s): %d runs x %.0f CPU s\n", label, $(NF - 4), $(NF - 2), runs, cost }
  function hm(t) { return t >= 3600 ? sprintf("%.1f h", t / 3600) : sprintf("%.1f min", t / 60) }
  END {
    for (i = 1; i <= n; ++i) for (j = i + 1; j <= n; ++j) if (c[j] > c[i]) { t = c[i]; c[i] = c[j]; c[j] = t }
    printf "\n%d runs, %.0f CPU s in all (%.1f CPU h); the longest run, %s, bounds the wall time from below.\n\n",
           n, total, total / 3600, hm(longest)
    printf "| CPUs | nodes of %d cores | simulation wall time | speed-up | CPUs busy |\n|---|---|---|---|---|\n", cores
    for (slots = 1; slots <= 1024; slots *= 2) {
      for (s = 1; s <= slots; ++s) load[s] = 0
      for (i = 1; i <= n; ++i) { b = 1; for (s = 2; s <= slots; ++s) if (load[s] < load[b]) b = s; load[b] += c[i] }
      m = 0; for (s = 1; s <= slots; ++s) if (load[s] > m) m = load[s]
      printf "| %d | %s | %s | %.1f | %.0f%% |\n", slots, (slots < cores ? "<1" : sprintf("%d", slots / cores)), hm(m),
             total / m, 100 * total / (m * slots)
      if (m <= longest * 1.0001) break
    }
  }'
}
for p in "${projects[@]}"; do
  # shellcheck disable=SC2086
  project $p
done
