# The driven gas: T(t) per e from T0 = 1 to the steady state, each with the steady temperature of the
# Enskog energy balance (dashed). Variables: dir, n, es, tts (Enskog T per e), ratios (measured/Enskog).
load figsrc.'/common.gp'
data = dir.'/effect-driven.tsv'
do for [k = 1:2] {
  eval term(k, 'effect-driven', 800, 560)
  set title sprintf("Driven gas (white noise, 2D): T(t) and the Enskog steady state, dashed (SCALE=%s)", scale)
  set logscale x; set format x "10^{%L}"
  set xlabel "t"; set ylabel "T"; set key top left; set xrange [1:*]
  plot for [i = 1:n] data index (i - 1) using 1:2 with lines lw 2 lc rgb col(i) \
         title sprintf("e = %s (T/T_{Enskog} = %s)", word(es, i), fmt(word(ratios, i), "%.3f")), \
       for [i = 1:n] real(word(tts, i)) with lines dt 2 lc rgb col(i) notitle
  set output
}
