# Walls and gravity in 2D (pipelines/figures/effect-walls.sh): (a) the density profile over a thermal
# wall with the hydrostatic one of Henderson's pressure and the barometric one; (b) the temperature
# profile against the wall's temperature. Variables: dir, figsrc, Tw, g, ch and cb (each theory's chi^2
# per slab from 3 diameters up).
load figsrc.'/common.gp'
data = dir.'/effect-walls.tsv'
do for [k = 1:2] {
  eval term(k, 'effect-walls', 1200, 520)
  set multiplot layout 1, 2 title sprintf("Elastic disks over a thermal wall (T_w = %s) under gravity g = %s (SCALE=%s)", Tw, g, scale)
  set xlabel "height y (diameters)"; set ylabel "number density n"; set key top right
  set logscale y; set format y "10^{%L}"
  set title sprintf("(a) density; chi^2 per slab: Henderson hydrostatics %s, barometric %s", fmt(ch, "%.2f"), fmt(cb, "%.0f"))
  plot data using 1:($2 > 0 ? $2 : 1/0):3 with yerrorbars lc rgb col(1) pt 7 ps 0.5 title "measured", \
       data using 1:($6 > 0 ? $6 : 1/0) with lines lw 2 lc rgb col(2) title "hydrostatic, Henderson's p(n)", \
       data using 1:($7 > 0 ? $7 : 1/0) with lines lw 2 dt 2 lc rgb "gray30" title "barometric (ideal gas)"
  unset logscale y; set format y "%g"
  set ylabel "temperature T"; set yrange [0:2]
  set title "(b) temperature: the wall's at every height"
  plot data using 1:($4 == $4 ? $4 : 1/0):5 with yerrorbars lc rgb col(1) pt 7 ps 0.5 title "measured", \
       real(Tw) with lines lw 2 dt 2 lc rgb "gray30" title "T_w"
  unset multiplot
  set output
}
