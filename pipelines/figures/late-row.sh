#!/bin/bash
# late-row.sh NAME E SERIES END OUT   (called by answer.sh and fig8.sh)
# One fits row, the late exponent of an ensemble q(t) (SERIES: a gg-fit average output; q is the mean mass
# m, or the symbol in FS_QUANTITY) over the last FS_LATE_DECADES before END, whether it has settled
# (against the window before) and the values of q the window spans (docs/PHYSICS.md "The answer"):
#   NAME E z stderr t1 t2 "change from the ... decades before: ... (settled|still changing); q from ... to ..."
# or, where it cannot be measured (a window too short), NAME E nan nan - END and why. OUT: the gg-fit
# late-exponent output it writes. Environment: FIT, FS_SIGMAS, FS_LATE_DECADES, FS_QUANTITY.
set -euo pipefail
: "${FIT:?}" "${FS_SIGMAS:?}" "${FS_LATE_DECADES:?}"
name=$1 e=$2 mass=$3 end=$4 f=$5
g() { awk -v x="$1" 'BEGIN { if (x ~ /nan|inf/) print "n/a"; else printf "%.4g", x }'; }
val() { "$FIT" table --no-header "$1:$2" | head -n 1 | cut -f1; }
if ! "$FIT" --quiet late-exponent "$mass:/average/mean" --end "$end" --decades "$FS_LATE_DECADES" \
       --sigmas "$FS_SIGMAS" -o "$f" 2> "$f.err"; then
  printf '%s\t%s\tnan\tnan\t-\t%s\t%s\n' "$name" "$e" "$(g "$end")" \
    "$(sed -e 's/^gg-fit[a-z -]*: \(error: \)\{0,1\}//' -e 's/^late-exponent: [^ ]* carries/the ensemble carries/' "$f.err" | head -n 1)"
  exit 0
fi
z=$(val "$f" /late/exponent) s=$(val "$f" /late/exponent_stderr)
c=$(val "$f" /late/change) cs=$(val "$f" /late/change_stderr)
read -r a b < <("$FIT" table --no-header "$f:/late/window" | paste -sd ' ')
settled=$([ "$(val "$f" /late/settled)" = 1 ] && echo settled || echo "still changing")
# The values the window spans: windows of different e compare equal growth stages where they overlap.
read -r ma mb < <("$FIT" table --no-header "$mass:/average/mean" | awk -v a="$a" -v b="$b" \
  '$1 >= a * (1 - 1e-9) && first == "" { first = $2 } $1 <= b * (1 + 1e-9) { last = $2 } END { print first, last }')
printf '%s\t%s\t%s\t%s\t%s\t%s\tchange from the %s decades before: %s +- %s (%s); %s from %s to %s\n' \
  "$name" "$e" "$(g "$z")" "$(g "$s")" "$(g "$a")" "$(g "$b")" "$FS_LATE_DECADES" "$(g "$c")" "$(g "$cs")" \
  "$settled" "${FS_QUANTITY:-m}" "$(g "$ma")" "$(g "$mb")"
