#!/bin/bash
# table.sh: the cheap step of `make -f Makefile.study accuracy` (pipelines/accuracy/accuracy.mk passes the
# configuration in ACC_* variables). From the simulations and per-run analyses under $ACCR (each with its
# CPU seconds in FILE.cpu) it makes the ensemble averages and fits (gg-fit average / power-law / collapse,
# under $ACCR/fits, remade every time), then writes
#   $OUT/accuracy.tsv  one row per knob value and quantity:
#     knob value runs cpu_sim_s cpu_ana_s disk_MB quantity value stderr reference ref_value ref_stderr
#     deviation dev_sigma note
#     (deviation = value - ref_value; dev_sigma = deviation / sqrt(stderr^2 + ref_stderr^2) for independent
#      runs, n/a when the row re-analyses the reference's own runs; curve rows (E(t), m(t)) give the largest
#      relative deviation from the reference curve and its sigma at that time)
#   $OUT/accuracy.md   the same as markdown tables, one per knob, with the reference and its cost
#   $OUT/accuracy.{png,svg}  (pipelines/accuracy/accuracy.gp)
set -euo pipefail
export LC_ALL=C
: "${FIT:?}" "${ACCR:?}" "${OUT:?}" "${ACC_DIR:?}"
W=$ACCR/fits
rm -rf "$W"; mkdir -p "$W" "$OUT"
LOG=$W/gg-fit.log
: > "$LOG"

read -r zw1 zw2 <<< "$ACC_ZWIN"; read -r tw1 tw2 <<< "$ACC_TWIN"; read -r cw1 cw2 <<< "$ACC_CWIN"
E=$ACC_E E2=$ACC_E2 TM=$ACC_TMAX
g0=$(awk -F: '{ printf "g%sw%src%s", $1, $2, $3 }' <<< "$ACC_CG0")
cgtag() { awk -F: '{ printf "g%sw%src%s", $1, $2, $3 }' <<< "$1"; }
cgname() { awk -F: '{ printf "grid %s, w %s, rho_c %s", $1, $2, $3 }' <<< "$1"; }
sid() { echo "e$1-L$2-t$3-$4-$5"; }               # e L t_max cut snap
simf() { echo "$ACCR/sim/$1/run$2.h5"; }          # id seed
anaf() { echo "$ACCR/ana/$1/run$2.$3-$4.h5"; }    # id seed tool cg

# ok_seeds ID R: the seeds 1..R whose run completed (a collapsed run holds only its first part)
ok_seeds() {
  local k
  for k in $(seq 1 "$2"); do
    if grep -q $'^status\tok' "$(simf "$1" "$k").cpu"; then echo "$k"; fi
  done | tr '\n' ' '
}
# sum of the CPU seconds of the files named on stdin (FILE.cpu beside each)
cpu_sum() { local f s=0; while read -r f; do [ -n "$f" ] && s=$(awk -F'\t' -v s="$s" '$1 == "cpu" { s += $2 } END { printf "%.3f", s }' "$f.cpu"); done; printf '%.1f' "$s"; }
disk_mb() { local f; while read -r f; do [ -n "$f" ] && stat -c %s "$f"; done | awk '{ s += $1 } END { printf "%.1f", s / 1048576 }'; }
sims_of() { local k; for k in $2; do simf "$1" "$k"; done; }            # id "seeds"
anas_of() { local k; for k in $2; do anaf "$1" "$k" "$3" "$4"; done; }  # id "seeds" tool cg
nwords() { wc -w <<< "$1" | tr -d ' '; }
errs() { [ "$1" -ge 3 ] && echo jackknife || echo covariance; }          # jackknife needs >= 3 runs

# Ensemble averages (cached in $W by name): mass / energy / domlen  ID "seeds" [cg] -> file
avg() {
  local what=$1 id=$2 seeds=$3 cg=${4:-$g0} tag out ds files=()
  tag=$(tr ' ' _ <<< "${seeds% }")
  case $what in
    mass)   out=$W/$id-s$tag-$cg.mass.h5;   ds=/cluster/mean_mass;             mapfile -t files < <(anas_of "$id" "$seeds" cluster "$cg") ;;
    domlen) out=$W/$id-s$tag-$cg.domlen.h5; ds=/domains/length;                mapfile -t files < <(anas_of "$id" "$seeds" domains "$cg") ;;
    energy) out=$W/$id-s$tag.energy.h5;     ds=/observables/kinetic_energy/value; mapfile -t files < <(sims_of "$id" "$seeds") ;;
  esac
  # a failed average (e.g. no cluster at all in an early frame of a coarse grid: NaN) makes the fits n/a
  [ -e "$out" ] || "$FIT" average --dataset "$ds" "${files[@]}" -o "$out" 2>> "$LOG" || true
  echo "$out"
}
# power-law exponent "value stderr" (theta: factor -1) of an average over [w1, w2]
plaw() {  # file nruns w1 w2 factor
  local out=$W/pl.$RANDOM$RANDOM.h5
  if ! "$FIT" power-law --errors "$(errs "$2")" "$1:/average/mean" --window "$3" "$4" -o "$out" 2>> "$LOG"; then
    echo "nan nan"; return; fi
  "$FIT" table --no-header "$out:/fit/exponent" "$out:/fit/exponent_stderr" |
    awk -F'\t' -v f="$5" '{ printf "%.6g %.3g\n", $1 * f, $2 }'
}
# amplitude ratio A(2nd)/A(1st) at a common exponent: "value stderr"
ratio() {  # file1 file2 nruns w1 w2
  local out=$W/co.$RANDOM$RANDOM.h5
  if ! "$FIT" collapse --errors "$(errs "$3")" "$1:/average/mean" "$2:/average/mean" --window "$4" "$5" -o "$out" 2>> "$LOG"; then
    echo "nan nan"; return; fi
  "$FIT" table --no-header "$out:/fit/amplitude_ratio" "$out:/fit/amplitude_ratio_stderr" |
    awk -F'\t' 'NR == 2 { printf "%.6g %.3g\n", $1, $2 }'
}
# mean and stderr of an average at the time nearest t
at_time() {  # file t
  [ -e "$1" ] || { echo "nan nan"; return; }
  "$FIT" table --no-header "$1:/average/mean" "$1:/average/stderr" |
    awk -F'\t' -v t="$2" '{ d = log($1 / t); if (d < 0) d = -d; if (n == 0 || d < best) { best = d; v = $2; s = $3 }; n++ }
                          END { printf "%.6g %.3g\n", v, s }'
}
# largest relative deviation of curve X from curve REF over their common times in [tlo, thi]:
# "max|X/REF - 1| sigma_of_that_ratio time rms" (rms = root mean square of (X/REF - 1)/sigma over the
# times where they differ: ~1 when X and REF differ by noise only)
curve_dev() {  # fileX fileREF tlo [thi]
  [ -e "$1" ] && [ -e "$2" ] || { echo "nan nan nan nan"; return; }
  join -t $'\t' \
    <("$FIT" table --no-header "$1:/average/mean" "$1:/average/stderr" | awk -F'\t' -v OFS='\t' '{ printf "%.5e\t%s\t%s\n", $1, $2, $3 }' | sort) \
    <("$FIT" table --no-header "$2:/average/mean" "$2:/average/stderr" | awk -F'\t' -v OFS='\t' '{ printf "%.5e\t%s\t%s\n", $1, $2, $3 }' | sort) |
    awk -F'\t' -v tlo="$3" -v thi="${4:-1e300}" '
      $1 + 0 >= tlo && $1 + 0 <= thi && $4 > 0 {
        r = $2 / $4 - 1; a = r < 0 ? -r : r
        s = sqrt(($3 / $4)^2 + ($2 * $5 / ($4 * $4))^2)
        if (s > 0 && r != 0) { c2 += (r / s)^2; nc++ }   # times before the first difference (same seeds) left out
        if (n++ == 0 || a > best) { best = a; sig = s; t = $1 + 0 } }
      END { if (n == 0) print "nan nan nan nan"; else printf "%.4g %.3g %g %.2g\n", best, sig, t, nc ? sqrt(c2 / nc) : 0 }'
}

RAW=$W/rows.tsv
: > "$RAW"
# row KNOB VALUE RUNS CPU_SIM CPU_ANA DISK QUANTITY "VALUE STDERR" REFNAME "REFVALUE REFSTDERR" SAME NOTE
row() {
  local v e rv re
  read -r v e <<< "$8"; read -r rv re <<< "${10}"
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$1" "$2" "$3" "$4" "$5" "$6" "$7" "$v" "$e" \
    "$9" "$rv" "$re" "${11}" "${12}" >> "$RAW"
}

# ------------------------------------------------------------------------------ ensemble quantities
# quantities ID ID2 "seeds" "seeds2" CG ZW1 ZW2 TW1 TW2 CW1 CW2: sets Q_zeta Q_theta Q_ratio Q_l (value stderr)
# and CPU/disk per quantity: C_sim_e C_sim_e2 C_cl C_cl2 C_dom D_e D_e2
quantities() {
  local id=$1 id2=$2 s=$3 s2=$4 cg=$5 n n2 m m2 en dl
  n=$(nwords "$s"); n2=$(nwords "$s2")
  m=$(avg mass "$id" "$s" "$cg"); en=$(avg energy "$id" "$s"); dl=$(avg domlen "$id" "$s" "$cg")
  Q_zeta=$(plaw "$m" "$n" "$6" "$7" 1)
  Q_theta=$(plaw "$en" "$n" "$8" "$9" -1)
  Q_l=$(at_time "$dl" "$TM")
  C_sim_e=$(sims_of "$id" "$s" | cpu_sum); D_e=$(sims_of "$id" "$s" | disk_mb)
  C_cl=$(anas_of "$id" "$s" cluster "$cg" | cpu_sum); C_dom=$(anas_of "$id" "$s" domains "$cg" | cpu_sum)
  if [ -n "$id2" ]; then
    m2=$(avg mass "$id2" "$s2" "$cg")
    Q_ratio=$(ratio "$m" "$m2" "$(( n < n2 ? n : n2 ))" "${10}" "${11}")
    C_sim_e2=$(sims_of "$id2" "$s2" | cpu_sum); D_e2=$(sims_of "$id2" "$s2" | disk_mb)
    C_cl2=$(anas_of "$id2" "$s2" cluster "$cg" | cpu_sum)
  else
    Q_ratio="nan nan"; C_sim_e2=0; D_e2=0; C_cl2=0
  fi
}
add() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f", a + b }'; }
# the four standard rows of one ensemble setting
std_rows() {  # knob value runs refname same note [skip_l]
  local zn="zeta (m ~ t^zeta, e = $E, $zw1-$zw2)" tn="theta (E ~ t^-theta, e = $E, $tw1-$tw2)"
  row "$1" "$2" "$3" "$C_sim_e" "$C_cl" "$D_e" "zeta" "$Q_zeta" "$4" "$R_zeta" "$5" "$6"
  row "$1" "$2" "$3" "$C_sim_e" 0 "$D_e" "theta" "$Q_theta" "$4" "$R_theta" "$5" "$6"
  row "$1" "$2" "$3" "$(add "$C_sim_e" "$C_sim_e2")" "$(add "$C_cl" "$C_cl2")" "$(add "$D_e" "$D_e2")" \
      "A($E2)/A($E)" "$Q_ratio" "$4" "$R_ratio" "$5" "$6"
  [ -n "${7:-}" ] || row "$1" "$2" "$3" "$C_sim_e" "$C_dom" "$D_e" "l(t=$TM)" "$Q_l" "$4" "$R_l" "$5" "$6"
}

# The reference.
REF=$(sid "$E" "$ACC_LREF" "$TM" "$ACC_CUT" "$ACC_SNAP"); REF2=$(sid "$E2" "$ACC_LREF" "$TM" "$ACC_CUT" "$ACC_SNAP")
RS=$(ok_seeds "$REF" "$ACC_RUNS_REF"); RS2=$(ok_seeds "$REF2" "$ACC_RUNS_REF")
quantities "$REF" "$REF2" "$RS" "$RS2" "$g0" "$zw1" "$zw2" "$tw1" "$tw2" "$cw1" "$cw2"
R_zeta=$Q_zeta R_theta=$Q_theta R_ratio=$Q_ratio R_l=$Q_l
REF_CPU_SIM=$(add "$C_sim_e" "$C_sim_e2"); REF_CPU_ANA=$(add "$(add "$C_cl" "$C_cl2")" "$C_dom")
REF_DISK=$(add "$D_e" "$D_e2")
REF_CPU_ZETA=$(add "$C_sim_e" "$C_cl")
REF_CPU_SIM_E=$C_sim_e REF_CPU_CL=$C_cl REF_CPU_CL2=$C_cl2 REF_CPU_SIM_E2=$C_sim_e2 REF_D_E=$D_e REF_D_E2=$D_e2
REFNAME="REF (L=$ACC_LREF, $ACC_RUNS_REF runs)"
NREF=$(( $(nwords "$RS") ))

# Ensemble size at L = ACC_L: the first R seeds of ACC_RUNS.
B=$(sid "$E" "$ACC_L" "$TM" "$ACC_CUT" "$ACC_SNAP"); B2=$(sid "$E2" "$ACC_L" "$TM" "$ACC_CUT" "$ACC_SNAP")
for r in $ACC_RS; do
  s=$(ok_seeds "$B" "$r"); s2=$(ok_seeds "$B2" "$r")
  quantities "$B" "$B2" "$s" "$s2" "$g0" "$zw1" "$zw2" "$tw1" "$tw2" "$cw1" "$cw2"
  std_rows "runs (L=$ACC_L)" "$r" "$r" "$REFNAME" 0 "seeds 1-$r"
done

# Box size L (ACC_RUNS_L runs each), then the reference itself.
for L in $ACC_LS; do
  id=$(sid "$E" "$L" "$TM" "$ACC_CUT" "$ACC_SNAP"); id2=$(sid "$E2" "$L" "$TM" "$ACC_CUT" "$ACC_SNAP")
  s=$(ok_seeds "$id" "$ACC_RUNS_L"); s2=$(ok_seeds "$id2" "$ACC_RUNS_L")
  quantities "$id" "$id2" "$s" "$s2" "$g0" "$zw1" "$zw2" "$tw1" "$tw2" "$cw1" "$cw2"
  std_rows "box L ($ACC_RUNS_L runs)" "$L" "$ACC_RUNS_L" "$REFNAME" 0 "N = $(awk -v L="$L" 'BEGIN { printf "%d", 0.37 * L * L + 0.5 }')"
done
quantities "$REF" "$REF2" "$RS" "$RS2" "$g0" "$zw1" "$zw2" "$tw1" "$tw2" "$cw1" "$cw2"
std_rows "box L ($ACC_RUNS_L runs)" "$ACC_LREF (REF)" "$ACC_RUNS_REF" "$REFNAME" 1 \
  "the reference: N = $(awk -v L="$ACC_LREF" 'BEGIN { printf "%d", 0.37 * L * L + 0.5 }'), $ACC_RUNS_REF runs"

# Run length t_max at L = ACC_L: fit windows [first, t_max].
for t in $ACC_TMAXS; do
  id=$(sid "$E" "$ACC_L" "$t" "$ACC_CUT" "$ACC_SNAP")
  s=$(ok_seeds "$id" "$ACC_TMAX_RUNS")
  quantities "$id" "" "$s" "" "$g0" "$zw1" "$t" "$tw1" "$t" "" ""
  zn="fits over [$zw1, $t] (zeta) and [$tw1, $t] (theta)"
  row "t_max (L=$ACC_L, $ACC_TMAX_RUNS runs)" "$t" "$ACC_TMAX_RUNS" "$C_sim_e" "$C_cl" "$D_e" zeta "$Q_zeta" "$REFNAME" "$R_zeta" 0 "$zn"
  row "t_max (L=$ACC_L, $ACC_TMAX_RUNS runs)" "$t" "$ACC_TMAX_RUNS" "$C_sim_e" 0 "$D_e" theta "$Q_theta" "$REFNAME" "$R_theta" 0 "$zn"
done

# Fit windows on the reference runs.
mref=$(avg mass "$REF" "$RS"); mref2=$(avg mass "$REF2" "$RS2"); eref=$(avg energy "$REF" "$RS")
for w in $ACC_ZWINS; do
  a=${w%_*} b=${w#*_}
  row "fit window (REF runs)" "$a-$b" "$NREF" "$REF_CPU_SIM_E" "$REF_CPU_CL" "$REF_D_E" zeta "$(plaw "$mref" "$NREF" "$a" "$b" 1)" \
      "REF, window $zw1-$zw2" "$R_zeta" 1 "refit only (no new simulation)"
  row "fit window (REF runs)" "$a-$b" "$NREF" "$REF_CPU_SIM_E" 0 "$REF_D_E" theta "$(plaw "$eref" "$NREF" "$a" "$b" -1)" \
      "REF, window $tw1-$tw2" "$R_theta" 1 "refit only (no new simulation)"
done
for w in $ACC_CWINS; do
  a=${w%_*} b=${w#*_}
  row "fit window (REF runs)" "$a-$b" "$NREF" "$(add "$REF_CPU_SIM_E" "$REF_CPU_SIM_E2")" "$(add "$REF_CPU_CL" "$REF_CPU_CL2")" \
      "$(add "$REF_D_E" "$REF_D_E2")" "A($E2)/A($E)" "$(ratio "$mref" "$mref2" "$NREF" "$a" "$b")" \
      "REF, window $cw1-$cw2" "$R_ratio" 1 "refit only (no new simulation)"
done

# Coarse-graining on the reference runs.
for cg in $ACC_CGS; do
  quantities "$REF" "$REF2" "$RS" "$RS2" "$(cgtag "$cg")" "$zw1" "$zw2" "$tw1" "$tw2" "$cw1" "$cw2"
  v=$(cgname "$cg")
  row "coarse-graining (REF runs)" "$v" "$NREF" "$C_sim_e" "$C_cl" "$D_e" zeta "$Q_zeta" "REF, $(cgname "$ACC_CG0")" "$R_zeta" 1 "re-analysis only"
  row "coarse-graining (REF runs)" "$v" "$NREF" "$(add "$C_sim_e" "$C_sim_e2")" "$(add "$C_cl" "$C_cl2")" "$(add "$D_e" "$D_e2")" \
      "A($E2)/A($E)" "$Q_ratio" "REF, $(cgname "$ACC_CG0")" "$R_ratio" 1 "re-analysis only"
  row "coarse-graining (REF runs)" "$v" "$NREF" "$C_sim_e" "$C_dom" "$D_e" "l(t=$TM)" "$Q_l" "REF, $(cgname "$ACC_CG0")" "$R_l" 1 \
      "re-analysis only; l is measured in the coarse-grained field, so it depends on the definition"
done

# Collapse cutoffs at L = ACC_CUT_L, same seeds; reference: the smallest cutoff ACC_CUT_REF.
# E(t), m(t): largest relative deviation from the reference curve in two ranges, 1 <= t <= ACC_TSPLIT
# (homogeneous cooling and onset: small noise) and ACC_TSPLIT < t <= t_max (late clustering: noisy).
# Plot data: $W/cut-E.dat, $W/cut-m.dat (blocks: reference stderr band, then one per cutoff: t, deviation %,
# sigma %), $W/cutcost.dat (label, CPU s, collapse note).
CL=${ACC_CUT_L:-$ACC_L} TS=${ACC_TSPLIT:-100}
TS2=$(awk -v t="$TS" 'BEGIN { printf "%.10g", t * 1.0001 }')
cutname() { case $1 in none) echo "none";; tc*) echo "t_c = ${1#tc}";; d*) echo "delta = ${1#d}";; esac; }
CR=$(sid "$E" "$CL" "$TM" "$ACC_CUT_REF" "$ACC_SNAP")
crs=$(ok_seeds "$CR" "$ACC_CUT_RUNS"); ncr=$(nwords "$crs")
quantities "$CR" "" "$crs" "" "$g0" "$zw1" "$zw2" "$tw1" "$tw2" "" ""
CR_zeta=$Q_zeta CR_theta=$Q_theta CR_cpu=$C_sim_e
CR_E=$(avg energy "$CR" "$crs"); CR_M=$(avg mass "$CR" "$crs")
CRNAME="$(cutname "$ACC_CUT_REF") (same seeds)"
band() {  # relative stderr of a reference average, in %: t -s +s
  [ -e "$1" ] || return 0
  "$FIT" table --no-header "$1:/average/mean" "$1:/average/stderr" |
    awk -F'\t' -v tlo=1 '$1 + 0 >= tlo && $2 > 0 { printf "%g\t%g\t%g\n", $1, -100 * $3 / $2, 100 * $3 / $2 }'
}
ratio_curve() {  # fileX fileREF: t, 100 (X/REF - 1), 100 sigma
  [ -e "$1" ] && [ -e "$2" ] || return 0
  join -t $'\t' \
    <("$FIT" table --no-header "$1:/average/mean" "$1:/average/stderr" | awk -F'\t' '{ printf "%.5e\t%s\t%s\n", $1, $2, $3 }' | sort) \
    <("$FIT" table --no-header "$2:/average/mean" "$2:/average/stderr" | awk -F'\t' '{ printf "%.5e\t%s\t%s\n", $1, $2, $3 }' | sort) |
    sort -g | awk -F'\t' '$1 + 0 >= 1 && $4 > 0 { printf "%g\t%g\t%g\n", $1, 100 * ($2 / $4 - 1), 100 * sqrt(($3 / $4)^2 + ($2 * $5 / ($4 * $4))^2) }'
}
{ printf '# reference %s: relative stderr band of E (%%): t -s +s\n' "$(cutname "$ACC_CUT_REF")"; band "$CR_E"; } > "$W/cut-E.dat"
{ printf '# reference %s: relative stderr band of m (%%): t -s +s\n' "$(cutname "$ACC_CUT_REF")"; band "$CR_M"; } > "$W/cut-m.dat"
printf '# cutoff\tCPU s (all runs)\tnote\n' > "$W/cutcost.dat"
for c in $ACC_CUTS $ACC_CUT_REF; do
  id=$(sid "$E" "$CL" "$TM" "$c" "$ACC_SNAP")
  all=$(seq 1 "$ACC_CUT_RUNS" | tr '\n' ' '); s=$(ok_seeds "$id" "$ACC_CUT_RUNS"); n=$(nwords "$s")
  cpu=$(sims_of "$id" "$all" | cpu_sum); disk=$(sims_of "$id" "$all" | disk_mb)
  knob="cutoff (e=$E, L=$CL, $ACC_CUT_RUNS runs)" v=$(cutname "$c")
  [ "$c" = "$ACC_CUT" ] && v="$v (study)"
  [ "$c" = "$ACC_CUT_REF" ] && v="$v (ref)"
  # collapses: "t = ... after ... collisions per particle" per collapsed run
  coll=$(for k in $all; do f=$(simf "$id" "$k").cpu
           if grep -q $'^status\tcollapse' "$f"; then sed -n 's/.*inelastic collapse at t = \([0-9.e+-]*\) after \([0-9.e+-]*\) collisions per particle.*/\1 \2/p' "$f"; fi
         done)
  cnote=""
  if [ -n "$coll" ]; then
    ts=$(awk '{ printf "%s%.4g", (NR > 1 ? ", " : ""), $1 }' <<< "$coll")
    cs=$(awk '{ printf "%s%.3g", (NR > 1 ? ", " : ""), $2 }' <<< "$coll")
    tstat=$(awk '{ s += $1; q += $1 * $1; n++ } END { m = s / n; printf "%.4g %s", m, (n > 1 ? sprintf("%.3g", sqrt((q / n - m * m) * n / (n - 1) / n)) : "nan") }' <<< "$coll")
    cnote="$(wc -l <<< "$coll" | tr -d ' ') of $ACC_CUT_RUNS runs collapsed (gg-sim exit 1): at t = $ts after $cs collisions per particle"
    row "$knob" "$v" "$ACC_CUT_RUNS" "$cpu" 0 "$disk" "collapse time" "$tstat" "-" "nan nan" 0 "$cnote"
  fi
  printf '"%s"\t%s\t"%s"\n' "$(sed 's/delta/{\/Symbol d}/; s/t_c/t_c/' <<< "$v")" "$cpu" "$(awk -v c="$cnote" 'BEGIN { if (c != "") { split(c, a, ": at "); print "collapse at " a[2] } }' | sed 's/ after.*//')" >> "$W/cutcost.dat"
  [ "$n" -ge 1 ] || continue
  speed=$(awk -v a="$CR_cpu" -v b="$cpu" 'BEGIN { printf "%.2g", (b > 0 ? a / b : 0) }')
  note="CPU of all $ACC_CUT_RUNS runs; speed-up over the reference cutoff: ${speed}x"
  [ "$n" = "$ACC_CUT_RUNS" ] || note="$note; averages over the $n runs that completed"
  Ef=$(avg energy "$id" "$s"); Mf=$(avg mass "$id" "$s")
  quantities "$id" "" "$s" "" "$g0" "$zw1" "$zw2" "$tw1" "$tw2" "" ""
  same=0; [ "$c" = "$ACC_CUT_REF" ] && same=1
  if [ "$same" = 0 ]; then
    for q in E m; do
      f=$Ef; [ $q = m ] && f=$Mf; r=$CR_E; [ $q = m ] && r=$CR_M
      { printf '\n\n# %s: t, 100 (%s/%s_ref - 1), sigma (%%); first line: the title\n"%s, %s s"\tnan\tnan\n' "$v" "$q" "$q" \
          "$(sed 's/delta/{\/Symbol d}/' <<< "$v")" "$(printf '%.0f' "$cpu")"; ratio_curve "$f" "$r"; } >> "$W/cut-$q.dat"
    done
  fi
  for q in E m; do
    f=$Ef; [ $q = m ] && f=$Mf; r=$CR_E; [ $q = m ] && r=$CR_M
    ca=0; [ $q = m ] && ca=$C_cl
    d=($(curve_dev "$f" "$r" 1 "$TS"))
    row "$knob" "$v" "$n" "$cpu" "$ca" "$disk" "$q(t) max rel. dev., 1 <= t <= $TS" "${d[0]} ${d[1]}" "$CRNAME" "0 0" "$same" \
        "$note; largest |$q/${q}_ref - 1| at t = ${d[2]}; rms deviation in sigmas: ${d[3]}"
    d=($(curve_dev "$f" "$r" "$TS2" "$TM"))
    row "$knob" "$v" "$n" "$cpu" "$ca" "$disk" "$q(t) max rel. dev., $TS < t <= $TM" "${d[0]} ${d[1]}" "$CRNAME" "0 0" "$same" \
        "largest |$q/${q}_ref - 1| at t = ${d[2]}; rms deviation in sigmas: ${d[3]}"
  done
  row "$knob" "$v" "$n" "$cpu" 0 "$disk" theta "$Q_theta" "$CRNAME" "$CR_theta" "$same" ""
  row "$knob" "$v" "$n" "$cpu" "$C_cl" "$disk" zeta "$Q_zeta" "$CRNAME" "$CR_zeta" "$same" ""
done

# Snapshots (density, precision) at L = ACC_L: same trajectories (snapshots do not perturb the dynamics).
# Plot data $W/snaps.dat: label, disk MB per run, zeta change from the reference, zeta stderr, CPU s.
snapname() { local s=${1#s}; echo "${s%?}/decade, $( [ "${s: -1}" = f ] && echo float || echo double)"; }
SR=$(sid "$E" "$ACC_L" "$TM" "$ACC_CUT" "$ACC_SNAP_REF")
srs=$(ok_seeds "$SR" "$ACC_SNAP_RUNS")
quantities "$SR" "" "$srs" "" "$g0" "$zw1" "$zw2" "$tw1" "$tw2" "" ""
SR_zeta=$Q_zeta SR_M=$(avg mass "$SR" "$srs")
SRNAME="$(snapname "$ACC_SNAP_REF") (same runs)"
printf '# snapshots\tdisk MB per run\tzeta - zeta_ref\tzeta stderr\tCPU s (sim + cluster)\n' > "$W/snaps.dat"
for sn in $ACC_SNAPS $ACC_SNAP_REF; do
  id=$(sid "$E" "$ACC_L" "$TM" "$ACC_CUT" "$sn"); s=$(ok_seeds "$id" "$ACC_SNAP_RUNS"); n=$(nwords "$s")
  quantities "$id" "" "$s" "" "$g0" "$zw1" "$zw2" "$tw1" "$tw2" "" ""
  v=$(snapname "$sn"); [ "$sn" = "$ACC_SNAP" ] && v="$v (study)"; [ "$sn" = "$ACC_SNAP_REF" ] && v="$v (ref)"
  knob="snapshots (L=$ACC_L, $ACC_SNAP_RUNS runs)"
  nsnap=$(h5ls "$(simf "$id" 1)/particles/all/position/value" 2>/dev/null | sed -n 's/.*{\([0-9]*\),.*/\1/p')
  per=$(awk -v d="$D_e" -v n="$n" 'BEGIN { printf "%.2f", d / n }')
  d=($(curve_dev "$(avg mass "$id" "$s")" "$SR_M" 0))
  row "$knob" "$v" "$n" "$C_sim_e" "$C_cl" "$D_e" "m(t) max rel. dev." "${d[0]} ${d[1]}" "$SRNAME" "0 0" 1 \
      "largest |m/m_ref - 1| at the common snapshot times; ${nsnap:-?} snapshots per run; disk $per MB per run"
  row "$knob" "$v" "$n" "$C_sim_e" "$C_cl" "$D_e" zeta "$Q_zeta" "$SRNAME" "$SR_zeta" 1 "fit over the snapshots in $zw1-$zw2"
  read -r zv ze <<< "$Q_zeta"; read -r zr SNAPZERR <<< "$SR_zeta"
  printf '"%s"\t%s\t%s\t%s\t%s\n' "$(sed 's/\/decade,//; s/ (study)/*/' <<< "$v")" "$per" \
    "$(awk -v a="$zv" -v b="$zr" 'BEGIN { printf "%.4g", a - b }')" "$ze" "$(add "$C_sim_e" "$C_cl")" >> "$W/snaps.dat"
done

# ---------------------------------------------------------------------------------------------- outputs
TSV=$OUT/accuracy.tsv
{
  printf '# What accuracy costs in time (make -f Makefile.study accuracy). e = %s (and %s for the amplitude ratio), rho = 0.37, T0 = 1, t_max = %s unless stated.\n' "$E" "$E2" "$TM"
  printf '# Reference: L = %s, %s runs per e, %s, %s, %s; CPU %s s (simulations) + %s s (analyses); %s MB.\n' \
    "$ACC_LREF" "$ACC_RUNS_REF" "$(cutname "$ACC_CUT")" "$(snapname "$ACC_SNAP")" "$(cgname "$ACC_CG0")" "$REF_CPU_SIM" "$REF_CPU_ANA" "$REF_DISK"
  printf '# deviation = value - ref_value; dev_sigma = deviation / sqrt(stderr^2 + ref_stderr^2) (n/a when the row re-analyses the reference runs). Errors: jackknife over runs (covariance for < 3 runs).\n'
  printf 'knob\tvalue\truns\tcpu_sim_s\tcpu_ana_s\tdisk_MB\tquantity\tvalue\tstderr\treference\tref_value\tref_stderr\tdeviation\tdev_sigma\tnote\n'
  awk -F'\t' -v OFS='\t' '
    function num(x) { return x !~ /nan|inf|^-?$/ }
    { dev = "nan"; sig = "n/a"
      if (num($8) && num($11)) {
        dev = sprintf("%.3g", $8 - $11)
        if ($13 == 0 && num($9) && num($12) && ($9 * $9 + $12 * $12) > 0) sig = sprintf("%.2g", ($8 - $11) / sqrt($9 * $9 + $12 * $12))
      }
      if ($11 == 0 && $12 == 0 && $7 ~ /max/) { dev = $8; sig = ($13 == 0 && num($9) && $9 > 0) ? sprintf("%.2g", $8 / $9) : "n/a" }
      print $1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $11, $12, dev, sig, $14 }' "$RAW"
} > "$TSV.tmp"
mv "$TSV.tmp" "$TSV"

{ "$ACC_DIR/markdown.sh" "$TSV"; awk -f "$ACC_DIR/cutoff-choice.awk" "$TSV"; } > "$OUT/accuracy.md.tmp"
mv "$OUT/accuracy.md.tmp" "$OUT/accuracy.md"

# Plot inputs: the reference values, what the runs without cutoff did, and the re-analysis variants
# (relative change of zeta, theta, the amplitude ratio and l from the reference, in %) one per line.
G=$W/reanalysis.dat
awk -F'\t' -v OFS='\t' '
  function num(x) { return x !~ /nan|inf|n\/a|^-?$/ }
  /^#/ || /^knob\t/ { next }
  $1 ~ /^(coarse|fit window)/ {
    lab = $2
    if ($1 ~ /^coarse/) { gsub(/rho_c /, "{/Symbol r}_c ", lab) } else lab = "window " lab
    if (!(lab in idx)) { idx[lab] = n++; name[idx[lab]] = lab }
    q = ($7 == "zeta") ? 1 : ($7 == "theta") ? 2 : ($7 ~ /^A\(/) ? 3 : 4
    if (num($8) && num($11) && $11 != 0) { v[idx[lab], q] = 100 * ($8 - $11) / $11; e[idx[lab], q] = 100 * $9 / $11 }
  }
  END { print "# label", "zeta_%", "err", "theta_%", "err", "ratio_%", "err", "l_%", "err"
        for (i = 0; i < n; i++) { printf "\"%s\"", name[i]
          for (q = 1; q <= 4; q++) printf "\t%s\t%s", ((i, q) in v) ? v[i, q] : "nan", ((i, q) in e) ? e[i, q] : "nan"
          printf "\n" } }' "$TSV" > "$G"
coll=$(awk -F'\t' '$7 == "collapse time" { print $15 }' "$TSV" | head -1)
[ -z "$coll" ] || coll="without cutoff: $coll"
read -r rz rze <<< "$R_zeta"; read -r rth rthe <<< "$R_theta"; read -r rr rre <<< "$R_ratio"; read -r rl rle <<< "$R_l"
LC_ALL=C.UTF-8 "${GNUPLOT:-gnuplot}" -e "tsv='$TSV'; rean='$G'; cutdir='$W'; dir='$OUT'; refname='L = $ACC_LREF, $NREF runs'; e1='$E'; e2='$E2'; tm='$TM'; \
  rz=$rz; rze=$rze; rth=$rth; rthe=$rthe; rr=$rr; rre=$rre; rl=$rl; rle=$rle; rzc=$REF_CPU_ZETA; snapzerr='${SNAPZERR:-n/a}'; coll='${coll//\'/}'; \
  lbase='$ACC_L'" "$ACC_DIR/accuracy.gp"
echo "accuracy: wrote $TSV, $OUT/accuracy.md, $OUT/accuracy.png, $OUT/accuracy.svg" >&2
