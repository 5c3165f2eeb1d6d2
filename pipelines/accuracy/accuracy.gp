# accuracy.gp: the figure of `make -f Makefile.study accuracy` from accuracy.tsv (called by table.sh).
# Variables: tsv, dir, refname, e1, e2, tm, and the reference values rz rze (zeta), rth rthe (theta),
# rr rre (amplitude ratio), rl rle (l(t_max)), rzc (CPU s behind the reference zeta); coll: what the runs without cutoff did; lbase: L of the
# ensemble-size rows; rean: the re-analysis variants (table.sh: label, then value and error in % for zeta,
# theta, amplitude ratio, l); cutdir: the directory of the plot data files of table.sh (cut-E.dat, cut-m.dat,
# cutcost.dat, snaps.dat, reanalysis.dat); snapzerr: the stderr of zeta of the snapshot runs.
# Columns of accuracy.tsv: 1 knob 2 value 3 runs 4 cpu_sim 5 cpu_ana 6 disk 7 quantity 8 value 9 stderr
# 10 reference 11 ref_value 12 ref_stderr 13 deviation 14 dev_sigma 15 note
set encoding utf8
set datafile separator "\t"
set datafile missing "nan"
col(i) = word("#0072B2 #D55E00 #009E73 #CC79A7 #E69F00 #56B4E9 #000000", i)
is(k, q) = (strstrt(strcol(1), k) == 1 && strcol(7) eq q)
isq(k, q) = (strstrt(strcol(1), k) == 1 && strstrt(strcol(7), q) == 1)
# 1 for a selected row, NaN otherwise (multiply x AND y by it: rows left out must not widen the autoscale)
sel(k, q) = is(k, q) ? 1 : NaN
# t_max rows other than the base run length (that point is the R = ACC_RUNS_L / L = ACC_L point)
selt(q) = (is("t_max", q) && strcol(2) ne tm) ? 1 : NaN
selq(k, q, r) = (isq(k, q) && (strstrt(strcol(2), "ref") > 0) == r) ? 1 : NaN
cpu = '($4 + $5)'
snl(s) = (strstrt(s, "/decade") > 0 ? s[1:strstrt(s, "/decade") - 1]."/dec ".(strstrt(s, "float") > 0 ? "f" : "d") : s)
lab(s) = (strstrt(s, " (") > 0 ? s[1:strstrt(s, " (") - 1] : s)

do for [k = 1:2] {
  if (k == 1) { set terminal pngcairo size 1400, 2100 enhanced font ",11"; set output dir.'/accuracy.png' }
  if (k == 2) { set terminal svg size 1400, 2100 enhanced font ",11" background rgb "white"; set output dir.'/accuracy.svg' }
  set multiplot layout 5, 2 title sprintf("What accuracy costs in time: e = %s (and %s), {/Symbol r} = 0.37, t_{max} = %s; reference (grey band): %s", e1, e2, tm, refname) font ",13"
  set grid lc rgb "gray85"
  set logscale x; set format x "10^{%L}"
  set key top right font ",10" opaque box lc rgb "gray70"
  set xlabel "CPU seconds (simulations + analyses behind the number)"

  # (a)-(d): the study's numbers against their cost, for the ensemble size, the box and the run length
  array Q[4]; array RV[4]; array RE[4]; array YL[4]
  Q[1] = "zeta"; Q[2] = "theta"; Q[3] = "A(".e2.")/A(".e1.")"; Q[4] = "l(t=".tm.")"
  RV[1] = rz; RV[2] = rth; RV[3] = rr; RV[4] = rl
  RE[1] = rze; RE[2] = rthe; RE[3] = rre; RE[4] = rle
  YL[1] = "{/Symbol z}   (m ∝ t^{/Symbol z}, e = ".e1.")"; YL[2] = "{/Symbol q}   (E ∝ t^{-{/Symbol q}}, e = ".e1.")"
  YL[3] = "amplitude ratio A(".e2.")/A(".e1.") of m(t)"; YL[4] = "l(t = ".tm."), e = ".e1
  array PT[4]; PT[1] = "(a)"; PT[2] = "(b)"; PT[3] = "(c)"; PT[4] = "(d)"
  do for [p = 1:4] {
    set title PT[p]." ".Q[p].": value ± stderr vs CPU; labels = runs, L, t_{max}"
    set ylabel YL[p]
    set object 1 rect from graph 0, first (RV[p] - RE[p]) to graph 1, first (RV[p] + RE[p]) behind fc rgb "gray85" fs solid 0.6 noborder
    set arrow 1 from graph 0, first RV[p] to graph 1, first RV[p] nohead lc rgb "gray40" lw 2 back
    plot NaN with lines lc rgb "gray40" lw 2 title "reference ± stderr", \
         tsv using (@cpu * sel("runs", Q[p])):($8 * sel("runs", Q[p])):9 with yerrorbars pt 7 ps 1.1 lc rgb col(1) title "runs R (L = ".lbase.")", \
         '' using (@cpu * sel("runs", Q[p])):($8 * sel("runs", Q[p])):("R=".strcol(2)) with labels offset char -0.6, 0.8 right font ",9" tc rgb col(1) notitle, \
         '' using (@cpu * sel("box", Q[p])):($8 * sel("box", Q[p])):9 with yerrorbars pt 5 ps 1.1 lc rgb col(2) title "box L", \
         '' using (@cpu * sel("box", Q[p])):($8 * sel("box", Q[p])):("L=".lab(strcol(2))) with labels offset char 0.6, -0.7 left font ",9" tc rgb col(2) notitle, \
         '' using (@cpu * selt(Q[p])):($8 * selt(Q[p])):9 with yerrorbars pt 9 ps 1.3 lc rgb col(3) title "t_{max} (fit to t_{max})", \
         '' using (@cpu * selt(Q[p])):($8 * selt(Q[p])):("t=".strcol(2)) with labels offset char 0.6, 0.7 left font ",9" tc rgb col(3) notitle
    unset object 1; unset arrow 1
  }

  # (e), (f): how far the cutoffs move E(t) and m(t) (ensemble curves against the smallest t_c, same seeds)
  array CQ[2]; CQ[1] = "E"; CQ[2] = "m"
  array CT[2]; CT[1] = "(e) cutoffs: E(t) against the smallest t_c (grey: its stderr); key: CPU s of the runs"
  CT[2] = "(f) cutoffs: m(t) against the smallest t_c (grey: its stderr)"
  do for [p = 1:2] {
    f = cutdir.'/cut-'.CQ[p].'.dat'
    stats f using 1 nooutput
    nb = STATS_blocks
    set title CT[p]
    set xlabel "t"; set ylabel "100 (".CQ[p]."(t) / ".CQ[p]."_{ref}(t) - 1)   (%)"
    set yrange [-100:150]
    set key top left font ",9" maxrows 4
    plot f index 0 using 1:2:3 with filledcurves fc rgb "gray80" fs solid 0.7 title "reference ± stderr", \
         for [i = 1:nb - 1] f index i using 1:2 with linespoints pt 7 ps 0.5 lw 1.5 lc rgb col(i) title columnheader(1), \
         0 with lines lc rgb "gray40" notitle
    set yrange [*:*]
  }
  set key top right font ",10"

  # (g) what the cutoffs cost (CPU of all runs) and what the runs without cutoff did
  unset logscale x; set format x "%g"
  set logscale y; set format y "%g"
  set xlabel ""; set ylabel "CPU seconds (all runs)"
  set title "(g) cutoffs at e = ".e1.": CPU s of the runs (to t = ".tm.", or to the collapse)"
  set xtics rotate by 25 right font ",9" nomirror
  set style fill solid 0.6 border lc rgb "gray30"; set boxwidth 0.6
  set yrange [0.1:*]; set xrange [-0.6:*]; set offsets 0, 0.6, 0, 0
  plot cutdir.'/cutcost.dat' using 0:2:xtic(1) with boxes lc rgb col(6) notitle, \
       '' using 0:2:(sprintf("%.0f s", $2)) with labels offset 0, 0.7 font ",9" notitle, \
       '' using 0:(0.3):3 with labels left rotate by 90 offset 0, 0 font ",9" tc rgb col(2) notitle
  set yrange [*:*]; set xrange [*:*]; set offsets 0, 0, 0, 0
  unset logscale y

  # (h) snapshots: disk per run (bars) and the change of zeta (points, right axis)
  set title sprintf("(h) snapshots per decade, float/double (*: study): disk per run, CPU s, change of {/Symbol z}\n(same runs; the stderr of {/Symbol z} itself is %s)", snapzerr)
  set ylabel "disk per run (MB)"; set y2label "{/Symbol z} - {/Symbol z}_{ref}  (same runs)"
  set y2tics; set ytics nomirror
  set xrange [-0.6:*]; set offsets 0, 0.6, graph 0.12, 0; set yrange [0:*]
  set key top center maxrows 2
  plot cutdir.'/snaps.dat' using 0:2:xtic(1) with boxes lc rgb col(4) title "disk per run (MB)", \
       '' using 0:2:(sprintf("%.0f s", $5)) with labels offset 0, 0.7 font ",9" notitle, \
       '' using 0:3 axes x1y2 with points pt 7 ps 1.4 lc rgb col(2) title "{/Symbol z} - {/Symbol z}_{ref} (right axis)", \
       0 axes x1y2 with lines lc rgb "gray40" dt 2 notitle
  unset y2tics; unset y2label; set ytics mirror; set yrange [*:*]
  set xtics norotate font ",11" mirror; set xrange [*:*]; set offsets 0, 0, 0, 0
  set style fill solid 0.6 noborder

  # (g) analysis choices on the reference runs: relative change of zeta, theta, ratio and l (file rean)
  unset logscale x; set format x "%g"
  set xlabel ""
  set ylabel "change from the reference (%)"
  set title "(i) re-analysis of the reference runs: coarse-graining and fit window (change of each number)"
  set xtics rotate by 25 right font ",9" nomirror
  set xrange [-0.6:*]; set offsets 0, 0.6, 0, 0
  set key top left
  plot rean using ($0 - 0.15):2:3:xtic(1) with yerrorbars pt 7 ps 1.1 lc rgb col(1) title "{/Symbol z}", \
       '' using ($0 - 0.05):4:5 with yerrorbars pt 9 ps 1.2 lc rgb col(3) title "{/Symbol q}", \
       '' using ($0 + 0.05):6:7 with yerrorbars pt 5 ps 1.1 lc rgb col(2) title "A(".e2.")/A(".e1.")", \
       '' using ($0 + 0.15):8:9 with yerrorbars pt 13 ps 1.2 lc rgb col(4) title "l(t_{max})", \
       0 with lines lc rgb "gray40" notitle
  set xtics norotate font ",11" mirror; set xrange [*:*]; set offsets 0, 0, 0, 0

  # (h) statistical error vs CPU
  set logscale xy; set format x "10^{%L}"; set format y "%g"
  set xlabel "CPU seconds (simulations + analyses behind the number)"
  set ylabel "standard error"
  set title "(j) the price of a digit: stderr of {/Symbol z} and {/Symbol q} vs CPU (runs R, box L)"
  set key default; set key bottom left font ",10" opaque box lc rgb "gray70"
  guide(x) = rze * sqrt(rzc / x)
  plot guide(x) with lines lc rgb "gray50" dt 3 title "∝ CPU^{-1/2} through the reference {/Symbol z}", \
       tsv using (@cpu * sel("runs", "zeta")):($9 * sel("runs", "zeta")) with linespoints pt 7 ps 1.1 lc rgb col(1) title "{/Symbol z}, runs R (L = ".lbase.")", \
       '' using (@cpu * sel("box", "zeta")):($9 * sel("box", "zeta")) with linespoints pt 5 ps 1.1 lc rgb col(2) title "{/Symbol z}, box L", \
       '' using (@cpu * sel("runs", "theta")):($9 * sel("runs", "theta")) with linespoints pt 6 ps 1.1 dt 2 lc rgb col(1) title "{/Symbol q}, runs R (L = ".lbase.")", \
       '' using (@cpu * sel("box", "theta")):($9 * sel("box", "theta")) with linespoints pt 4 ps 1.1 dt 2 lc rgb col(2) title "{/Symbol q}, box L", \
       '' using (@cpu * sel("box", "zeta")):($9 * sel("box", "zeta")):(lab(strcol(2))) with labels offset char 0.6, -0.7 left font ",9" tc rgb col(2) notitle
  unset logscale y
  unset multiplot
  set output
}
