# Paper Fig. 7: 1D, e = 0.5, rho = 0.3, delta = 0.005. (a) E(t) with the fit and t^-2/3; (b) m(t).
# Variables: dir, th, b, e1, e2, z, a, m1, m2, scale.
load figsrc.'/common.gp'
data = dir.'/fig7.tsv'
efit(x) = powerlaw(x, b, th, -1, e1, e2)
mfit(x) = powerlaw(x, a, z, 1, m1, m2)
do for [k = 1:2] {
  eval term(k, 'fig7', 1300, 560)
  set multiplot layout 1, 2 title sprintf("Fig. 7: 1D, e = 0.5, {/Symbol r} = 0.3, {/Symbol d} = 0.005, T_0 = 1 (SCALE=%s)", scale)
  set logscale xy; set format x "10^{%L}"; set format y "10^{%L}"
  set samples 400
  set xlabel "t"; set ylabel "E(t)"; set key bottom left; set xrange [0.01:*]
  set title "(a) energy"
  plot data index 0 using 1:2:3 with yerrorlines lc rgb col(1) pt 7 ps 0.4 title "E(t)", \
       efit(x) with lines lw 3 lc rgb col(2) title sprintf("fit: {/Symbol q} = %s", fmt(th, "%.3f")), \
       (x > 10 ? 0.5 * x**(-2.0/3) : 1/0) with lines dt 2 lc rgb "gray40" title "t^{-2/3}"
  set ylabel "m(t)"; set key top left; set xrange [*:*]
  set title "(b) average cluster mass"
  plot data index 1 using 1:2:3 with yerrorlines lc rgb col(1) pt 7 ps 0.4 title "m(t)", \
       mfit(x) with lines lw 3 lc rgb col(2) title sprintf("fit: {/Symbol z} = %s", fmt(z, "%.3f")), \
       (x > 1 ? 2 * x**(2.0/3) : 1/0) with lines dt 2 lc rgb "gray40" title "t^{2/3}"
  unset multiplot
  set output
}
