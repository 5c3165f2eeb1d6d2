# Uniform shear flow in 3D (pipelines/figures/effect-shear.sh): (a) the reduced shear rate and pressure
# tensor against the strain, with Grad's steady values; (b) the profiles along y: the flow against
# a (y - L/2), the density and temperature over their means. Variables: dir, figsrc, e, a, got and grad
# (a* P*_xx P*_yy P*_zz P*_xy: the run's steady means and Grad's values).
load figsrc.'/common.gp'
data = dir.'/effect-shear.tsv'
prof = dir.'/effect-shear.profile.tsv'
names = "a* P*_{xx} P*_{yy} P*_{zz} -P*_{xy}"
sign(k) = k == 5 ? -1 : 1
do for [k = 1:2] {
  eval term(k, 'effect-shear', 1200, 520)
  set multiplot layout 1, 2 title sprintf("Inelastic spheres (e = %s) in uniform shear flow, a = %s, Lees-Edwards images (SCALE=%s)", e, a, scale)
  set xlabel "strain a t"; set ylabel "reduced value"; set key outside right top
  set yrange [0:1.8]; set xrange [0:*]
  set title "(a) approach to the steady state; dashed: Grad's method"
  plot for [f = 1:5] data using 1:(sign(f) * column(f + 1)) with lines lw 1.5 lc rgb col(f) title word(names, f), \
       for [f = 1:5] sign(f) * real(word(grad, f)) with lines lw 2 dt 2 lc rgb col(f) notitle
  set autoscale xy; set key inside top left
  set xlabel "height y (diameters)"; set ylabel "mean flow u_x"; set y2label "n / <n>,  T / <T>"
  set y2range [0:2]; set y2tics; set ytics nomirror
  set title sprintf("(b) profiles: steady a* = %.3f (Grad %.3f), -P*_{xy} = %.3f (%.3f)", \
                    real(word(got, 1)), real(word(grad, 1)), -real(word(got, 5)), -real(word(grad, 5)))
  plot prof using 1:3:4 with yerrorbars lc rgb col(1) pt 7 ps 0.5 title "u_x measured", \
       prof using 1:6 with lines lw 2 dt 2 lc rgb "gray30" title "a (y - L/2)", \
       prof using 1:2 axes x1y2 with linespoints lc rgb col(2) pt 5 ps 0.4 title "n / <n>", \
       prof using 1:5 axes x1y2 with linespoints lc rgb col(3) pt 9 ps 0.4 title "T / <T>"
  unset y2tics; unset y2label; set ytics mirror
  unset multiplot
  set output
}
