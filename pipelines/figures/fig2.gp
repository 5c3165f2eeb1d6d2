# Paper Fig. 2: snapshots (positions) at e = 0.8, rho = 0.37, the particles of the largest cluster (column
# 3 = 0) in red, so that the giant cluster of the late snapshot shows. Variables: dir, nf, times, L, scale.
load figsrc.'/common.gp'
data = dir.'/fig2.tsv'
ps = (L > 300 ? 0.08 : (L > 150 ? 0.15 : 0.35))
do for [k = 1:2] {
  eval term(k, 'fig2', 1200, 1240)
  set multiplot layout 2, 2 title sprintf("Fig. 2: e = 0.8, {/Symbol r} = 0.37, L = %d, T_0 = 1 (SCALE=%s); red: the largest cluster", L, scale)
  set size ratio -1
  set xrange [0:L]; set yrange [0:L]
  unset key; set tics out; set format x ""; set format y ""
  do for [f = 1:nf] {
    set title sprintf("t = %s", word(times, f))
    plot data index (f - 1) using 1:($3 == 0 ? 1/0 : $2) with points pt 7 ps ps lc rgb "black", \
         data index (f - 1) using 1:($3 == 0 ? $2 : 1/0) with points pt 7 ps ps lc rgb "#d62728"
  }
  unset multiplot
  set output
}
