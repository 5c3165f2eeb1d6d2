#!/bin/bash
# timed.sh [--allow-collapse] TARGET CMD ARGS...
# Runs CMD (which must write TARGET.part.h5), measures its CPU time (user + system, bash `time`), and on
# success writes TARGET.cpu, then renames TARGET.part.h5 to TARGET, so a complete-looking TARGET always has
# its CPU record. TARGET.cpu holds tab-separated "key value" lines:
#   cpu     <user+sys seconds>
#   status  ok | collapse
#   message <gg-sim's collapse message>          (status collapse only)
# --allow-collapse: gg-sim's exit 1 for an inelastic collapse (it still writes everything recorded up to
# then) counts as a result, not a failure: a collapsed run is a data point of the accuracy study.
set -uo pipefail
allow=0
if [ "${1:-}" = --allow-collapse ]; then allow=1; shift; fi
target=${1:?usage: timed.sh [--allow-collapse] TARGET CMD ARGS...}; shift
part=$target.part.h5 log=$target.log.tmp cpu=$target.cpu.tmp
rm -f "$part" "$log" "$cpu"
TIMEFORMAT='%3U %3S'
{ time "$@" 2>"$log"; } 2>"$cpu.time"
status=$?
[ -s "$log" ] && cat "$log" >&2
read -r user sys < "$cpu.time" || { user=nan; sys=0; }
rm -f "$cpu.time"
state=ok msg=
if [ $status -ne 0 ]; then
  if [ $allow = 1 ] && [ $status = 1 ] && [ -e "$part" ] && grep -q 'inelastic collapse' "$log"; then
    state=collapse; msg=$(grep -m1 'inelastic collapse' "$log")
  else
    echo "timed.sh: '$1' failed (exit $status); no $target" >&2
    rm -f "$part" "$log"; exit $status
  fi
fi
rm -f "$log"
{
  printf 'cpu\t%s\n' "$(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.3f", u + s }')"
  printf 'status\t%s\n' "$state"
  [ -z "$msg" ] || printf 'message\t%s\n' "$msg"
} > "$cpu"
mv "$cpu" "$target.cpu"
mv "$part" "$target"
