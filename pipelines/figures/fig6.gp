# Paper Fig. 6: E(t), log-log, three e, with late power-law fits, a t^-1 guide and Haff's law (fitted t0).
# Variables: dir, n, es, ths, bs, t1s, t2s, t0s, e0s, scale.
load figsrc.'/common.gp'
data = dir.'/fig6.tsv'
fitline(x, i) = powerlaw(x, word(bs, i), word(ths, i), -1, word(t1s, i), word(t2s, i))
haff(x, i) = (ok(word(t0s, i)) && ok(word(e0s, i)) && x <= 20 * real(word(t0s, i))) \
             ? real(word(e0s, i)) / (1 + x / real(word(t0s, i)))**2 : 1/0
do for [k = 1:2] {
  eval term(k, 'fig6', 1000, 760)
  set logscale xy; set format x "10^{%L}"; set format y "10^{%L}"
  set xlabel "t"; set ylabel "E(t)"
  set xrange [0.01:*]
  set key bottom left
  set samples 500
  set title sprintf("Fig. 6: kinetic energy per particle, {/Symbol r} = 0.37, T_0 = 1 (SCALE=%s)", scale)
  plot for [i = 1:n] data index (i - 1) using 1:2:3 with yerrorlines lc rgb col(i) pt 7 ps 0.4 \
         title sprintf("e = %s", word(es, i)), \
       for [i = 1:n] haff(x, i) with lines lw 1.5 dt 3 lc rgb col(i) \
         title sprintf("Haff, t_0 = %s", fmt(word(t0s, i), "%.3g")), \
       for [i = 1:n] fitline(x, i) with lines lw 3 lc rgb col(i) \
         title sprintf("fit: {/Symbol q} = %s", fmt(word(ths, i), "%.2f")), \
       (x > 10 ? 0.3 / x : 1/0) with lines lc rgb "gray40" dt 2 title "t^{-1}"
  set output
}
