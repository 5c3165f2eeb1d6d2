# Fig. 8, the finite-size study (fig8.sh): (a) m(t) for every e and L, (b) its local exponent,
# (c) the amplitude ratios A(e)/A(first e) of m at one common exponent against 1/L with their
# extrapolation, (d) E(t), (g) the paper's length l(t), (h) the largest cluster's share of the clustered
# particles (t_g where it reaches 1/2), (e) the
# time-shift collapse q against t / c(e) and (f) the lag t_e(q)/t_first(q) against q, at the largest L
# with a shift (cL), q = cq: the paper's length l where it has one, else m. Colour = e, line style and
# point = L. Variables: dir, figsrc, scale, mlab, zlab ("i:L" per block, i = index of e), rlab (index of
# e per ratio block), nr (ratio blocks), clab and glab (index of e per collapse and lag block), llab and
# slab ("i:L" per l and share block), cL, cq,
# es, ls, verdict (the study's headline, fig8.sh's fs_verdict).
load figsrc.'/common.gp'
data = dir.'/fig8.tsv'
nm = words(mlab); nz = words(zlab); nrl = words(rlab); nc = words(clab); ng = words(glab); nl = words(llab)
ns = words(slab)
ei(s) = int(s[1:strstrt(s, ':') - 1]) + 1
Lof(s) = s[strstrt(s, ':') + 1:]
li(s) = sum [j = 1:words(ls)] (word(ls, j) eq Lof(s) ? j : 0)
lab(s) = sprintf("e = %s, L = %s", word(es, ei(s)), Lof(s))
# empty(msg): a panel that says what is missing (gnuplot refuses a plot with no defined point, and a
# logarithmic axis over [0:1]; every panel sets its own scales).
empty(msg) = sprintf('unset logscale; set format xy "%%g"; set label 99 "%s" at graph 0.5, 0.5 center; plot [0:1] [0:1] -1 notitle; unset label 99', msg)
do for [k = 1:2] {
  eval term(k, 'fig8', 2600, 1000)
  set multiplot layout 2, 4 title sprintf("Fig. 8: finite-size study, {/Symbol r} = 0.37 (SCALE=%s); e-independence of the late amplitude: %s", \
                                          scale, verdict)
  # (a) m(t)
  set logscale xy; set format x "10^{%L}"; set format y "10^{%L}"
  set xlabel "t"; set ylabel "m(t)"; set key top left font ",9"
  set title "(a) mean cluster mass"
  if (nm > 0) {
    plot for [b = 1:nm] data index (b - 1) using 1:2 with linespoints lc rgb col(ei(word(mlab, b))) \
           dt li(word(mlab, b)) pt (li(word(mlab, b)) + 5) ps 0.5 title lab(word(mlab, b)), \
         0.5 * x**0.6 with lines lc rgb "gray40" dt 2 title "t^{0.6}"
  } else { eval empty("no runs yet") }
  # (b) local exponent
  set logscale x; unset logscale y; set format x "10^{%L}"; set format y "%g"; set yrange [-0.2:2.5]
  set ylabel "d ln m / d ln t"; set title "(b) local exponent of m(t)"
  if (nz > 0) {
    plot for [b = 1:nz] data index (nm + b - 1) using 1:2 with lines lw 2 lc rgb col(ei(word(zlab, b))) \
           dt li(word(zlab, b)) title lab(word(zlab, b)), \
         0.6 with lines lc rgb "gray40" dt 2 title "0.6"
  } else { eval empty("no ensemble of 3 runs yet") }
  set yrange [*:*]
  # (c) amplitude ratios against 1/L (the extrapolated points at 1/L = 0 are open symbols)
  unset logscale x; set format x "%g"; set xlabel "1/L"; set ylabel sprintf("A(e)/A(%s)", word(es, 1))
  set title "(c) amplitude ratio of m at one common exponent, against 1/L"
  set key top right
  if (nr > 0) {
    set xrange [-0.08 / real(word(ls, 1)) : 1.15 / real(word(ls, 1))]
    plot for [b = 1:nrl] data index (nm + nz + b - 1) using 1:2:3 with yerrorlines lw 2 pt 7 \
           lc rgb col(int(word(rlab, b)) + 1) title sprintf("e = %s", word(es, int(word(rlab, b)) + 1)), \
         for [b = nrl + 1:nr] data index (nm + nz + b - 1) using 1:2:3 with yerrorbars pt 6 ps 2 lw 2 \
           lc rgb col(int(word(rlab, b - nrl)) + 1) title "L -> {/Symbol \245}", \
         1 with lines lc rgb "gray40" dt 2 title "1 (e-independent)"
    set xrange [*:*]
  } else { eval empty("no box size with all e fitted before finite size or t_g") }
  # (d) E(t)
  set logscale xy; set format x "10^{%L}"; set format y "10^{%L}"
  set xlabel "t"; set ylabel "E(t)"; set key bottom left font ",9"
  set title "(d) kinetic energy per particle"
  if (nm > 0) {
    plot for [b = 1:nm] data index (nm + nz + nr + b - 1) using 1:2 with lines lw 2 lc rgb col(ei(word(mlab, b))) \
           dt li(word(mlab, b)) title lab(word(mlab, b))
  } else { eval empty("no runs yet") }
  # (e) time-shift collapse
  set logscale xy; set format x "10^{%L}"; set format y "10^{%L}"
  set ylabel cq; set xlabel sprintf("t / c(e)   (c(%s) = 1)", word(es, 1)); set key top left font ",9"
  set title sprintf("(e) %s against t / c(e), L = %s (gg-fit shift)", cq, cL)
  if (nc > 0) {
    plot for [b = 1:nc] data index (2 * nm + nz + nr + b - 1) using 1:2 with linespoints pt 7 ps 0.5 \
           lc rgb col(int(word(clab, b)) + 1) title sprintf("e = %s", word(es, int(word(clab, b)) + 1))
  } else { eval empty("no box size with a shift yet") }
  # (f) lag against m
  set format y "%g"; set format x "%g"; set xlabel cq
  set ylabel sprintf("t_e(%s) / t_{%s}(%s)", cq, word(es, 1), cq); set key top right
  set title sprintf("(f) lag at equal %s, L = %s (flat: a constant time factor)", cq, cL)
  if (ng > 0) {
    set logscale xy
    plot for [b = 1:ng] data index (2 * nm + nz + nr + nc + b - 1) using 1:2:3 with yerrorlines pt 7 lw 2 \
           lc rgb col(int(word(glab, b)) + 1) title sprintf("e = %s", word(es, int(word(glab, b)) + 1))
  } else { eval empty("no box size with a shift yet") }
  # (g) the paper's length l(t)
  b0 = 2 * nm + nz + nr + nc + ng
  set logscale xy; set format x "10^{%L}"; set format y "%g"; set xlabel "t"; set ylabel "l(t)"; set key top left font ",9"
  set title "(g) the paper's length l(t) (first moment of the domain lengths)"
  if (nl > 0) {
    plot for [b = 1:nl] data index (b0 + b - 1) using 1:2 with linespoints lc rgb col(ei(word(llab, b))) \
           dt li(word(llab, b)) pt (li(word(llab, b)) + 5) ps 0.5 title lab(word(llab, b))
  } else { eval empty("no results with l(t) yet") }
  # (h) the largest cluster's share of the clustered particles; t_g where the mean reaches 1/2
  set logscale x; unset logscale y; set yrange [0:1]; set ylabel "largest cluster / clustered particles"
  set title "(h) the giant cluster: t_g where the share reaches 1/2"
  if (ns > 0) {
    plot for [b = 1:ns] data index (b0 + nl + b - 1) using 1:2 with lines lw 2 lc rgb col(ei(word(slab, b))) \
           dt li(word(slab, b)) title lab(word(slab, b)), \
         0.5 with lines lc rgb "gray40" dt 2 title "1/2"
  } else { eval empty("no results with the giant cluster's share yet") }
  set yrange [*:*]
  unset multiplot
  set output
}
