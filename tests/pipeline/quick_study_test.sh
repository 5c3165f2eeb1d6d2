#!/bin/bash
# quick_study_test.sh SOURCE_DIR BUILD_DIR
# Runs `make -f Makefile.study -j2 SCALE=quick` with RUNS and FIGURES in a temporary folder (the user's
# runs/ and figures/ are not touched) and the tools already built in BUILD_DIR, then checks:
#   every figure's PNG, SVG, data TSV and fits table exists; summary.md has no NaN/inf;
#   m(t) grows and E(t) falls over the last decade of every ensemble; theta is near its late value (1 in
#   2D, 2/3 in 1D).
set -uo pipefail
src=$(cd "$1" && pwd) bin=$(cd "$2" && pwd)
fail() { echo "FAIL: $*" >&2; echo "(outputs kept in $tmp)" >&2; trap - EXIT; exit 1; }
for tool in simulate/gg-sim analyze/gg-cluster analyze/gg-correlate analyze/gg-domains analyze/gg-velocity analyze/gg-fit; do
  [ -x "$bin/$tool" ] || { echo "FAIL: $bin/$tool is missing: build first" >&2; exit 1; }
done
for prog in make gnuplot h5dump h5ls awk; do
  command -v $prog > /dev/null || { echo "FAIL: $prog not found: run make -f Makefile.study deps" >&2; exit 1; }
done
tmp=$(mktemp -d "${TMPDIR:-/tmp}/gg-pipeline.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
# Do not inherit the variables of a calling make (e.g. `make -f Makefile.study test SCALE=...`).
unset MAKEFLAGS MFLAGS MAKEOVERRIDES MAKELEVEL GNUMAKEFLAGS

start=$(date +%s)
if ! make -C "$src" -f Makefile.study -j2 SCALE=quick BUILD="$bin" RUNS="$tmp/runs" FIGURES="$tmp/figures" \
       figures summary > "$tmp/make.log" 2>&1; then
  tail -40 "$tmp/make.log" >&2
  fail "make -f Makefile.study SCALE=quick failed"
fi
echo "quick study: $(( $(date +%s) - start )) s"
fig=$tmp/figures

# 1. every figure and table
for n in 2 3 4 5 6 7 8 9 10 11; do
  for ext in png svg tsv fits.tsv; do
    [ -s "$fig/fig$n.$ext" ] || fail "fig$n.$ext missing or empty"
  done
  [ "$(head -c 4 "$fig/fig$n.png" | od -An -tx1 | tr -d ' \n')" = 89504e47 ] || fail "fig$n.png is not a PNG"
  grep -q '<svg' "$fig/fig$n.svg" || fail "fig$n.svg is not an SVG"
done
[ -s "$fig/summary.md" ] || fail "summary.md missing"

# 2. every number in the summary is finite (undefined quantities are written n/a)
if grep -Eiw 'nan|-nan|inf|-inf|infinity' "$fig/summary.md"; then fail "summary.md contains a non-finite number"; fi
rows=$(grep -c '^| [0-9]' "$fig/summary.md")
[ "$rows" -ge 20 ] || fail "summary.md has $rows rows, expected >= 20"
grep -q '^| [0-9].*zeta ≃ 0.6 | [0-9]' "$fig/summary.md" || fail "summary.md has no measured zeta"
# the finite-size section: a verdict word computed from the statements (read in the paper's length l at the
# largest box), and one row per box and e with the giant cluster's time t_g measured in every cell
grep -Eq '^\*\*Verdict: e-independence of the late amplitude \(q\(e\)/q\(0\.5\) = 1 at equal times\) is (supported|rejected|undecided)\*\* at the largest box where it has a verdict \(L = 128\), read in l\. ' \
  "$fig/summary.md" || fail "summary.md has no finite-size verdict read in l at L = 128"
tgrows=$(grep -Ec '^\| (64|128) \| 0\.[579] \| [0-9]+ \| [0-9]+ \| [0-9.]+ ± [0-9.e+-]+ \(3 of 3 runs reach\)' "$fig/summary.md")
[ "$tgrows" = 6 ] || fail "summary.md has $tgrows cells with t_g, expected 6"
grep -Eq '^\*\*When the giant cluster forms\.\*\* .* Against L: t_g\(e = 0\.5\) ~ L\^\([0-9.-]+ ± [0-9.]+\): (grows with L|falls with L|independent of L|undecided);' \
  "$fig/summary.md" || fail "summary.md does not say whether t_g grows with L"
# the 3D rows (Fig. 9): Haff, theta and zeta for e = 0.5 and 0.9, each with a measured number
rows3=$(grep -Ec '^\| [0-9]+ \| 3D: .* \| [0-9][^|]* ± ' "$fig/summary.md")
[ "$rows3" = 6 ] || fail "summary.md has $rows3 measured 3D rows, expected 6 (Haff, theta, zeta x e = 0.5, 0.9)"
fsrows=$(grep -Ec '^\| (64|128) \| 0\.[579] \|' "$fig/summary.md")
[ "$fsrows" = 6 ] || fail "summary.md has $fsrows finite-size rows, expected 6 (L = 64, 128 x 3 e)"
# the longer runs beside the largest box's e = 0.9 (FS_LONG): when the smaller box departs from them
grep -Eq '^\*\*Longer runs, e = 0\.9 at L = 128:\*\* 2 runs to t = 4000 \(complete.* L = 64 departs from them' "$fig/summary.md" ||
  fail "summary.md does not report the longer runs and the onset of L = 64 against them"
# The three statements (gg-fit late-exponent, ratio, shift) at the larger box for l(t), l_C(t) (each with
# a time factor for each e) and m(t) before t_g, and for the two other cluster definitions of the quick scale.
for q in 'l\(t\)' 'l_C\(t\)' 'm\(t\), before t_g'; do
  grep -Eq '^\*\*L = 128, '"$q"'\.\*\* \(1\) late exponents agree: (yes|no)\. \(2\) equal-time amplitude = 1: (supported|rejected|undecided)\. \(3\) ' \
    "$fig/summary.md" || fail "summary.md has no three statements for $q at L = 128"
done
for q in l l_C; do
  shiftrows=$(awk -v h="**L = 128, $q(t).**" 'index($0, h) == 1 { on = 1; next } /^\*\*/ { on = 0 } on' "$fig/summary.md" |
    grep -Ec '^\| 0\.[79] \| .* \| [0-9.]+ ± [0-9.e-]+ \[[0-9]+, [0-9]+\] \| [0-9.]+ \((collapses|does not collapse)\)')
  [ "$shiftrows" = 2 ] || fail "summary.md has $shiftrows time-shift factors of $q at L = 128, expected 2 (e = 0.7, 0.9)"
done
# m and l at equal energy, each with a ratio for e = 0.7 and 0.9
for q in l m; do
  eerows=$(awk -v h="**L = 128, $q(t)" 'index($0, h) == 1 { on = 1; next } /^\*\*/ { on = 0 } on' "$fig/summary.md" |
    grep -Ec '^\| 0\.[79] \| [^|]* \| [^|]* \| [^|]* \| [0-9.]+ ± [0-9.e-]+ \[[0-9.e-]+, [0-9.e-]+\] \|')
  [ "$eerows" = 2 ] || fail "summary.md has $eerows ratios of $q at equal energy at L = 128, expected 2"
done
defrows=$(grep -Ec '^\| rho_c = 0\.[456], w = [12], [48]-conn\.' "$fig/summary.md")
[ "$defrows" = 3 ] || fail "summary.md has $defrows cluster definitions in the answer's table, expected 3"

# 3. late-time trends: blocks of the figure data (gnuplot 'index' blocks: '# label' then 'time value stderr')
# last value vs the value a decade earlier, for every block whose label starts with the given text.
trend() {  # FILE LABEL_PREFIX up|down
  awk -F'\t' -v pre="$2" -v dir="$3" '
    function check() {
      if (!on) return
      if (n < 2) { print "block \"" lab "\": too few points"; bad = 1; return }
      j = n; while (j > 1 && t[j - 1] >= t[n] / 10) j--
      if (j == n) j = n - 1
      ok = (dir == "up") ? (v[n] > v[j]) : (v[n] < v[j])
      printf "  %-60s %s: %g (t = %g) -> %g (t = %g)\n", lab, (ok ? "ok" : "WRONG"), v[j], t[j], v[n], t[n]
      if (!ok) bad = 1
      found++
    }
    /^# / && $0 !~ /^# time/ { check(); lab = substr($0, 3); on = (index(lab, pre) == 1); n = 0; next }
    /^#/ || NF < 2 { next }
    on && $2 !~ /nan/ { t[++n] = $1; v[n] = $2 }
    END { check(); if (!found) { print "no block starts with \"" pre "\""; bad = 1 } exit bad }' "$1"
}
echo "m(t) grows at late times:"
trend "$fig/fig3.tsv" "m(t), e = " up || fail "m(t) does not grow at late times"
trend "$fig/fig7.tsv" "1D m(t)" up || fail "1D m(t) does not grow at late times"
echo "E(t) falls at late times:"
trend "$fig/fig6.tsv" "E(t) per particle" down || fail "E(t) does not fall at late times"
trend "$fig/fig7.tsv" "1D E(t)" down || fail "1D E(t) does not fall at late times"
trend "$fig/fig9.tsv" "3D E(t)" down || fail "3D E(t) does not fall at late times"
trend "$fig/fig10.tsv" "BAM, E(t)" down || fail "BAM E(t) does not fall at late times"
trend "$fig/fig10.tsv" "BAM, mean mass" up || fail "BAM m(t) does not grow at late times"
echo "3D m(t) grows at e = 0.5 (e = 0.9 has not left its plateau by the quick t_max):"
trend "$fig/fig9.tsv" "3D m(t), e = 0.5" up || fail "3D m(t) does not grow at e = 0.5"

# 4. fitted theta against the paper's late decay E ~ t^-theta: theta = 1 in 2D (measured 1.03 and 1.01 at
# e = 0.5 and 0.7 at this scale); at e = 0.9 the quick runs end on the way from Haff's 2 to it (1.27);
# theta = 2/3 in 1D (0.71).
awk -F'\t' '
  $1 == "theta" { n++; lo = $2 == "0.9" ? 1 : 0.85; hi = $2 == "0.9" ? 1.6 : 1.15
    ok = ($3 + 0 > lo && $3 + 0 < hi); printf "  theta(e = %s) = %s %s\n", $2, $3, ok ? "ok" : "OUT OF (" lo ", " hi ")"; if (!ok) bad = 1 }
  END { if (n != 3) { print "expected 3 theta rows, got " n; bad = 1 } exit bad }' "$fig/fig6.fits.tsv" || fail "2D theta out of range"
awk -F'\t' '
  $1 == "theta_1d" { n++; ok = ($3 + 0 > 0.57 && $3 + 0 < 0.77); printf "  theta_1d = %s %s\n", $3, ok ? "ok" : "OUT OF (0.57, 0.77)"; if (!ok) bad = 1 }
  END { if (n != 1) bad = 1; exit bad }' "$fig/fig7.fits.tsv" || fail "1D theta out of range"

# 4b. Haff's law in 3D: the fitted t0 within 15% of the Enskog t0 with the Carnahan-Starling g
# (docs/PHYSICS.md; at early times the gas is homogeneous in any box)
awk -F'\t' '
  $1 == "haff_t0_ratio_3d" { n++; ok = ($3 + 0 > 0.85 && $3 + 0 < 1.15); printf "  3D t0/t0_Enskog(e = %s) = %s %s\n", $2, $3, ok ? "ok" : "OUT OF (0.85, 1.15)"; if (!ok) bad = 1 }
  END { if (n != 2) { print "expected 2 haff_t0_ratio_3d rows, got " n; bad = 1 } exit bad }' "$fig/fig9.fits.tsv" || fail "3D Haff t0 off"

# 4c. the BAM in 2D (Fig. 10): growth slower than mean field's t (Trizac & Hansen 1995 find zeta ~ 0.86 at
# low density) and the hyperscaling relation 2 zeta + d theta = 2d (eq. 5) within 10%
awk -F'\t' '
  $1 == "zeta_bam" { z = $3; ok = (z + 0 > 0.75 && z + 0 < 0.98); printf "  BAM zeta = %s %s\n", z, ok ? "ok" : "OUT OF (0.75, 0.98)"; if (!ok) bad = 1; n++ }
  $1 == "hyperscaling_bam" { h = $3; ok = (h + 0 > 3.6 && h + 0 < 4.4); printf "  BAM 2 zeta + 2 theta = %s %s\n", h, ok ? "ok" : "OUT OF (3.6, 4.4)"; if (!ok) bad = 1; n++ }
  END { if (n != 2) { print "expected zeta_bam and hyperscaling_bam rows"; bad = 1 } exit bad }' "$fig/fig10.fits.tsv" || fail "BAM exponents off"
rowsb=$(grep -Ec '^\| [0-9]+ \| (BAM|inelastic gas), 2D: .* \| [0-9][^|]* ± ' "$fig/summary.md")
[ "$rowsb" = 5 ] || fail "summary.md has $rowsb measured Fig. 10 rows, expected 5 (BAM hyperscaling and zeta, the gas's hyperscaling x 3 e)"

# 4d. the velocities (Fig. 11): per e a flow-field energy fraction in (0, 1] at both ends that grows
# (the clusters move as wholes: their velocities parallelize), a finite a2 and xi_L-vs-l growth; the
# summary's six Fig. 11 rows each with a number; the field snapshot holds every cell of the grid.
awk -F'\t' '
  $1 == "flow_fraction_early" || $1 == "flow_fraction_late" {
    ok = ($3 + 0 > 0 && $3 + 0 <= 1); if (!ok) { printf "  %s(e = %s) = %s OUT OF (0, 1]\n", $1, $2, $3; bad = 1 } }
  $1 == "flow_fraction_growth" { n++; ok = ($3 + 0 > 1); printf "  flow-field energy fraction late/early (e = %s) = %s %s\n", $2, $3, ok ? "ok" : "NOT > 1"; if (!ok) bad = 1 }
  $1 == "a2_late" || $1 == "xi_over_l_growth" { m++; if ($3 !~ /^-?[0-9]/) { printf "  %s(e = %s) = %s not a number\n", $1, $2, $3; bad = 1 } }
  END { if (n != 3 || m != 6) { print "expected 3 flow_fraction_growth and 6 a2_late/xi_over_l_growth rows, got " n ", " m; bad = 1 } exit bad }' \
  "$fig/fig11.fits.tsv" || fail "Fig. 11 velocity rows off"
rowsv=$(grep -Ec '^\| [0-9]+ \| (velocities parallelize|the parallel-velocity domains) .* \| [0-9][^|]* ± ' "$fig/summary.md")
[ "$rowsv" = 6 ] || fail "summary.md has $rowsv measured Fig. 11 rows, expected 6 (flow fraction and xi_L vs l x 3 e)"
cells=$(awk '/^# flow field/ { on = 1; next } on && /^[0-9]/ { n++ } END { print n + 0 }' "$fig/fig11.tsv")
[ "$cells" = $((128 * 128)) ] || fail "fig11.tsv's field snapshot has $cells cells, expected 128 x 128"

# 5. changing an analysis option reruns analyses only, never a simulation
if ! make -C "$src" -f Makefile.study -n SCALE=quick BUILD="$bin" RUNS="$tmp/runs" FIGURES="$tmp/figures" \
       RHO_C=0.6 figures summary > "$tmp/dry.log" 2>&1; then fail "make -n RHO_C=0.6 failed"; fi
grep -q 'gg-sim ' "$tmp/dry.log" && fail "RHO_C=0.6 would rerun a simulation"
grep -q 'gg-cluster .*--rho-c 0.6' "$tmp/dry.log" || fail "RHO_C=0.6 would not rerun gg-cluster"
echo "PASS"
