# Fig. 10: the ballistic aggregation model (BAM) against the inelastic gas in 2D. (a) m(t): the BAM's
# mean mass N0/N(t) and the gas's mean cluster mass, the BAM's late power law and the mean-field
# t^(2d/(d+2)) = t; (b) E(t) of both, the BAM's late power law and t^-1. The title gives the BAM's
# 2 zeta + d theta (eq. 5: 2d = 4). Variables: dir, n, es, zb, ab, tb, bb, z1, z2, t1, t2, hb, hbs, L, scale.
load figsrc.'/common.gp'
data = dir.'/fig10.tsv'
mfit(x) = powerlaw(x, ab, zb, 1, z1, z2)
efit(x) = powerlaw(x, bb, tb, -1, t1, t2)
do for [k = 1:2] {
  eval term(k, 'fig10', 1200, 560)
  set multiplot layout 1, 2 title sprintf("Fig. 10: ballistic aggregation (rho = 0.1, L = %s) and the inelastic gas, 2D; BAM: 2{/Symbol z} + d{/Symbol q} = %s ± %s (eq. 5: 4) (SCALE=%s)", L, fmt(hb, "%.3f"), fmt(hbs, "%.2g"), scale)
  set samples 400
  set logscale xy; set format x "10^{%L}"; set format y "10^{%L}"
  set xlabel "t"; set xrange [0.1:*]
  set ylabel "m(t)"; set key top left
  set title "(a) mean mass (BAM) and mean cluster mass (gas)"
  plot data index 0 using 1:2:3 with yerrorlines lc rgb "black" pt 7 ps 0.4 title "BAM", \
       for [i = 1:n] data index (1 + i) using 1:2:3 with yerrorlines lc rgb col(i) pt 6 ps 0.4 \
         title sprintf("gas, e = %s", word(es, i)), \
       mfit(x) with lines lw 3 lc rgb "gray30" title sprintf("BAM fit: {/Symbol z} = %s", fmt(zb, "%.3f")), \
       (x > 1 ? x : 1/0) with lines lc rgb "gray50" dt 2 title "t (mean field)"
  set ylabel "E(t)"; set key bottom left
  set title "(b) energy per unit mass"
  plot data index 1 using 1:2:3 with yerrorlines lc rgb "black" pt 7 ps 0.4 title "BAM", \
       for [i = 1:n] data index (1 + n + i) using 1:2:3 with yerrorlines lc rgb col(i) pt 6 ps 0.4 \
         title sprintf("gas, e = %s", word(es, i)), \
       efit(x) with lines lw 3 lc rgb "gray30" title sprintf("BAM fit: {/Symbol q} = %s", fmt(tb, "%.3f")), \
       (x > 1 ? 1 / x : 1/0) with lines lc rgb "gray50" dt 2 title "t^{-1}"
  unset multiplot
  set output
}
