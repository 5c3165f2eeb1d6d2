#!/bin/bash
# cpu-log.sh TARGET CMD ARGS...
# Runs CMD and appends its CPU time (user + system seconds of CMD and its children) to TARGET.cpu as one
# line "cpu <seconds> <exit status> <UTC end time>". A run that is stopped and resumed (sim-resume.sh)
# adds one line per piece, so the sum of the first numbers is the CPU the whole run took; the finite-size
# results record it (pipelines/finite-size/collect.sh). The exit status is CMD's.
set -uo pipefail
target=${1:?usage: cpu-log.sh TARGET CMD ARGS...}; shift
TIMEFORMAT='%3U %3S'
# A stop of the whole process group (Ctrl-C, a job's time limit, a cancelled make) reaches CMD, which
# saves its checkpoint and exits; this script waits for it and still logs the piece. (A handler, not an
# ignored signal: CMD must still receive it.)
trap 'true' TERM INT
times=$(mktemp)
{ time "$@" 2>&3; } 3>&2 2>"$times"   # CMD's stderr stays stderr; only bash's time line goes to the file
status=$?
read -r user sys < "$times" 2>/dev/null || { user=0; sys=0; }
rm -f "$times"
printf 'cpu %s %s %s\n' "$(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.1f", u + s }')" "$status" \
  "$(date -u +%Y-%m-%dT%H:%M:%SZ)" >> "$target.cpu"
exit $status
