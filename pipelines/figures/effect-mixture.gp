# The mixture effect: (a) the temperatures T_1(t), T_2(t) of the two species of a binary mixture cooling
# homogeneously, (b) their ratio against Garzo & Dufty's (horizontal line). Variables: dir, figsrc, gd
# (the Garzo-Dufty ratio), e, masses.
load figsrc.'/common.gp'
data = dir.'/effect-mixture.tsv'
do for [k = 1:2] {
  eval term(k, 'effect-mixture', 1200, 520)
  set multiplot layout 1, 2 title sprintf("Binary mixture of disks cooling (e = %s, masses %s, equal radii)", e, masses)
  set logscale x; set format x "10^{%L}"; set xlabel "t"
  set logscale y; set format y "10^{%L}"; set ylabel "T_s(t)"; set key bottom left
  set title "(a) temperature of each species"
  plot data using 1:2 with linespoints lc rgb col(1) pt 7 ps 0.5 title "T_1 (species 0)", \
       data using 1:3 with linespoints lc rgb col(2) pt 5 ps 0.5 title "T_2 (species 1)"
  unset logscale y; set format y "%g"; set ylabel "T_1 / T_2"; set key top right
  set yrange [0.5:1.2]
  set title "(b) temperature ratio"
  plot data using 1:4 with linespoints lc rgb "black" pt 7 ps 0.5 title "simulation", \
       gd with lines lw 2 lc rgb col(3) dt 2 title sprintf("Garzo and Dufty (1999): %.4f", gd)
  unset multiplot
  set output
}
