#!/bin/bash
# answer.sh PREFIX L "ES" "SERIES" "STARTS" "ENDS" ["ENERGIES"]   (called by fig8.sh)
# The answer to the paper's question at one box edge L, for one measure of the cluster size q(t) (the mean
# mass m of one cluster definition, the paper's length l or the correlation length l_C; its symbol in
# FS_QUANTITY, m unless set), in three computed statements, each with its interval (docs/PHYSICS.md
# "The answer"); below m stands for q:
#   (1) exponent: the late exponent of m(t) of each e over its last FS_LATE_DECADES before its end, whether
#       it has settled (against the window before), and whether it agrees with the first e's;
#   (2) amplitude at equal time (the paper's observation): m_e(t) / m_first(t) over the last
#       FS_LATE_DECADES before the earliest end of all e, against 1;
#   (3) time-shift universality: the factor c(e) with m_e(t) = m_first(t / c) over [start, end] of each e
#       (gg-fit shift), whether one master curve collapses all e within errors and whether c is a
#       constant; beside it the ratios of the Haff times (1 - e0^2)/(1 - e^2) and of the onset times;
#   and, given ENERGIES (gg-fit average outputs of E(t) of the same runs, in the same order), the paper's
#   closing question: m_e / m_first at equal energy (gg-fit at-equal), m read where each e's own E(t)
#   falls to levels every e's E passes inside its [start, end]; if it differs from 1, m as a function
#   of E does not collapse across e: cluster growth is not slaved to the energy decay.
# Every verdict is taken at the coverage of a normal's FS_SIGMAS sigma with Student's t of its
# jackknife's degrees of freedom (docs/PHYSICS.md "Calibration of the verdicts").
# SERIES: gg-fit average outputs of q(t), one per e (>= 3 runs each); STARTS, ENDS: per e, the part of
# q(t) past its onset and before finite size (for m also before the giant cluster forms). Prints fits rows (NAME E value stderr t1 t2 note) named
# PREFIX<quantity>_L<L>; the work files go to $FS_WORK/answer-PREFIX-L<L>/.
# Environment: FIT, FIGSRC, FS_WORK, FS_SIGMAS, FS_TOLERANCE, FS_LATE_DECADES, FS_QUANTITY.
set -euo pipefail
: "${FIT:?}" "${FIGSRC:?}" "${FS_WORK:?}" "${FS_SIGMAS:?}" "${FS_TOLERANCE:?}" "${FS_LATE_DECADES:?}"
q=${FS_QUANTITY:-m}
export FS_QUANTITY=$q
pre=$1 L=$2
read -r -a es <<< "$3"; read -r -a mass <<< "$4"; read -r -a t1 <<< "$5"; read -r -a t2 <<< "$6"
read -r -a energy <<< "${7:-}"
w=$FS_WORK/answer-${pre}L$L
mkdir -p "$w"
g() { awk -v x="$1" 'BEGIN { if (x ~ /nan|inf/) print "n/a"; else printf "%.4g", x }'; }
val() { "$FIT" table --no-header "$1:$2" | head -n 1 | cut -f1; }   # a scalar (or the first value)
attr() { h5dump -a "$2" "$1" | sed -n 's/^ *(0): "\(.*\)"/\1/p'; }

# (1) late exponents, each e over the last decades before its own end.
# A quantity that cannot be measured (a window too short, no common range) gets a row saying why.
why() { sed 's/^gg-fit[a-z -]*: \(error: \)\{0,1\}//' "$w/err" | head -n 1; }
zs=() zse=()
for i in "${!es[@]}"; do
  f=$w/late-${es[i]}.h5
  row=$("$FIGSRC/late-row.sh" "${pre}late_exponent_L$L" "${es[i]}" "${mass[i]}" "${t2[i]}" "$f")
  printf '%s\n' "$row"
  if [ "$(cut -f3 <<< "$row")" = nan ]; then zs+=(nan) zse+=(nan); else zs+=("$(val "$f" /late/exponent)") zse+=("$(val "$f" /late/exponent_stderr)"); fi
done
# Each against the first by Welch's test of the difference (gg-fit compare).
agree=yes
for i in "${!es[@]}"; do
  [ "$i" -gt 0 ] || continue
  f=$w/late-compare-${es[i]}.h5
  if [ "${zs[i]}" = nan ] || [ "${zs[0]}" = nan ] ||
     ! "$FIT" --quiet compare "$w/late-${es[0]}.h5:/late/exponent" "$w/late-${es[i]}.h5:/late/exponent" \
         --sigmas "$FS_SIGMAS" -o "$f" 2> "$w/err"; then
    d=nan ds=nan ok=n/a
  else
    read -r d ds a < <("$FIT" table --no-header "$f:/compare/difference" "$f:/compare/difference_stderr" "$f:/compare/agree" | tail -n 1)
    case $a in 1) ok=agree ;; 0) ok=differ ;; *) ok=n/a ;; esac
  fi
  how=$([ "$ok" = differ ] && echo "beyond" || echo "within")
  printf '%slate_exponent_difference_L%s\t%s\t%s\t%s\t-\t-\tz(%s) - z(%s): %s (%s %s sigma)\n' "$pre" "$L" "${es[i]}" \
    "$(g "$d")" "$(g "$ds")" "${es[i]}" "${es[0]}" "$ok" "$how" "$FS_SIGMAS"
  case $ok in differ) agree=no ;; n/a) [ "$agree" = no ] || agree=n/a ;; esac
done
printf '%sstatement_exponent_L%s\tall\t%s\tnan\t-\t-\tthe late exponents of every e agree with e = %s within %s sigma: %s\n' \
  "$pre" "$L" "$agree" "${es[0]}" "$FS_SIGMAS" "$agree"

# (2) m_e / m_first at equal times over the last decades before the earliest end.
end=$(printf '%s\n' "${t2[@]}" | sort -g | head -n 1)
start=$(awk -v t="$end" -v d="$FS_LATE_DECADES" 'BEGIN { printf "%.6g", t / 10^d }')
verdict=supported
for i in "${!es[@]}"; do
  [ "$i" -gt 0 ] || continue
  f=$w/ratio-${es[i]}.h5
  if ! "$FIT" --quiet ratio "${mass[0]}:/average/mean" "${mass[i]}:/average/mean" --window "$start" "$end" \
         --sigmas "$FS_SIGMAS" --tolerance "$FS_TOLERANCE" -o "$f" 2> "$w/err"; then
    printf '%sequal_time_ratio_L%s\t%s\tnan\tnan\t%s\t%s\t%s\n' "$pre" "$L" "${es[i]}" "$(g "$start")" "$(g "$end")" "$(why)"
    [ "$verdict" = rejected ] || verdict=n/a
    continue
  fi
  v=$(attr "$f" /ratio/verdict)
  printf '%sequal_time_ratio_L%s\t%s\t%s\t%s\t%s\t%s\t%s(%s)/%s(%s) at equal times; = 1: %s\n' "$pre" "$L" "${es[i]}" \
    "$(g "$(val "$f" /ratio/ratio)")" "$(g "$(val "$f" /ratio/ratio_stderr)")" "$(g "$start")" "$(g "$end")" \
    "$q" "${es[i]}" "$q" "${es[0]}" "$v"
  case $v in rejected) verdict=rejected ;; undecided) [ "$verdict" != supported ] || verdict=undecided ;; esac
done
printf '%sstatement_amplitude_L%s\tall\t%s\tnan\t%s\t%s\t%s(e)/%s(%s) = 1 at equal late times (%s sigma, within %s): %s\n' \
  "$pre" "$L" "$verdict" "$(g "$start")" "$(g "$end")" "$q" "$q" "${es[0]}" "$FS_SIGMAS" "$FS_TOLERANCE" "$verdict"
# m at equal energy: E levels every e's E(t) passes inside its [start, end] (3, log-spaced strictly inside).
if [ "${#energy[@]}" -eq "${#es[@]}" ]; then
  read -r elo ehi < <(for i in "${!es[@]}"; do
      "$FIT" table --no-header "${energy[i]}:/average/mean" |
        awk -v a="${t1[i]}" -v b="${t2[i]}" '$1 >= a && hi == "" { hi = $2 } $1 <= b { lo = $2 } END { print lo + 0, hi + 0 }'
    done | awk 'NR == 1 || $1 > lo { lo = $1 } NR == 1 || $2 < hi { hi = $2 } END { print lo, hi }')
  levels=$(awk -v lo="$elo" -v hi="$ehi" 'BEGIN { if (lo > 0 && hi > lo) for (k = 0; k < 3; ++k) printf "%.4g ", lo * (hi / lo)^((k + 0.5) / 3) }')
  pairs=()
  for i in "${!es[@]}"; do pairs+=("${energy[i]}:/average/mean" "${mass[i]}:/average/mean"); done
  f=$w/equal-energy.h5
  answer=n/a
  if [ -z "$levels" ]; then
    printf '%sstatement_energy_L%s	all	n/a	nan	-	-	the energies of the e share no range inside their windows\n' "$pre" "$L"
  elif read -r -a lv <<< "$levels" &&
       ! "$FIT" --quiet at-equal "${pairs[@]}" --at "${lv[@]}" --sigmas "$FS_SIGMAS" --tolerance "$FS_TOLERANCE" -o "$f" 2> "$w/err"; then
    printf '%sstatement_energy_L%s	all	n/a	nan	-	-	%s\n' "$pre" "$L" "$(why)"
  else
    answer=supported
    verdicts=$(attr "$f" /at_equal/verdicts)
    read -r -a r < <("$FIT" table --no-header "$f:/at_equal/mean_ratio" | paste -sd ' ')
    read -r -a rs < <("$FIT" table --no-header "$f:/at_equal/mean_ratio_stderr" | paste -sd ' ')
    for i in "${!es[@]}"; do
      [ "$i" -gt 0 ] || continue
      v=$(awk -F'", "' -v k=$((i + 1)) '{ print $k }' <<< "$verdicts")
      printf '%sequal_energy_ratio_L%s\t%s\t%s\t%s\t%s\t%s\t%s(%s)/%s(%s) at equal E, over E in [%s, %s] (levels %s; the 5th and 6th columns are E); = 1: %s\n' \
        "$pre" "$L" "${es[i]}" "$(g "${r[i]}")" "$(g "${rs[i]}")" "$(g "$elo")" "$(g "$ehi")" "$q" "${es[i]}" "$q" "${es[0]}" \
        "$(g "$elo")" "$(g "$ehi")" "${levels% }" "$v"
      case $v in rejected) answer=rejected ;; undecided) [ "$answer" != supported ] || answer=undecided ;; esac
    done
    case $answer in
      rejected) text="no: $q(e)/$q(${es[0]}) = 1 at equal energy is rejected" ;;
      supported) text="yes: $q(e)/$q(${es[0]}) = 1 within $FS_TOLERANCE at equal energy" ;;
      *) text="undecided: $q(e)/$q(${es[0]}) at equal energy is neither excluded from 1 nor within $FS_TOLERANCE of it" ;;
    esac
    printf '%sstatement_energy_L%s\tall\t%s\tnan\t%s\t%s\t%s as a function of E collapses across e (%s sigma): %s\n' \
      "$pre" "$L" "${text%%:*}" "$(g "$elo")" "$(g "$ehi")" "$q" "$FS_SIGMAS" "$text"
  fi
fi

# (3) time shift against the first e.
inputs=() windows=()
for i in "${!es[@]}"; do inputs+=("${mass[i]}:/average/mean"); windows+=(--window "${t1[i]}" "${t2[i]}"); done
f=$w/shift.h5
if "$FIT" --quiet shift "${inputs[@]}" "${windows[@]}" --sigmas "$FS_SIGMAS" -o "$f" 2> "$w/err"; then
  "$FIT" table --no-header "$f:/shift/factor" "$f:/shift/factor_stderr" "$f:/shift/chi2_per_point" \
    "$f:/shift/collapses" "$f:/shift/lag/drift" "$f:/shift/lag/drift_stderr" "$f:/shift/lag/constant" \
    "$f:/shift/lag/curvature" "$f:/shift/lag/curvature_stderr" |
    awk -F'\t' -v OFS='\t' -v pre="$pre" -v L="$L" -v es="${es[*]}" -v a="${t1[*]}" -v b="${t2[*]}" -v q="$q" '
      function num(x, f) { return x ~ /nan|inf/ ? "n/a" : sprintf(f, x) }
      BEGIN { split(es, e, " "); split(a, t1, " "); split(b, t2, " ") }
      NR > 1 {
        print pre "shift_factor_L" L, e[NR], sprintf("%.4g", $1), sprintf("%.3g", $2), t1[NR], t2[NR],
              sprintf("%s_e(t) = %s_%s(t / c); chi2 per point %s; lag drift d ln lag / d ln %s = %s +- %s (%s); lag curvature %s +- %s (%s)",
                      q, q, e[1], num($3, "%.3g"), q, num($5, "%.3g"), num($6, "%.2g"),
                      $7 == 1 ? "constant" : $7 == 0 ? "drifts" : "undetermined", num($8, "%.3g"), num($9, "%.2g"),
                      $4 == 1 ? "collapses" : "does not collapse")
        ok = ok && $4 == 1; if ($7 == 0) con = "no"; else if ($7 != 1 && con == "yes") con = "undetermined"
      }
      NR == 1 { ok = 1; con = "yes" }
      END { print pre "statement_shift_L" L, "all", ok ? "yes" : "no", "nan", "-", "-",
                  "one master curve " q "(t / c(e)) collapses every e within errors: " (ok ? "yes" : "no") \
                  "; c(e) constant over the range of " q ": " con }'
else
  rm -f "$f"
  printf '%sstatement_shift_L%s\tall\tn/a\tnan\t-\t-\t%s\n' "$pre" "$L" "$(why)"
fi
# The time ratios c(e) is compared with: of the Haff times, and of the onset of growth (plateau).
for i in "${!es[@]}"; do
  [ "$i" -gt 0 ] || continue
  printf '%shaff_time_ratio_L%s\t%s\t%s\tnan\t-\t-\t(1 - %s^2) / (1 - %s^2): t_0(e)/t_0(%s) of Haff'"'"'s law\n' "$pre" "$L" \
    "${es[i]}" "$(awk -v a="${es[0]}" -v b="${es[i]}" 'BEGIN { printf "%.4g", (1 - a * a) / (1 - b * b) }')" "${es[0]}" "${es[i]}" "${es[0]}"
done
# (Onsets only where m(t) starts at t = 0: a curve cut at --from has no plateau.)
for i in "${!es[@]}"; do
  [ "$pre" = fs_ ] || break
  "$FIT" --quiet onset "${mass[i]}:/average/mean" --asymptote 0.6 -o "$w/onset-${es[i]}.h5" 2> /dev/null || true
done
for i in "${!es[@]}"; do
  [ "$pre" = fs_ ] || break
  [ "$i" -gt 0 ] || continue
  a=$(val "$w/onset-${es[0]}.h5" /onset/plateau_time 2> /dev/null || echo nan)
  b=$(val "$w/onset-${es[i]}.h5" /onset/plateau_time 2> /dev/null || echo nan)
  printf '%sonset_time_ratio_L%s\t%s\t%s\tnan\t-\t-\tt_onset(%s)/t_onset(%s), m leaving its plateau (gg-fit onset)\n' "$pre" "$L" \
    "${es[i]}" "$(awk -v a="$a" -v b="$b" 'BEGIN { if (a + 0 > 0 && b == b + 0) printf "%.4g", b / a; else print "nan" }')" "${es[i]}" "${es[0]}"
done
