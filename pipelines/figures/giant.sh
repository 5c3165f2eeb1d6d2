#!/bin/bash
# giant.sh "ES" "LS" "IDS" OUT.tsv   (called by fig8.sh)
# When the giant cluster forms, per e and box edge L, and whether that time grows with L (docs/PHYSICS.md
# "The answer in lengths"): from each cell's ensemble averages $FS_WORK/<id>/share.h5 (the largest cluster's
# share of the particles in clusters) and wraps.h5 (1 where the largest cluster wraps the box, so the
# mean is the fraction of runs wrapping), made by fig8.sh of >= 3 runs each (their number in <name>.runs),
#   t_g     the first time the mean share reaches 1/2 (gg-fit crossing --level 0.5),
#   t_wrap  the first wrapping time, exp(mean over runs of ln t_r), t_r where run r's largest cluster first
#           wraps (gg-fit crossing --per-run: the fraction of runs wrapping crosses 1/2 at the runs' median,
#           whose jackknife is too narrow; NaN when a run never wraps in its window),
# t_g with its jackknife error over runs, t_wrap with the standard error of its mean, and per e the slope of ln t against ln L over the boxes that
# have one, with gg-fit crossing's verdict: "grows with x" (a box effect: the giant recedes as L grows),
# "independent of x" (intrinsic), "falls with x" or "undecided".
# IDS: the cells' ids, e-major (ES x LS, in that order). Prints fits rows fs_tg_L<L>, fs_twrap_L<L> (value
# t, stderr t x the error of ln t), fs_tg_slope, fs_twrap_slope; writes OUT.tsv with "e L t_g" per cell
# (nan where it is not reached or not measured) for the window ends of m(t).
# Environment: FIT, FS_WORK, FS_SIGMAS, FS_TOLERANCE.
set -euo pipefail
: "${FIT:?}" "${FS_WORK:?}" "${FS_SIGMAS:?}" "${FS_TOLERANCE:?}"
read -r -a es <<< "$1"; read -r -a ls <<< "$2"; read -r -a ids <<< "$3"; tg_out=$4
nl=${#ls[@]}
: > "$tg_out"
g() { awk -v x="$1" 'BEGIN { if (x ~ /nan|inf/ || x == "") print "nan"; else printf "%.4g", x }'; }
col() { "$FIT" table --no-header "$1:$2" | awk -F'\t' '{ print $NF }'; }   # a dataset, one value a line (after the time column table adds beside /crossing/time)
for i in "${!es[@]}"; do
  e=${es[i]}
  for what in tg:share twrap:wraps; do
    name=${what%%:*} file=${what#*:}
    case $name in
      tg) text="first time the largest cluster holds half of the clustered particles (ensemble mean of its share)" ;;
      *) text="first time the largest cluster wraps the box (geometric mean over runs)" ;;
    esac
    per_run=(); [ "$name" = tg ] || per_run=(--per-run)
    inputs=() sizes=() counts=()
    for j in "${!ls[@]}"; do
      f=$FS_WORK/${ids[i * nl + j]}/$file.h5
      [ -e "$f" ] && [ "$(cat "${f%.h5}.runs")" -ge 3 ] || { printf 'fs_%s_L%s\t%s\tnan\tnan\t-\t-\tfewer than 3 runs with the giant cluster'"'"'s data\n' "$name" "${ls[j]}" "$e"; continue; }
      inputs+=("$f:/average/mean") sizes+=("${ls[j]}") counts+=("$(cat "${f%.h5}.runs")")
    done
    [ "${#inputs[@]}" -gt 0 ] || continue
    out=$FS_WORK/crossing-$name-$e.h5
    xs=(); [ "${#inputs[@]}" -lt 2 ] || xs=(--x "${sizes[@]}")
    if ! "$FIT" --quiet crossing "${inputs[@]}" --level 0.5 "${xs[@]}" "${per_run[@]}" --sigmas "$FS_SIGMAS" \
           --tolerance "$FS_TOLERANCE" -o "$out" 2> "$out.err"; then
      why=$(sed 's/^gg-fit[a-z -]*: \(error: \)\{0,1\}//' "$out.err" | head -n 1)
      for L in "${sizes[@]}"; do printf 'fs_%s_L%s\t%s\tnan\tnan\t-\t-\t%s\n' "$name" "$L" "$e" "$why"; done
      continue
    fi
    paste <(col "$out" /crossing/time) <(col "$out" /crossing/log_time_stderr) <(col "$out" /crossing/log_time_dof) \
          <(col "$out" /crossing/runs_reaching) <(printf '%s\n' "${sizes[@]}") <(printf '%s\n' "${counts[@]}") |
      while IFS=$'\t' read -r t s dof k L n; do
        printf 'fs_%s_L%s\t%s\t%s\t%s\t-\t-\t%s; %d of %d runs reach it; error of ln t %s (%s dof)\n' "$name" "$L" "$e" \
          "$(g "$t")" "$(awk -v t="$t" -v s="$s" 'BEGIN { if (t ~ /nan/ || s ~ /nan/) print "nan"; else printf "%.3g", t * s }')" \
          "$text" "$k" "$n" "$(g "$s")" "$(g "$dof")"
        [ "$name" != tg ] || printf '%s\t%s\t%s\n' "$e" "$L" "$(g "$t")" >> "$tg_out"
      done
    if [ "${#xs[@]}" -gt 0 ]; then
      verdict=$(h5dump -a /crossing/verdict "$out" | sed -n 's/^ *(0): "\(.*\)"/\1/p')
      printf 'fs_%s_slope\t%s\t%s\t%s\t%s\t%s\td ln t / d ln L over L = %s (%s dof); %s sigma, flat within %s: %s\n' "$name" "$e" \
        "$(g "$(col "$out" /crossing/slope)")" "$(g "$(col "$out" /crossing/slope_stderr)")" "${sizes[0]}" "${sizes[-1]}" \
        "${sizes[*]}" "$(g "$(col "$out" /crossing/slope_dof)")" "$FS_SIGMAS" "$FS_TOLERANCE" "${verdict:-undecided}"
    fi
  done
done
