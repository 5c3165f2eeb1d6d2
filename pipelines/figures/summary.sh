#!/bin/bash
# summary.sh FIGN.fits.tsv ...  > summary.md   (called by Makefile.study)
# The paper's statements against our numbers, read from the figures' fit tables (which fitrow.sh and the
# figure scripts fill from the gg-fit outputs with `gg-fit table`). Environment (for the header): SCALE,
# L2, NRUN, TMAXS, L1, NRUN1, TMAX1, RHO_C, L3, NRUN3, TMAXS3, RHO_C3.
# Verdict: agree when |ours - paper| <= max(2 sigma, tol), tol = 10% for exponents, 25% for times and ratios
# read off the paper's figure, 20% for amplitude ratios; "not reached" when our quantity is undefined
# (e.g. the t^0.6 regime never starts before t_max). Undefined numbers are written as "n/a", never NaN.
set -euo pipefail
L2=${L2:-?} L1=${L1:-?}
N2=$(awk -v L="$L2" 'BEGIN { if (L + 0 > 0) printf "%d", 0.37 * L * L + 0.5; else print "?" }')
N1=$(awk -v L="$L1" 'BEGIN { if (L + 0 > 0) printf "%d", 0.3 * L + 0.5; else print "?" }')
N3=$(awk -v L="${L3:-?}" 'BEGIN { if (L + 0 > 0) printf "%d", 0.55 * L * L * L + 0.5; else print "?" }')
cat <<HEAD
# Das & Paul, cooling granular gas: the paper's statements against this study

Scale \`${SCALE:-?}\`: 2D rho = 0.37, L = $L2 (N = $N2), ${NRUN:-?} runs per e, t_max = ${TMAXS:-?} for e = 0.5, 0.7, 0.9
(TC model t_c = 1e-4 for e = 0.5 and 0.7), start = random + 10 elastic collisions per particle, T0 = 1;
1D rho = 0.3, e = 0.5, delta = 0.005, L = $L1 (N = $N1), ${NRUN1:-?} runs, t_max = ${TMAX1:-?};
3D spheres rho = 0.55 (eta = 0.288), L = ${L3:-?} (N = $N3), ${NRUN3:-?} runs per e, t_max = ${TMAXS3:-?} for e = 0.5, 0.9 (t_c = 1e-4 for 0.5).
Clusters: psi = sgn(rho_loc - ${RHO_C:-0.5}) on a unit grid with 3x3 (2D) / 3-cell (1D) coarse-graining (docs/DESIGN.md);
in 3D rho_c = ${RHO_C3:-0.75} (the same packing fraction as 2D's threshold), 3x3x3 blocks, face connectivity.
Errors: jackknife over runs (standard errors). The paper states neither T0 nor its onset criterion: times
depend on both (all times scale as 1/sqrt(T0)); exponents and ratios do not.

Verdict: **disagree** when |ours - paper| > max(2 sigma, tol), with tol = 10% for exponents, 25% for times
and ratios read off the paper's figures, 20% for amplitude ratios, 0.1 for collapse deviations; otherwise
**agree** if our error bar sigma <= tol, **inconclusive** if it is larger (too noisy to tell); **not reached**
when our quantity is undefined at this scale (e.g. a regime that has not started by t_max). A statement that
a quantity exceeds a bound ("grows (> 1)") is **agree** when ours minus 2 sigma exceeds it, **disagree** when
ours plus 2 sigma falls below it, else **inconclusive**.

| # | paper's statement | paper | ours | verdict | how we measured |
|---|---|---|---|---|---|
HEAD
awk -F'\t' '
  /^#/ || NF < 4 { next }
  { k = $1 "|" $2; val[k] = $3; err[k] = $4; t1[k] = $5; t2[k] = $6 }
  function def(x) { return x != "" && x !~ /nan|inf/ && x != "-" }
  function num(x) { return def(x) ? sprintf("%.3g", x) : "n/a" }
  function pm(v, s) { return def(v) ? num(v) " ± " (def(s) ? sprintf("%.2g", s) : "n/a") : "n/a" }
  function tnum(x) { return !def(x) ? "n/a" : (x + 0 >= 100 ? sprintf("%.0f", x) : sprintf("%.3g", x)) }
  function win(k) { return (def(t1[k]) && def(t2[k])) ? " over t in [" tnum(t1[k]) ", " tnum(t2[k]) "]" : "" }
  # agree: within the tolerance (or 2 sigma) and precise enough (sigma <= tol) to say so;
  # inconclusive: consistent only because the error bar is larger than the tolerance; else disagree.
  function verdict(v, s, p, tol,   d, lim) {
    if (!def(v)) return "not reached"
    d = v - p; if (d < 0) d = -d
    lim = tol; if (def(s) && 2 * s > lim) lim = 2 * s
    if (d > lim) return "disagree"
    return (def(s) && s > tol) ? "inconclusive" : "agree"
  }
  function row(stmt, p, pshow, v, s, tolrel, how,   tol) {
    tol = (p == 0) ? tolrel : tolrel * (p < 0 ? -p : p)
    printf "| %d | %s | %s | %s | %s | %s |\n", ++n, stmt, pshow, pm(v, s), verdict(v, s, p, tol), how
  }
  # above: a claim that a quantity exceeds the threshold p: agree when v - 2 sigma > p, disagree when
  # v + 2 sigma < p, else inconclusive.
  function above(stmt, p, pshow, v, s, how,   vd) {
    if (!def(v)) vd = "not reached"
    else if (!def(s)) vd = (v > p) ? "agree" : "disagree"
    else vd = (v - 2 * s > p) ? "agree" : (v + 2 * s < p) ? "disagree" : "inconclusive"
    printf "| %d | %s | %s | %s | %s | %s |\n", ++n, stmt, pshow, pm(v, s), vd, how
  }
  function ratio(a, b, what, stmt, p, pshow, tolrel, how,   v, s) {
    if (def(val[a]) && def(val[b]) && val[b] != 0) {
      v = val[a] / val[b]
      s = (def(err[a]) && def(err[b]) && val[a] != 0) ? v * sqrt((err[a] / val[a])^2 + (err[b] / val[b])^2) : "nan"
    } else { v = "nan"; s = "nan" }
    row(stmt, p, pshow, v, s, tolrel, how)
  }
  END {
    split("0.5 0.7 0.9", E, " ")
    for (i = 1; i <= 3; ++i) { k = "zeta|" E[i]
      row("m ~ t^zeta at late times, e = " E[i], 0.6, "zeta ≃ 0.6", val[k], err[k], 0.10,
          "power-law fit of the ensemble m(t)" win(k) " (Fig. 3)") }
    for (i = 1; i <= 3; ++i) { k = "theta|" E[i]
      row("E ~ t^-theta in the ICS (2D), e = " E[i], 1, "theta = 1", val[k], err[k], 0.10,
          "power-law fit of the ensemble E(t)" win(k) " (Fig. 6)") }
    k = "theta_1d|0.5"
    row("1D: E ~ t^-theta (e = 0.5, rho = 0.3, delta = 0.005)", 2/3, "theta = 2/3", val[k], err[k], 0.10,
        "power-law fit of the 1D ensemble E(t)" win(k) " (Fig. 7a)")
    k = "zeta_1d_last_decade|0.5"
    row("1D: growth of m appears frozen while E keeps decaying", 0, "local zeta ≈ 0 at late t", val[k], "nan", 0.2,
        "ln(m(t2)/m(t1))/ln(t2/t1)" win(k) ", the last decade of the run (Fig. 7b)")
    k = "onset_plateau_time|0.5"
    row("onset of the crossover to the ICS, e = 0.5", 0.35, "t ≃ 0.35", val[k], err[k], 0.25,
        "m(t) > 1.1 x its early plateau (Fig. 3); T0 = 1, paper T0 unknown")
    k = "onset_plateau_time|0.9"
    row("onset of the crossover to the ICS, e = 0.9", 3, "t ≃ 3", val[k], err[k], 0.25,
        "as above")
    ratio("onset_plateau_time|0.9", "onset_plateau_time|0.5", "", "ratio of onset times, e = 0.9 / e = 0.5", 9, "≈ 9", 0.25,
          "ratio of the two onsets above (independent of T0)")
    ratio("onset_asymptote_time|0.9", "onset_asymptote_time|0.5", "", "ratio of the times the t^0.6 regime starts, e = 0.9 / e = 0.5", 3.5, "≈ 3.5", 0.25,
          "first time the local exponent of m(t) is within 0.1 of 0.6 (3 samples in a row), e = 0.5: " tnum(val["onset_asymptote_time|0.5"]) ", e = 0.9: " tnum(val["onset_asymptote_time|0.9"]))
    k = "crossover_peak_exponent|0.5"
    row("power-law exponent of m during the crossover, e = 0.5", 0.75, "≈ 0.75", val[k], err[k], 0.25,
        "largest local exponent of m(t) (0.5-decade sliding fit) before the end of the late window, at t = " tnum(t1[k]))
    k = "crossover_peak_exponent|0.9"
    row("power-law exponent of m during the crossover, e = 0.9", 2, "≈ 2", val[k], err[k], 0.25,
        "as above, at t = " tnum(t1[k]))
    for (i = 2; i <= 3; ++i) { k = "amplitude_ratio|" E[i]
      row("same late-time amplitude of m(t) for all e: A(" E[i] ")/A(0.5)", 1, "1 (data overlap)", val[k], err[k], 0.20,
          "one common exponent (" num(val["collapse_exponent|all"]) " ± " num(err["collapse_exponent|all"]) "), one amplitude per e" win(k) " (Fig. 3)") }
    for (i = 2; i <= 3; ++i) { k = "energy_amplitude_ratio|" E[i]
      row("E(t) of all e superimpose in the ICS: B(" E[i] ")/B(0.5)", 1, "1 (data overlap)", val[k], err[k], 0.20,
          "one common exponent, one amplitude per e" win(k) " (Fig. 6)") }
    k = "lC_over_l_max_deviation|e"
    row("C(r,t) vs r/l collapses across e (late times)", 0, "collapse", val[k], err[k], 0.1,
        "largest relative difference of l_C/l (C = 1/2) between e; l from P(l_d); r_0/l (first zero) differs by up to " num(val["r0_over_l_max_deviation|e"]) " (Fig. 4)")
    k = "lC_over_l_max_deviation|time"
    row("C(r,t) vs r/l collapses across time (e = 0.9)", 0, "collapse", val[k], err[k], 0.1,
        "largest relative difference of l_C/l between the three times; r_0/l differs by up to " num(val["r0_over_l_max_deviation|time"]) " (Fig. 5)")
    for (i = 1; i <= 3; ++i) { k = "haff_t0_ratio|" E[i]
      row("before the ICS: Haff cooling, e = " E[i] " (our check)", 1, "Haff law", val[k], err[k], 0.15,
          "fitted t0 / Enskog t0 in E = E0/(1+t/t0)^2" win(k) " (Fig. 6)") }
    # 3D (Fig. 9), when its table is given: against published 3D results (docs/PHYSICS.md).
    split("0.5 0.9", E3, " ")
    for (i = 1; i <= 2; ++i) { k = "haff_t0_ratio_3d|" E3[i]; if (!(k in val)) continue
      row("3D: Haff cooling before clustering, e = " E3[i], 1,
          "t0 = 6/((1-e^2) omega0) (Brilliantov & Pöschel 2004)", val[k], err[k], 0.15,
          "fitted t0 = " num(val["haff_t0_3d|" E3[i]]) " / Enskog t0 = " num(val["haff_t0_enskog_3d|" E3[i]]) \
          " (Carnahan-Starling g)" win(k) " (Fig. 9a)") }
    for (i = 1; i <= 2; ++i) { k = "theta_3d|" E3[i]; if (!(k in val)) continue
      row("3D: E ~ t^-theta at late times, e = " E3[i], 1.2, "theta = 6/5 (Pathak et al. 2014)", val[k], err[k], 0.10,
          "power-law fit of the ensemble E(t)" win(k) " (Fig. 9a)") }
    for (i = 1; i <= 2; ++i) { k = "zeta_3d|" E3[i]; if (!(k in val)) continue
      ratio(k, "zeta|" E3[i], "", "3D: growth of m insensitive to the dimension, e = " E3[i] ": zeta(3D)/zeta(2D)", 1,
            "≈ 1 (Paul & Das 2018)", 0.20,
            "zeta(3D) = " pm(val[k], err[k]) win(k) " (Fig. 9b) over the 2D zeta of Fig. 3; largest cluster ~ t^" \
            num(val["zeta_largest_3d|" E3[i]]) ", holding " num(val["largest_fraction_3d|" E3[i]]) " of N at t_max") }
    # The ballistic aggregation model against the inelastic gas (Fig. 10), when its table is given.
    k = "hyperscaling_bam|bam"
    if (k in val) {
      row("BAM, 2D: hyperscaling 2 zeta + d theta = 2d (eq. 5)", 4, "4 (Trizac & Hansen 1995; Paul & Das 2017)",
          val[k], err[k], 0.05, "zeta = " pm(val["zeta_bam|bam"], err["zeta_bam|bam"]) win("zeta_bam|bam") \
          ", theta = " pm(val["theta_bam|bam"], err["theta_bam|bam"]) win("theta_bam|bam") " (Fig. 10)")
      row("BAM, 2D: mean-field growth m ~ t^(2d/(d+2)) (eq. 4); the paper cites simulations that find less", 1,
          "zeta = 1 (Carnevale et al. 1990)", val["zeta_bam|bam"], err["zeta_bam|bam"], 0.10,
          "power-law fit of the ensemble mean mass N0/N(t)" win("zeta_bam|bam") "; disagree here is the departure the paper reports (Fig. 10a)")
    }
    # The velocities (Fig. 11), when its table is given: the paper explains the clustering by the
    # "progressive parallelization of velocities"; the flow field carries a growing share of the energy.
    for (i = 1; i <= 3; ++i) { k = "flow_fraction_growth|" E[i]; if (!(k in val)) continue
      above("velocities parallelize progressively, e = " E[i] ": flow-field energy fraction, last snapshot / first",
            1, "grows (> 1)", val[k], err[k],
            "sum M|u|^2 / sum m|v - V|^2 of the coarse-grained flow u: " num(val["flow_fraction_early|" E[i]]) \
            " at t = " tnum(t1[k]) ", " num(val["flow_fraction_late|" E[i]]) " at t = " tnum(t2[k]) "; a2 = " \
            pm(val["a2_late|" E[i]], err["a2_late|" E[i]]) " at the end (Fig. 11a, b)") }
    for (i = 1; i <= 3; ++i) { k = "xi_over_l_growth|" E[i]; if (!(k in val)) continue
      row("the parallel-velocity domains grow with the clusters, e = " E[i] " (our check)", 1, "xi_L ~ l",
          val[k], err[k], 0.25, "ln(xi_L(t2)/xi_L(t1)) / ln(l(t2)/l(t1))" win(k) "; xi_L/l = " \
          num(val["xi_over_l_late|" E[i]]) " at t2 (Fig. 11c)") }
    for (i = 1; i <= 3; ++i) { k = "hyperscaling_gas|" E[i]; if (!(k in val)) continue
      row("inelastic gas, 2D: hyperscaling does not hold, e = " E[i] ": 2 zeta + d theta", 3.2,
          "2 x 0.6 + 2 x 1 = 3.2, not 4 (eqs. 5, 8, 9)", val[k], err[k], 0.10,
          "zeta = " pm(val["zeta_gas|" E[i]], err["zeta_gas|" E[i]]) " (Fig. 3), theta = " \
          pm(val["theta_gas|" E[i]], err["theta_gas|" E[i]]) " (Fig. 6)") }
  }' "$@"
# The finite-size section, from Fig. 8's rows (the last fits table, when given).
for f in "$@"; do
  case $f in *fig8.fits.tsv) awk -f "$(dirname "$0")/summary-finite-size.awk" "$f" ;; esac
done
