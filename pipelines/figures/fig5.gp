# Paper Fig. 5: C(r,t) vs r at three times (e = 0.9); inset: vs r/l. Variables: dir, n, e, ts, scale.
load figsrc.'/common.gp'
data = dir.'/fig5.tsv'
do for [k = 1:2] {
  eval term(k, 'fig5', 1000, 760)
  set multiplot
  set origin 0, 0; set size 1, 1
  set xlabel "r"; set ylabel "C(r, t)"; set xrange [0:*]; set yrange [-0.3:1.02]
  set grid; set key top right
  set title sprintf("Fig. 5: C(r,t), e = %s, {/Symbol r} = 0.37 (SCALE=%s)", e, scale)
  plot for [i = 1:n] data index (i - 1) using 1:3 with linespoints lw 2 pt 7 ps 0.4 lc rgb col(i) \
         title sprintf("t = %.4g", real(word(ts, i))), 0 with lines lc rgb "gray50" notitle
  set origin 0.45, 0.3; set size 0.5, 0.45
  unset title; unset key; unset grid
  set xlabel "r / l" offset 0, 0.5; set ylabel "C" offset 1.5, 0; set xrange [0:4]
  set object 1 rect from graph 0, 0 to graph 1, 1 behind fc rgb "white" fs solid 1.0 noborder
  plot for [i = 1:n] data index (i - 1) using 2:3 with lines lw 2 lc rgb col(i), 0 with lines lc rgb "gray50"
  unset object 1
  unset multiplot
  set output
}
