#!/bin/bash
# answer.sh PREFIX L "ES" "MASSES" "STARTS" "ENDS" ["ENERGIES"]   (called by fig8.sh)
# The answer to the paper's question at one box edge L, for one cluster definition, in three computed
# statements, each with its interval (docs/PHYSICS.md "The answer"):
#   (1) exponent: the late exponent of m(t) of each e over its last FS_LATE_DECADES before its end, whether
#       it has settled (against the window before), and whether it agrees with the first e's;
#   (2) amplitude at equal time (the paper's observation): m_e(t) / m_first(t) over the last
#       FS_LATE_DECADES before the earliest end of all e, against 1;
#   (3) time-shift universality: the factor c(e) with m_e(t) = m_first(t / c) over [start, end] of each e
#       (gg-fit shift), whether one master curve collapses all e within errors and whether c is a
#       constant; beside it the ratios of the Haff times (1 - e0^2)/(1 - e^2) and of the onset times;
#   and, given ENERGIES (gg-fit average outputs of E(t)), the paper's closing remark: E_e / E_first over
#   the window of (2). Where E agrees (within the tolerance) and m does not, m as a function of E does
#   not collapse across e: cluster growth is not slaved to the energy decay.
# MASSES: gg-fit average outputs of m(t), one per e (>= 3 runs each); STARTS, ENDS: per e, the part of
# m(t) past its onset and before finite size. Prints fits rows (NAME E value stderr t1 t2 note) named
# PREFIX<quantity>_L<L>; the work files go to $FS_WORK/answer-PREFIX-L<L>/.
# Environment: FIT, FIGSRC, FS_WORK, FS_SIGMAS, FS_TOLERANCE, FS_LATE_DECADES.
set -euo pipefail
: "${FIT:?}" "${FIGSRC:?}" "${FS_WORK:?}" "${FS_SIGMAS:?}" "${FS_TOLERANCE:?}" "${FS_LATE_DECADES:?}"
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
agree=yes
for i in "${!es[@]}"; do
  [ "$i" -gt 0 ] || continue
  read -r d ds ok < <(awk -v a="${zs[i]}" -v sa="${zse[i]}" -v b="${zs[0]}" -v sb="${zse[0]}" -v k="$FS_SIGMAS" \
    'BEGIN { if (a == "nan" || b == "nan") { print "nan nan n/a"; exit }
             d = a - b; s = sqrt(sa * sa + sb * sb); print d, s, (d < 0 ? -d : d) <= k * s ? "agree" : "differ" }')
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
  printf '%sequal_time_ratio_L%s\t%s\t%s\t%s\t%s\t%s\tm(%s)/m(%s) at equal times; = 1: %s\n' "$pre" "$L" "${es[i]}" \
    "$(g "$(val "$f" /ratio/ratio)")" "$(g "$(val "$f" /ratio/ratio_stderr)")" "$(g "$start")" "$(g "$end")" \
    "${es[i]}" "${es[0]}" "$v"
  case $v in rejected) verdict=rejected ;; undecided) [ "$verdict" != supported ] || verdict=undecided ;; esac
done
printf '%sstatement_amplitude_L%s\tall\t%s\tnan\t%s\t%s\tm(e)/m(%s) = 1 at equal late times (%s sigma, within %s): %s\n' \
  "$pre" "$L" "$verdict" "$(g "$start")" "$(g "$end")" "${es[0]}" "$FS_SIGMAS" "$FS_TOLERANCE" "$verdict"
# The energies over the same window: m(E) collapses across e only if m agrees wherever E does.
if [ "${#energy[@]}" -eq "${#es[@]}" ]; then
  e_same=yes
  for i in "${!es[@]}"; do
    [ "$i" -gt 0 ] || continue
    f=$w/energy-ratio-${es[i]}.h5
    if "$FIT" --quiet ratio "${energy[0]}:/average/mean" "${energy[i]}:/average/mean" --window "$start" "$end" \
         --sigmas "$FS_SIGMAS" --tolerance "$FS_TOLERANCE" -o "$f" 2> "$w/err"; then
      v=$(attr "$f" /ratio/verdict)
      printf '%senergy_ratio_L%s\t%s\t%s\t%s\t%s\t%s\tE(%s)/E(%s) at equal times; = 1: %s\n' "$pre" "$L" "${es[i]}" \
        "$(g "$(val "$f" /ratio/ratio)")" "$(g "$(val "$f" /ratio/ratio_stderr)")" "$(g "$start")" "$(g "$end")" "${es[i]}" "${es[0]}" "$v"
    else
      v=n/a
      printf '%senergy_ratio_L%s\t%s\tnan\tnan\t%s\t%s\t%s\n' "$pre" "$L" "${es[i]}" "$(g "$start")" "$(g "$end")" "$(why)"
    fi
    [ "$v" = supported ] || e_same=no
  done
  if [ "$e_same" = yes ] && [ "$verdict" = rejected ]; then
    answer="no: E(e)/E(${es[0]}) = 1 within $FS_TOLERANCE there while m(e)/m(${es[0]}) = 1 is rejected"
  elif [ "$e_same" = yes ] && [ "$verdict" = supported ]; then
    answer="yes: both E and m agree across e there"
  else
    answer="undecided: E(e)/E(${es[0]}) = 1 is not supported over that window"
  fi
  printf '%sstatement_energy_L%s\tall\t%s\tnan\t%s\t%s\tm as a function of E collapses across e at late times: %s\n' \
    "$pre" "$L" "${answer%%:*}" "$(g "$start")" "$(g "$end")" "$answer"
fi

# (3) time shift against the first e.
inputs=() windows=()
for i in "${!es[@]}"; do inputs+=("${mass[i]}:/average/mean"); windows+=(--window "${t1[i]}" "${t2[i]}"); done
f=$w/shift.h5
if "$FIT" --quiet shift "${inputs[@]}" "${windows[@]}" --sigmas "$FS_SIGMAS" -o "$f" 2> "$w/err"; then
  "$FIT" table --no-header "$f:/shift/factor" "$f:/shift/factor_stderr" "$f:/shift/chi2_per_point" \
    "$f:/shift/collapses" "$f:/shift/lag/drift" "$f:/shift/lag/drift_stderr" "$f:/shift/lag/constant" |
    awk -F'\t' -v OFS='\t' -v pre="$pre" -v L="$L" -v es="${es[*]}" -v a="${t1[*]}" -v b="${t2[*]}" '
      function num(x, f) { return x ~ /nan|inf/ ? "n/a" : sprintf(f, x) }
      BEGIN { split(es, e, " "); split(a, t1, " "); split(b, t2, " ") }
      NR > 1 {
        print pre "shift_factor_L" L, e[NR], sprintf("%.4g", $1), sprintf("%.3g", $2), t1[NR], t2[NR],
              sprintf("m_e(t) = m_%s(t / c); chi2 per point %s (%s); lag drift d ln lag / d ln m = %s +- %s (%s)",
                      e[1], num($3, "%.3g"), $4 == 1 ? "collapses" : "does not collapse", num($5, "%.3g"), num($6, "%.2g"),
                      $7 == 1 ? "constant" : $7 == 0 ? "drifts" : "undetermined")
        ok = ok && $4 == 1; if ($7 == 0) con = "no"; else if ($7 != 1 && con == "yes") con = "undetermined"
      }
      NR == 1 { ok = 1; con = "yes" }
      END { print pre "statement_shift_L" L, "all", ok ? "yes" : "no", "nan", "-", "-",
                  "one master curve m(t / c(e)) collapses every e within errors: " (ok ? "yes" : "no") \
                  "; c(e) constant over the range of m: " con }'
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
