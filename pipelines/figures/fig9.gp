# Fig. 9: 3D hard spheres, eta = 0.288. (a) E(t) with Haff's law (fitted t0) and the late power law,
# a t^-6/5 guide; (b) m(t) (points) and the largest cluster (open points) with late power laws;
# (c) the local exponent of m(t). Variables: dir, n, es, ths, bs, t1s, t2s, t0s, e0s, zs, as, z1s, z2s,
# zls, als, L3, scale.
load figsrc.'/common.gp'
data = dir.'/fig9.tsv'
efit(x, i) = powerlaw(x, word(bs, i), word(ths, i), -1, word(t1s, i), word(t2s, i))
mfit(x, i) = powerlaw(x, word(as, i), word(zs, i), 1, word(z1s, i), word(z2s, i))
lfit(x, i) = powerlaw(x, word(als, i), word(zls, i), 1, word(z1s, i), word(z2s, i))
haff(x, i) = (ok(word(t0s, i)) && ok(word(e0s, i)) && x <= 20 * real(word(t0s, i))) \
             ? real(word(e0s, i)) / (1 + x / real(word(t0s, i)))**2 : 1/0
do for [k = 1:2] {
  eval term(k, 'fig9', 1600, 560)
  set multiplot layout 1, 3 title sprintf("Fig. 9: 3D inelastic hard spheres, {/Symbol h} = 0.288, L = %s, T_0 = 1 (SCALE=%s)", L3, scale)
  set samples 400
  set logscale xy; set format x "10^{%L}"; set format y "10^{%L}"
  set xlabel "t"; set ylabel "E(t)"; set key bottom left; set xrange [0.01:*]
  set title "(a) energy per particle"
  plot for [i = 1:n] data index (i - 1) using 1:2:3 with yerrorlines lc rgb col(i) pt 7 ps 0.4 \
         title sprintf("e = %s", word(es, i)), \
       for [i = 1:n] haff(x, i) with lines lw 1.5 dt 3 lc rgb col(i) \
         title sprintf("Haff, t_0 = %s", fmt(word(t0s, i), "%.3g")), \
       for [i = 1:n] efit(x, i) with lines lw 3 lc rgb col(i) \
         title sprintf("fit: {/Symbol q} = %s", fmt(word(ths, i), "%.2f")), \
       (x > 10 ? 2 * x**(-1.2) : 1/0) with lines lc rgb "gray40" dt 2 title "t^{-6/5}"
  set ylabel "mass"; set key top left; set xrange [0.1:*]
  set title "(b) mean cluster mass m(t) and largest cluster"
  plot for [i = 1:n] data index (n + i - 1) using 1:2:3 with yerrorlines lc rgb col(i) pt 7 ps 0.4 \
         title sprintf("m(t), e = %s", word(es, i)), \
       for [i = 1:n] data index (2 * n + i - 1) using 1:2 with linespoints lc rgb col(i) pt 6 ps 0.4 \
         title sprintf("largest, e = %s", word(es, i)), \
       for [i = 1:n] mfit(x, i) with lines lw 3 lc rgb col(i) \
         title sprintf("m fit: {/Symbol z} = %s", fmt(word(zs, i), "%.2f")), \
       for [i = 1:n] lfit(x, i) with lines lw 2 dt 4 lc rgb col(i) \
         title sprintf("largest fit: %s", fmt(word(zls, i), "%.2f"))
  unset logscale y; set format y "%g"
  set ylabel "d ln m / d ln t"; set key top left
  set title "(c) local exponent of m(t)"
  plot for [i = 1:n] data index (3 * n + i - 1) using 1:2:3 with yerrorlines lc rgb col(i) pt 7 ps 0.4 \
         title sprintf("e = %s", word(es, i)), \
       0 with lines lc rgb "gray60" notitle
  unset multiplot
  set output
}
