# Fig. 11: the velocities of the clustering gas. (a) the flow-field energy fraction and (b) the Sonine
# coefficient a2 against t, (c) the velocity correlation length xi_L against the cluster length l, per e;
# (d) the local density and (e) the vorticity of the flow field (arrows: u) of one late snapshot.
# Variables: dir, n, es, efield, stride, growth, xig, scale.
load figsrc.'/common.gp'
data = dir.'/fig11.tsv'
F = 3 * n  # index of the field block
do for [k = 1:2] {
  eval term(k, 'fig11', 1500, 1000)
  set multiplot layout 2, 3 title sprintf("Fig. 11: velocities, {/Symbol r} = 0.37, T_0 = 1 (SCALE=%s)", scale)
  set logscale x; set format x "10^{%L}"
  set xlabel "t"; set key top left
  set ylabel "flow-field energy fraction"
  set title "(a) {/Symbol S} M|u|^2 / {/Symbol S} m|v - V|^2"
  plot for [i = 1:n] data index (i - 1) using 1:2:3 with yerrorlines lc rgb col(i) pt 7 ps 0.4 \
         title sprintf("e = %s (late/early %s)", word(es, i), fmt(word(growth, i), "%.2f"))
  set ylabel "a_2"; set key bottom left
  set title "(b) Sonine coefficient of f(c)"
  plot for [i = 1:n] data index (n + i - 1) using 1:2:3 with yerrorlines lc rgb col(i) pt 7 ps 0.4 \
         title sprintf("e = %s", word(es, i)), 0 with lines lc rgb "gray40" dt 2 notitle
  set logscale xy; set format y "10^{%L}"
  set xlabel "cluster length l(t)"; set ylabel "{/Symbol x}_L(t)"; set key top left
  set title "(c) velocity correlation length against l"
  plot for [i = 1:n] data index (2 * n + i - 1) using 2:3:4 with yerrorlines lc rgb col(i) pt 7 ps 0.4 \
         title sprintf("e = %s (growth ratio %s)", word(es, i), fmt(word(xig, i), "%.2f")), \
       x with lines lc rgb "gray40" dt 2 title "{/Symbol x}_L = l"
  unset logscale; set format x "%g"; set format y "%g"
  set size ratio -1; set xlabel "x"; set ylabel "y"; unset key
  set title sprintf("(d) {/Symbol r}_{loc}, e = %s, last snapshot of run 1", efield)
  set palette defined (0 "white", 0.5 "#56B4E9", 1 "#0072B2")
  set autoscale xfix; set autoscale yfix
  plot data index F using 1:2:3 with image
  set title "(e) vorticity of u, arrows u"
  set palette defined (-1 "#0072B2", 0 "white", 1 "#D55E00")
  stats data index F using 4 nooutput
  wmax = (abs(STATS_min) > abs(STATS_max) ? abs(STATS_min) : abs(STATS_max))
  set cbrange [-wmax:wmax]
  stats data index F using (sqrt($5**2 + $6**2)) nooutput
  a = (STATS_max > 0 ? 2.0 * stride / STATS_max : 1)
  plot data index F using 1:2:4 with image, \
       data index F using 1:2:(a * $5):(a * $6) every stride:stride with vectors lc rgb "black" lw 0.8 head size 0.5, 20
  unset cbrange; set size noratio
  unset multiplot
  set output
}
