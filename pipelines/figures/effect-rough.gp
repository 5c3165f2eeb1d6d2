# Rough particles in 2D (pipelines/figures/effect-rough.sh): (a) T_tr(t) and T_rot(t) of a cooling gas
# started without rotation; (b) T_rot / T_tr against collisions per particle, with the steady ratio of
# the Maxwellian mean field as a horizontal line. Variables: dir, figsrc, e, beta, q, r (theory),
# m (the run's mean ratio over 10 to 40 collisions per particle).
load figsrc.'/common.gp'
data = dir.'/effect-rough.tsv'
do for [k = 1:2] {
  eval term(k, 'effect-rough', 1200, 520)
  set multiplot layout 1, 2 title sprintf("Rough disks (e = %s, {/Symbol b} = %s, q = %s, rho = 0.05)", e, beta, q)
  set logscale xy; set format x "10^{%L}"; set format y "10^{%L}"
  set xlabel "t"; set ylabel "temperature"; set key bottom left
  set title "(a) translational and rotational temperature"
  plot data using 1:2 with linespoints lc rgb col(1) pt 7 ps 0.4 title "T_{tr}", \
       data using 1:3 with linespoints lc rgb col(2) pt 7 ps 0.4 title "T_{rot}"
  unset logscale y; set format y "%g"
  set xlabel "collisions per particle"; set ylabel "T_{rot} / T_{tr}"; set key top right
  set xrange [0.1:*]; set yrange [0:1.2]
  set title sprintf("(b) ratio: mean over 10-40 collisions per particle %s, theory %s", fmt(m, "%.3f"), fmt(r, "%.3f"))
  plot data using 5:4 with linespoints lc rgb col(1) pt 7 ps 0.4 title "T_{rot} / T_{tr}", \
       real(r) with lines lw 2 lc rgb "gray30" dt 2 title "steady ratio, Maxwellian mean field"
  unset multiplot
  set output
}
