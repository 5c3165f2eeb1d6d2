# Viscoelastic particles in 3D (pipelines/figures/effect-viscoelastic.sh): T(t) of a dilute cooling gas
# against the kinetic theory and the t^(-5/3) law through the theory's last point. Variables: dir, figsrc,
# K, zr and zt (the run's and the theory's late exponents), te and Te (the theory's last time and T).
load figsrc.'/common.gp'
data = dir.'/effect-viscoelastic.tsv'
do for [k = 1:2] {
  eval term(k, 'effect-viscoelastic', 800, 560)
  set title sprintf("Viscoelastic spheres (K = %s): late exponent %s, kinetic theory %s (SCALE=%s)", K, fmt(zr, "%.3f"), fmt(zt, "%.3f"), scale)
  set logscale xy; set format x "10^{%L}"; set format y "10^{%L}"
  set xlabel "t"; set ylabel "T"; set key bottom left
  plot data using 1:2 with points lc rgb col(1) pt 7 ps 0.6 title "measured", \
       data using 1:3 with lines lw 2 lc rgb col(2) title "kinetic theory (Schwager and Poschel)", \
       (x > 100 ? real(Te) * (x / real(te)) ** (-5.0 / 3) : 1/0) with lines dt 2 lc rgb "gray30" title "t^{-5/3}"
  set output
}
