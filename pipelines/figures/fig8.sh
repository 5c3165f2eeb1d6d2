#!/bin/bash
# fig8.sh "ES" "LS" "PLAN"   (called by pipelines/finite-size/finite-size.mk)
# Fig. 8, the finite-size study: per box edge L and e, the ensemble m(t), its local exponent and E(t)
# from the per-run results in $FS_RESULTS/<id>/run<k>.h5 (collect.sh), with the ensembles of the paper's
# length l(t) (/domains/length), the correlation length l_C(t) and the giant cluster's share and wrapping;
# when the giant cluster forms, t_g(e, L), and whether it grows with L (giant.sh); per L with every e
# measured, the three statements of answer.sh (late exponents, ratio at equal times, time-shift collapse,
# and at equal energy) for l(t) and l_C(t) up to their own onset of finite size and for m(t) up to
# min(t_fs, t_g, t_max) (past t_g one cluster holds most particles and m counts the fragments left,
# docs/PHYSICS.md "The answer in lengths"), the same for m at FS_DEF_L for every other cluster definition in
# FS_DEF_DIRS, and the headline verdict fs_verdict drawn from them; beside them, per L, the amplitude
# ratios A(e)/A(0.5) of m at a common exponent (gg-fit collapse) and their extrapolation in 1/L (gg-fit
# extrapolate), a model fit kept as fs_amplitude_fit_verdict.
# PLAN: every cell as e:L:t_max:runs:id (id: its folder under FS_RESULTS).
# Environment: FIT FIGSRC OUT SCALE ERRORS GNUPLOT (lib.sh), FS_RESULTS, FS_WORK (scratch for the
# averages and fits, remade every time), FS_TFS_FROM, FS_CONSEC, FS_AMP_T1, FS_ZETA_T1 (one per e), FS_SIGMAS,
# FS_TOLERANCE, FS_DIR, FS_LATE_DECADES, FS_STEP_FROM (count-steps.sh), FS_DEF_L, FS_DEF_DIRS (the other
# definitions' results folders) and FS_LONG (longer runs beside a cell, e:L:t_max:runs:id each; finite-size.mk).
# Finite size sets in (t_fs, pass 2 below) when a quantity (m, l or l_C, each on its own) leaves the curve
# of the next larger box; every fit of it in a cell ends at min(t_fs, t_max), for m also at t_g. A cell
# with fewer than 3 runs is drawn but not fitted (the jackknife over runs needs 3); a result without the
# lengths (an older one) counts for m only.
# Writes $OUT/fig8.tsv, $OUT/fig8.fits.tsv (rows named fs_*, read by summary.sh) and $OUT/fig8.{png,svg}.
set -euo pipefail
: "${FIT:?}" "${OUT:?}" "${FIGSRC:?}" "${FS_RESULTS:?}" "${FS_WORK:?}" "${FS_DIR:?}"
: "${FS_TFS_FROM:?}" "${FS_STEP_FROM:?}" "${FS_CONSEC:?}" "${FS_MIN_DEV:?}" "${FS_AMP_T1:?}" "${FS_ZETA_T1:?}" "${FS_SIGMAS:?}" "${FS_TOLERANCE:?}"
. "$FIGSRC/lib.sh"
read -r -a es <<< "$1"; read -r -a ls <<< "$2"; read -r -a plan <<< "$3"
read -r -a zeta_t1 <<< "$FS_ZETA_T1"
declare -A tmx nreq cid   # per cell e,L: t_max, the runs planned and its id
for c in "${plan[@]}"; do IFS=: read -r e L T R I <<< "$c"; tmx[$e,$L]=$T nreq[$e,$L]=$R cid[$e,$L]=$I; done
errors=${ERRORS:-jackknife}
mkdir -p "$OUT" "$FS_WORK"
rm -rf "${FS_WORK:?}"/*
fits=$OUT/fig8.fits.tsv.tmp
: > "$FS_WORK/blocks.m"; : > "$FS_WORK/blocks.z"; : > "$FS_WORK/blocks.E"; : > "$FS_WORK/blocks.r"
: > "$FS_WORK/blocks.c"; : > "$FS_WORK/blocks.g"; : > "$FS_WORK/blocks.l"; : > "$FS_WORK/blocks.s"
mlab=() zlab=() rlab=() clab=() glab=() llab=() slab=()

# add_block GROUP LABEL CMD [ARG ...]: a data block appended to $FS_WORK/blocks.GROUP (lib.sh's block,
# one group of blocks at a time; the groups are joined in a fixed order at the end).
add_block() {
  local f=$FS_WORK/blocks.$1
  gg_blocks=0; [ ! -s "$f" ] || gg_blocks=1
  block "${@:2}" >> "$f"
}

# info FILE KEY: a value of a result's .info (collect.sh).
info() { awk -F'\t' -v k="$2" '$1 == k { print $2; exit }' "${1%.h5}.info"; }
# fit window end: t_fs if defined, else t_max; "ok" when the window [t1, end] spans a factor >= 2.
wmin() { awk -v a="$1" -v b="$2" 'BEGIN { if (a == "nan") print b; else if (b == "nan") print a; else print (a + 0 < b + 0 ? a : b) }'; }
spans() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(b != "nan" && b + 0 >= 2 * a) }'; }

{
  printf '# Fig. 8 fits (SCALE=%s; finite-size study; errors: %s over runs).' "${SCALE:-?}" "$errors"
  printf ' Columns: quantity e value stderr t1 t2 note\n'
} > "$fits"

# Each quantity read by the statements: its symbol, file of the ensemble average, dataset and row prefix.
qs=(m l lC)
declare -A qsym=([m]=m [l]=l [lC]=l_C) qfile=([m]=mass [l]=length [lC]=lengthC) \
  qds=([m]=/cluster/mean_mass [l]=/domains/length [lC]=/correlation/length) qpre=([m]=fs_ [l]=fs_l_ [lC]=fs_lC_)
# average_runs DATASET OUT RUN...: the ensemble average of DATASET over the runs that hold it (a result
# made before the lengths were kept has none), its number of runs in OUT's .runs; no OUT below 2 runs.
average_runs() {
  local ds=$1 out=$2 r have=(); shift 2
  for r in "$@"; do ! h5ls "$r$ds" > /dev/null 2>&1 || have+=("$r"); done
  echo "${#have[@]}" > "${out%.h5}.runs"
  [ "${#have[@]}" -ge 2 ] || return 0
  "$FIT" --quiet average --dataset "$ds" "${have[@]}" -o "$out" 2> /dev/null
}
# runs_of Q E L: the runs behind a cell's average of quantity Q.
runs_of() { cat "$FS_WORK/${cid[$2,$3]}/${qfile[$1]}.runs" 2> /dev/null || echo 0; }

# Pass 1, per cell: completeness, CPU, and the ensemble averages of m(t), l(t), l_C(t), the largest
# cluster's share and wrapping, and E(t).
cpu_total=0
declare -A nruns tfs tend
for L in "${ls[@]}"; do
  for i in "${!es[@]}"; do
    e=${es[i]} T=${tmx[${es[i]},$L]} nrun=${nreq[${es[i]},$L]}
    id=${cid[$e,$L]}
    mapfile -t runs < <(ls "$FS_RESULTS/$id"/run*.h5 2> /dev/null | sort -V || true)
    n=${#runs[@]}
    nruns[$e,$L]=$n
    cpu=0
    for r in "${runs[@]}"; do cpu=$(awk -v a="$cpu" -v b="$(info "$r" cpu_seconds)" 'BEGIN { print a + (b == "nan" ? 0 : b) }'); done
    cpu_total=$(awk -v a="$cpu_total" -v b="$cpu" 'BEGIN { print a + b }')
    state=complete; [ "$n" -ge "$nrun" ] || state="$((nrun - n)) of $nrun runs missing"
    printf 'fs_runs_L%s\t%s\t%d\tnan\t-\t%s\t%s; %.2f CPU h of simulation\n' "$L" "$e" "$n" "$T" "$state" \
      "$(awk -v c="$cpu" 'BEGIN { print c / 3600 }')" >> "$fits"
    [ "$n" -ge 2 ] || continue  # an ensemble average needs two runs
    w=$FS_WORK/$id; mkdir -p "$w"
    "$FIT" --quiet average --dataset /observables/kinetic_energy/value "${runs[@]}" -o "$w/energy.h5" 2> /dev/null
    for q in "${qs[@]}"; do average_runs "${qds[$q]}" "$w/${qfile[$q]}.h5" "${runs[@]}"; done
    average_runs /cluster/largest_share_of_clustered "$w/share.h5" "${runs[@]}"
    average_runs /cluster/largest_wraps "$w/wraps.h5" "${runs[@]}"
    # A step in the cluster count that the runs share, and whether resuming made it (count-steps.sh).
    if awk -v T="$T" -v f="$FS_STEP_FROM" 'BEGIN { exit !(T + 0 > f + 0) }'; then
      "$FIGSRC/count-steps.sh" "$L" "$e" "${runs[@]}" >> "$fits"
    fi
    printf 'fs_lengths_runs_L%s\t%s\t%d\tnan\t-\t-\truns that hold l(t) and l_C(t) (a result made before they were kept has neither)\n' \
      "$L" "$e" "$(( $(runs_of l "$e" "$L") < $(runs_of lC "$e" "$L") ? $(runs_of l "$e" "$L") : $(runs_of lC "$e" "$L") ))" >> "$fits"
  done
done

# When the giant cluster forms, t_g(e, L), and the first wrapping (giant.sh).
ids=()
for e in "${es[@]}"; do for L in "${ls[@]}"; do ids+=("${cid[$e,$L]}"); done; done
"$FIGSRC/giant.sh" "${es[*]}" "${ls[*]}" "${ids[*]}" "$FS_WORK/tg.tsv" >> "$fits"
declare -A tg
while IFS=$'\t' read -r e L t; do tg[$e,$L]=$t; done < "$FS_WORK/tg.tsv"

# Pass 2, the onset of finite size t_fs(e, L) of each quantity q (m, l, l_C): the first snapshot time at
# which q(t) in this box differs from q(t) in the next larger box by more than FS_SIGMAS combined standard
# errors, at FS_CONSEC consecutive snapshots from t = FS_TFS_FROM on (both ensembles of >= 3 runs): a
# length feels the box before a mass does. The largest box has no larger one: its t_fs is extrapolated
# as a power of L from the two boxes below it when both have one (t_fs ~ L^kappa), else not determined
# and its fits run to t_max.
deviates() {  # MASS_SMALL MASS_LARGE -> first time of deviation, or nan
  # The two boxes' samples at the times both have (a longer run has more of them).
  local small=$FS_WORK/deviates.small large=$FS_WORK/deviates.large
  if ! "$FIT" table --no-header "$1:/average/mean" "$1:/average/stderr" > "$small" 2> /dev/null ||
     ! "$FIT" table --no-header "$2:/average/mean" "$2:/average/stderr" > "$large" 2> /dev/null; then
    echo nan
    return
  fi
  awk -F'\t' -v OFS='\t' 'NR == FNR { m[$1] = $2; s[$1] = $3; next } $1 in m { print $1, m[$1], s[$1], $2, $3 }' \
      "$small" "$large" |
    awk -F'\t' -v k="$FS_SIGMAS" -v from="$FS_TFS_FROM" -v need="$FS_CONSEC" -v rel="$FS_MIN_DEV" '
      $1 + 0 < from || $2 <= 0 || $4 <= 0 { next }
      { d = log($2 / $4); if (d < 0) d = -d; s = sqrt(($3 / $2)^2 + ($5 / $4)^2)
        if (d > k * s && d > log(1 + rel)) { if (++run == 1) t = $1; if (run >= need) { print t; found = 1; exit } } else run = 0 }
      END { if (!found) print "nan" }'
}
for q in "${qs[@]}"; do
  for i in "${!es[@]}"; do
    e=${es[i]}
    for j in "${!ls[@]}"; do
      L=${ls[j]} next=${ls[j + 1]:-}
      tfs[$q,$e,$L]=nan
      [ -n "$next" ] && [ "$(runs_of "$q" "$e" "$L")" -ge 3 ] && [ "$(runs_of "$q" "$e" "$next")" -ge 3 ] || continue
      tfs[$q,$e,$L]=$(deviates "$FS_WORK/${cid[$e,$L]}/${qfile[$q]}.h5" "$FS_WORK/${cid[$e,$next]}/${qfile[$q]}.h5")
    done
    nl=${#ls[@]}
    how="${qsym[$q]}(t) differs from the next larger box (L = %s) by > ${FS_SIGMAS} sigma at ${FS_CONSEC} snapshots in a row"
    for j in "${!ls[@]}"; do
      L=${ls[j]}
      if [ "$j" -lt $((nl - 1)) ]; then
        # shellcheck disable=SC2059  # the format is ours
        note=$(printf "$how" "${ls[j + 1]}")
        if [ "${tfs[$q,$e,$L]}" = nan ]; then
          note="$note: not seen up to t_max (or fewer than 3 runs in either box)"
          # A larger box that stops earlier vouches only for its own range.
          ! awk -v a="${tmx[$e,${ls[j + 1]}]}" -v b="${tmx[$e,$L]}" 'BEGIN { exit !(a + 0 < b + 0) }' ||
            note="$note; checked only up to t = ${tmx[$e,${ls[j + 1]}]}, the larger box's t_max"
        fi
      elif [ "$nl" -ge 3 ] && [ "${tfs[$q,$e,${ls[nl - 2]}]}" != nan ] && [ "${tfs[$q,$e,${ls[nl - 3]}]}" != nan ]; then
        tfs[$q,$e,$L]=$(awk -v a="${tfs[$q,$e,${ls[nl - 3]}]}" -v b="${tfs[$q,$e,${ls[nl - 2]}]}" -v La="${ls[nl - 3]}" \
                         -v Lb="${ls[nl - 2]}" -v L="$L" 'BEGIN { k = log(b / a) / log(Lb / La); printf "%.4g", b * (L / Lb)^k }')
        note="largest box: extrapolated as t_fs ~ L^kappa from L = ${ls[nl - 3]} and ${ls[nl - 2]}"
      else
        note="largest box: no larger box to compare with; fits run to t_max"
      fi
      printf '%sonset_L%s\t%s\t%s\tnan\t-\t-\t%s\n' "${qpre[$q]}" "$L" "$e" "${tfs[$q,$e,$L]}" "$note" >> "$fits"
      tend[$q,$e,$L]=$(wmin "${tfs[$q,$e,$L]}" "${tmx[$e,$L]}")
      # m only up to the giant cluster's forming (t_g): past it m counts the fragments beside the giant.
      [ "$q" != m ] || tend[$q,$e,$L]=$(wmin "${tg[$e,$L]:-nan}" "${tend[$q,$e,$L]}")
    done
  done
done

# Longer runs beside a cell (FS_LONG): their late exponent, and the onset of finite size of the next
# smaller box against them past the cell's own t_max (two runs give the standard errors of the onset
# test; the late exponent's jackknife needs three, and with two its row says so).
for c in ${FS_LONG:-}; do
  IFS=: read -r e L T R id <<< "$c"
  mapfile -t runs < <(ls "$FS_RESULTS/$id"/run*.h5 2> /dev/null | sort -V || true)
  n=${#runs[@]} cpu=0
  for r in "${runs[@]}"; do cpu=$(awk -v a="$cpu" -v b="$(info "$r" cpu_seconds)" 'BEGIN { print a + (b == "nan" ? 0 : b) }'); done
  cpu_total=$(awk -v a="$cpu_total" -v b="$cpu" 'BEGIN { print a + b }')
  state=complete; [ "$n" -ge "$R" ] || state="$((R - n)) of $R runs missing"
  printf 'fs_long_runs_L%s\t%s\t%d\tnan\t-\t%s\t%s; %.2f CPU h of simulation\n' "$L" "$e" "$n" "$T" "$state" \
    "$(awk -v c="$cpu" 'BEGIN { print c / 3600 }')" >> "$fits"
  [ "$n" -ge 2 ] || continue
  w=$FS_WORK/$id; mkdir -p "$w"
  "$FIT" --quiet average --dataset /cluster/mean_mass "${runs[@]}" -o "$w/mass.h5" 2> /dev/null
  "$FIGSRC/late-row.sh" "fs_long_late_exponent_L$L" "$e" "$w/mass.h5" "$T" "$w/late.h5" >> "$fits"
  for j in "${!ls[@]}"; do
    [ "${ls[j + 1]:-}" = "$L" ] || continue
    small=${ls[j]}
    [ "${nruns[$e,$small]}" -ge 3 ] || continue
    t=$(deviates "$FS_WORK/${cid[$e,$small]}/mass.h5" "$w/mass.h5")
    printf 'fs_long_onset_L%s\t%s\t%s\tnan\t-\t%s\tm(t) differs from the %d longer runs at L = %s (to t = %s) by > %s sigma at %s snapshots in a row%s\n' \
      "$small" "$e" "$t" "$(wmin "${tmx[$e,$small]}" "$T")" "$n" "$L" "$T" "$FS_SIGMAS" "$FS_CONSEC" \
      "$([ "$t" != nan ] || echo ": not seen")" >> "$fits"
  done
done

# Pass 3, per cell: plotted blocks, local exponent and the m(t) power law up to min(t_fs, t_max).
for L in "${ls[@]}"; do
  fitted=()
  for i in "${!es[@]}"; do
    e=${es[i]} n=${nruns[${es[i]},$L]} w=$FS_WORK/${cid[${es[i]},$L]}
    [ "$n" -ge 2 ] || continue  # an ensemble average needs two runs
    label="e = $e, L = $L ($n runs)"
    add_block m "m(t), $label: time m stderr" "$FIT" table "$w/mass.h5:/average/mean" "$w/mass.h5:/average/stderr"
    add_block E "E(t), $label: time E stderr" "$FIT" table "$w/energy.h5:/average/mean" "$w/energy.h5:/average/stderr"
    mlab+=("$i:$L")
    if [ -e "$w/length.h5" ]; then
      add_block l "l(t), $label: time l stderr" "$FIT" table "$w/length.h5:/average/mean" "$w/length.h5:/average/stderr"
      llab+=("$i:$L")
    fi
    if [ -e "$w/share.h5" ]; then
      add_block s "largest cluster's share of the clustered particles, $label: time share stderr" "$FIT" table \
        "$w/share.h5:/average/mean" "$w/share.h5:/average/stderr"
      slab+=("$i:$L")
    fi
    end=${tend[m,$e,$L]}
    if [ "$n" -ge 3 ]; then
      "$FIT" --quiet local-exponent --errors "$errors" "$w/mass.h5:/average/mean" -o "$w/local.h5" 2> /dev/null
      add_block z "local exponent d ln m / d ln t, $label: time z stderr" "$FIT" table \
        "$w/local.h5:/local_exponent/exponent" "$w/local.h5:/local_exponent/stderr"
      zlab+=("$i:$L")
      t1=${zeta_t1[i]}
      if spans "$t1" "$end"; then
        "$FIT" --quiet power-law --errors "$errors" "$w/mass.h5:/average/mean" --window "$t1" "$end" -o "$w/zeta.h5" 2> /dev/null
        "$FIGSRC/fitrow.sh" "fs_zeta_L$L" "$e" "$w/zeta.h5" /fit/exponent /fit/exponent_stderr 1 "$t1" "$end" \
          "m = A t^zeta of the ensemble mean, up to min(t_fs, t_g, t_max)" >> "$fits"
      else
        printf 'fs_zeta_L%s\t%s\tnan\tnan\t%s\t%s\tfinite size sets in before the window could span a factor 2\n' \
          "$L" "$e" "$t1" "$end" >> "$fits"
      fi
      fitted+=("$e")
    fi
  done
  # Amplitude ratios at this L: all e fitted, over [FS_AMP_T1, the earliest window end of the e].
  if [ "${#fitted[@]}" -eq "${#es[@]}" ]; then
    t2=nan
    for e in "${es[@]}"; do t2=$(wmin "${tend[m,$e,$L]}" "$t2"); done
    if spans "$FS_AMP_T1" "$t2"; then
      inputs=()
      for i in "${!es[@]}"; do inputs+=("$FS_WORK/${cid[${es[i]},$L]}/mass.h5:/average/mean"); done
      "$FIT" --quiet collapse --errors "$errors" "${inputs[@]}" --window "$FS_AMP_T1" "$t2" \
        -o "$FS_WORK/collapse-L$L.h5" 2> /dev/null
      "$FIT" table --no-header "$FS_WORK/collapse-L$L.h5:/fit/amplitude_ratio" \
                               "$FS_WORK/collapse-L$L.h5:/fit/amplitude_ratio_stderr" |
        awk -F'\t' -v OFS='\t' -v L="$L" -v es="${es[*]}" -v t1="$FS_AMP_T1" -v t2="$t2" '
          BEGIN { split(es, e, " ") }
          NR > 1 { print "fs_amplitude_ratio_L" L, e[NR], sprintf("%.4g", $1), sprintf("%.3g", $2), t1, t2,
                         "A(e)/A(" e[1] ") at one common exponent (gg-fit collapse)" }' >> "$fits"
      "$FIGSRC/fitrow.sh" "fs_collapse_exponent_L$L" all "$FS_WORK/collapse-L$L.h5" /fit/exponent /fit/exponent_stderr 1 \
        "$FS_AMP_T1" "$t2" "common exponent of the amplitude fit" >> "$fits"
    fi
    # The three statements at this L, without a common exponent (answer.sh).
    masses=() ends=() energies=()
    for i in "${!es[@]}"; do
      masses+=("$FS_WORK/${cid[${es[i]},$L]}/mass.h5"); ends+=("${tend[m,${es[i]},$L]}")
      energies+=("$FS_WORK/${cid[${es[i]},$L]}/energy.h5")
    done
    "$FIGSRC/answer.sh" fs_ "$L" "${es[*]}" "${masses[*]}" "${zeta_t1[*]}" "${ends[*]}" "${energies[*]}" >> "$fits"
    # The same for the lengths, each up to its own onset of finite size (no t_g: a length of the
    # domains stays one as the giant forms), when every e has >= 3 runs that kept them.
    for q in l lC; do
      series=() qends=()
      for i in "${!es[@]}"; do
        [ "$(runs_of "$q" "${es[i]}" "$L")" -ge 3 ] || { series=(); break; }
        series+=("$FS_WORK/${cid[${es[i]},$L]}/${qfile[$q]}.h5"); qends+=("${tend[$q,${es[i]},$L]}")
      done
      if [ "${#series[@]}" -eq "${#es[@]}" ]; then
        FS_QUANTITY=${qsym[$q]} "$FIGSRC/answer.sh" "${qpre[$q]}" "$L" "${es[*]}" "${series[*]}" "${zeta_t1[*]}" \
          "${qends[*]}" "${energies[*]}" >> "$fits"
      else
        printf '%sstatement_exponent_L%s\tall\tn/a\tnan\t-\t-\tfewer than 3 runs with %s(t) for some e\n' \
          "${qpre[$q]}" "$L" "${qsym[$q]}" >> "$fits"
      fi
    done
    # Blocks of the collapse (q against t / c(e)) and of the lag against q, for the panels (e), (f): the
    # paper's length l where it has a shift, else m; the last L with a shift is drawn.
    cq=m shifted=$FS_WORK/answer-fs_L$L/shift.h5 drawn=("${masses[@]}")
    if [ -e "$FS_WORK/answer-fs_l_L$L/shift.h5" ]; then
      cq=l shifted=$FS_WORK/answer-fs_l_L$L/shift.h5 drawn=()
      for i in "${!es[@]}"; do drawn+=("$FS_WORK/${cid[${es[i]},$L]}/length.h5"); done
    fi
    if [ -e "$shifted" ]; then
      : > "$FS_WORK/blocks.c"; : > "$FS_WORK/blocks.g"; clab=() glab=() cL=$L
      mapfile -t factor < <("$FIT" table --no-header "$shifted:/shift/factor" | cut -f1)
      for i in "${!es[@]}"; do
        add_block c "$cq against t / c(e), e = ${es[i]}, L = $L (c = ${factor[i]}): t/c $cq stderr" \
          awk -v c="${factor[i]}" '!/^#/ && NF >= 3 { print $1 / c, $2, $3 }' < <("$FIT" table "${drawn[i]}:/average/mean" "${drawn[i]}:/average/stderr")
        clab+=("$i")
        [ "$i" -gt 0 ] || continue
        add_block g "lag t_e($cq)/t_${es[0]}($cq), e = ${es[i]}, L = $L: $cq lag stderr" \
          awk -F'\t' -v j="$i" 'NR > 1 && $1 == j { print $2, $3, $4 }' < <("$FIT" table "$shifted:/shift/lag/input" \
            "$shifted:/shift/lag/level" "$shifted:/shift/lag/ratio" "$shifted:/shift/lag/ratio_stderr")
        glab+=("$i")
      done
    fi
  fi
done

# The same statements for every other definition of a cluster at FS_DEF_L, from its own results of the
# same runs, each with the paper's definition's window ends (finite size is the box's).
for d in ${FS_DEF_DIRS:-}; do
  L=$FS_DEF_L tag=$(basename "$d") masses=() ends=() ok=1
  for i in "${!es[@]}"; do
    e=${es[i]} id=${cid[${es[i]},$L]}
    mapfile -t runs < <(ls "$d/$id"/run*.h5 2> /dev/null | sort -V || true)
    [ "${#runs[@]}" -ge 3 ] || { ok=0; break; }
    mkdir -p "$FS_WORK/def-$tag/$id"
    # Another definition may find no cluster at first (m undefined): its curve starts where the
    # statements first look, the start of the shift window or of the late exponent's earlier window.
    from=$(awk -v a="${zeta_t1[i]}" -v t="${tend[m,$e,$L]}" -v d="$FS_LATE_DECADES" \
      'BEGIN { b = t / 10^(2 * d); print (a + 0 < b ? a : b) }')
    "$FIT" --quiet average --dataset /cluster/mean_mass --from "$from" "${runs[@]}" \
      -o "$FS_WORK/def-$tag/$id/mass.h5" 2> /dev/null
    masses+=("$FS_WORK/def-$tag/$id/mass.h5"); ends+=("${tend[m,$e,$L]}")
  done
  if [ "$ok" = 1 ]; then
    "$FIGSRC/answer.sh" "def_${tag}_" "$L" "${es[*]}" "${masses[*]}" "${zeta_t1[*]}" "${ends[*]}" >> "$fits"
  else
    printf 'def_%s_statement_exponent_L%s	all	n/a	nan	-	-	fewer than 3 runs of some e
' "$tag" "$L" >> "$fits"
  fi
done

# Ratios against 1/L, their limit, and the verdict (at the largest L with a ratio; and for L -> inf).
sizes=() inputs=()
for L in "${ls[@]}"; do
  [ -e "$FS_WORK/collapse-L$L.h5" ] || continue
  sizes+=("$L"); inputs+=("$FS_WORK/collapse-L$L.h5:/fit/amplitude_ratio")
done
if [ "${#sizes[@]}" -gt 0 ]; then
  for i in "${!es[@]}"; do
    [ "$i" -gt 0 ] || continue
    add_block r "amplitude ratio A(${es[i]})/A(${es[0]}) against 1/L: invL ratio stderr" \
      awk -F'\t' -v q="fs_amplitude_ratio_L" -v e="${es[i]}" '
        index($1, q) == 1 && $2 == e { print 1 / substr($1, length(q) + 1), $3, $4 }' "$fits"
    rlab+=("$i")
  done
  "$FIT" --quiet extrapolate "${inputs[@]}" --sigmas "$FS_SIGMAS" --tolerance "$FS_TOLERANCE" \
    -o "$FS_WORK/extrapolate.h5" --L "${sizes[@]}" 2> /dev/null
  x=$FS_WORK/extrapolate.h5
  paste <("$FIT" table --no-header "$x:/extrapolate/limit" | cut -f2) \
        <("$FIT" table --no-header "$x:/extrapolate/limit_stderr" | cut -f2) \
        <("$FIT" table --no-header "$x:/extrapolate/at_largest" | cut -f2) \
        <("$FIT" table --no-header "$x:/extrapolate/at_largest_stderr" | cut -f2) \
        <("$FIT" table --no-header "$x:/extrapolate/largest_L" | cut -f2) \
        <("$FIT" table --no-header "$x:/extrapolate/verdict_largest" | cut -f2) \
        <("$FIT" table --no-header "$x:/extrapolate/verdict_limit" | cut -f2) |
    awk -F'\t' -v OFS='\t' -v es="${es[*]}" -v n="${#sizes[@]}" '
      BEGIN { split(es, e, " "); name[1] = "supported"; name[-1] = "rejected"; name[0] = "undecided" }
      NR > 1 {
        print "fs_amplitude_ratio_limit", e[NR], sprintf("%.4g", $1), sprintf("%.3g", $2), "-", "-",
              "A(e)/A(" e[1] ") extrapolated to L -> inf, linear in 1/L over " n " sizes; verdict " name[$7 + 0]
        print "fs_amplitude_ratio_largest", e[NR], sprintf("%.4g", $3), sprintf("%.3g", $4), $5, $5,
              "A(e)/A(" e[1] ") at the largest L with a ratio (L = " $5 "); verdict " name[$6 + 0]
      }' >> "$fits"
  v_largest=$(h5dump -a /extrapolate/verdict_at_largest_L "$x" | sed -n 's/^ *(0): "\(.*\)"/\1/p')
  v_limit=$(h5dump -a /extrapolate/verdict_limit "$x" | sed -n 's/^ *(0): "\(.*\)"/\1/p')
  printf 'fs_amplitude_fit_verdict\tall\t%s\tnan\t%s\t%s\te-independence of the amplitude of m at one common exponent at the largest L (%s sigma, within %s): %s; for L -> inf: %s\n' \
    "$v_largest" "${sizes[-1]}" "${sizes[-1]}" "$FS_SIGMAS" "$FS_TOLERANCE" "$v_largest" "$v_limit" >> "$fits"
  if [ "${#sizes[@]}" -ge 2 ]; then
    for i in "${!es[@]}"; do
      [ "$i" -gt 0 ] || continue
      add_block r "amplitude ratio A(${es[i]})/A(${es[0]}) extrapolated to L -> inf: invL ratio stderr" \
        awk -F'\t' -v e="${es[i]}" '$1 == "fs_amplitude_ratio_limit" && $2 == e { print 0, $3, $4 }' "$fits"
    done
  fi
else
  printf 'fs_amplitude_fit_verdict\tall\tundecided\tnan\t-\t-\tno box size has all e fitted: no amplitude ratio yet\n' >> "$fits"
fi
# The headline, from the statements of the largest box that has them (fs-headline.awk).
awk -f "$FIGSRC/fs-headline.awk" -v es="${es[*]}" "$fits" >> "$fits"
# The builds behind the runs: every piece of every result (collect.sh's piece lines), so that the summary
# names the program the numbers come from and says whether its tree was committed.
builds=$(cat "$FS_RESULTS"/*/run*.info 2> /dev/null | awk -F'\t' '$1 == "piece" {
    print "gg-sim " $3 " (" ($4 == "clean=1" ? "committed tree" : "uncommitted changes") ")" }' | sort -u | paste -sd ';' -)
printf 'fs_builds\tall\t%d\tnan\t-\t-\t%s\n' "$(awk -F';' '{ print NF }' <<< "$builds")" "${builds:-none}" >> "$fits"
printf 'fs_cpu_hours\tall\t%.2f\tnan\t-\t-\tCPU hours of the simulations behind this figure (sum over the present runs)\n' \
  "$(awk -v c="$cpu_total" 'BEGIN { print c / 3600 }')" >> "$fits"

# The data blocks in a fixed order: m, local exponent, ratios, E, collapse, lag, l, share (fig8.gp counts
# on it).
{
  gg_blocks=0
  for b in m z r E c g l s; do
    [ -s "$FS_WORK/blocks.$b" ] || continue
    [ "$gg_blocks" = 0 ] || printf '\n\n'
    gg_blocks=1
    cat "$FS_WORK/blocks.$b"
  done
} > "$OUT/fig8.tsv.tmp"
publish 8
# Block labels for the plot: "i:L" (i = index of e in ES) for the m/E and local-exponent blocks; the
# ratio blocks come per e > first, then (with a limit) once more each for the extrapolated point.
nr=$(grep -c '^# amplitude ratio' "$OUT/fig8.tsv" || true)
plot 8 "mlab='${mlab[*]}'; zlab='${zlab[*]}'; rlab='${rlab[*]}'; nr=$nr; es='${es[*]}'; ls='${ls[*]}'; \
  clab='${clab[*]}'; glab='${glab[*]}'; cL='${cL:-}'; cq='${cq:-m}'; llab='${llab[*]}'; slab='${slab[*]}'; \
  verdict='$(fits_column "$OUT/fig8.fits.tsv" fs_verdict 3)'"
