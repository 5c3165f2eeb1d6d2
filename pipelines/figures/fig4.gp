# Paper Fig. 4: C(r,t) vs r/l for the three e in the scaling regime. Variables: dir, n, es, ts, scale.
load figsrc.'/common.gp'
data = dir.'/fig4.tsv'
do for [k = 1:2] {
  eval term(k, 'fig4', 1000, 760)
  set xlabel "r / l"; set ylabel "C(r, t)"
  set xrange [0:4]; set yrange [-0.3:1.02]
  set grid; set key top right
  set title sprintf("Fig. 4: C(r,t) vs r/l, {/Symbol r} = 0.37, late times (SCALE=%s)", scale)
  plot for [i = 1:n] data index (i - 1) using 2:3 with linespoints lw 2 pt 7 ps 0.5 lc rgb col(i) \
         title sprintf("e = %s, t = %.4g", word(es, i), real(word(ts, i))), \
       0 with lines lc rgb "gray50" notitle
  set output
}
