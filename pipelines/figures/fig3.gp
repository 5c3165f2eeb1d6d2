# Paper Fig. 3: m(t), log-log, three e, with the late-window power-law fits and a t^0.6 guide.
# Inset: local exponent d ln m / d ln t.  Variables: dir, n, es, zs, as, t1s, t2s, scale.
load figsrc.'/common.gp'
data = dir.'/fig3.tsv'
fitline(x, i) = powerlaw(x, word(as, i), word(zs, i), 1, word(t1s, i), word(t2s, i))
do for [k = 1:2] {
  eval term(k, 'fig3', 1000, 760)
  set multiplot
  set origin 0, 0; set size 1, 1
  set logscale xy; set format x "10^{%L}"; set format y "10^{%L}"
  set xlabel "t"; set ylabel "m(t)"
  set key top left
  set title sprintf("Fig. 3: average cluster mass, {/Symbol r} = 0.37, T_0 = 1 (SCALE=%s)", scale)
  set samples 400
  plot for [i = 1:n] data index (i - 1) using 1:2:3 with yerrorlines lc rgb col(i) pt 7 ps 0.6 \
         title sprintf("e = %s", word(es, i)), \
       for [i = 1:n] fitline(x, i) with lines lw 3 lc rgb col(i) dt 1 \
         title sprintf("fit: {/Symbol z} = %s", fmt(word(zs, i), "%.2f")), \
       0.5 * x**0.6 with lines lc rgb "gray40" dt 2 title "t^{0.6}"
  # inset: local exponent
  set origin 0.55, 0.1; set size 0.42, 0.38
  unset logscale y; set format y "%g"; set yrange [-0.2:*]
  set xlabel "t" offset 0, 0.5; set ylabel "d ln m / d ln t" offset 1.5, 0
  unset title; unset key
  set object 1 rect from graph 0, 0 to graph 1, 1 behind fc rgb "white" fs solid 1.0 noborder
  plot for [i = 1:n] data index (n + i - 1) using 1:2 with lines lw 2 lc rgb col(i), \
       0.6 with lines lc rgb "gray40" dt 2
  unset object 1; set yrange [*:*]
  unset multiplot
  set output
}
