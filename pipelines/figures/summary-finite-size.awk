# summary-finite-size.awk FIG8.fits.tsv   (called by summary.sh)
# The finite-size section of figures/summary.md from Fig. 8's fits rows (fig8.sh): the headline verdict
# (fs-headline.awk: the lengths' statements first, then m before the giant cluster forms, and at equal
# energy), when the giant cluster forms and whether that grows with L, one table row per box edge L and
# e, what is complete and missing, steps in the cluster count of the long runs, the statements per
# quantity and box, the common-exponent amplitude fit of m (a model fit, not the headline) and the other
# cluster definitions.
BEGIN { FS = "\t" }
/^#/ || NF < 4 { next }
{
  q = $1; e = $2
  if (q ~ /^fs_lengths_runs_L/) lruns[substr(q, 18), e] = $3
  else if (q ~ /^fs_(tg|twrap)_L/) { split(q, parts, "_"); giant[parts[2], substr(parts[3], 2), e] = $3; giant_err[parts[2], substr(parts[3], 2), e] = $4; giant_note[parts[2], substr(parts[3], 2), e] = $7 }
  else if (q ~ /^fs_(tg|twrap)_slope$/) { split(q, parts, "_"); slope[parts[2], e] = $3; slope_err[parts[2], e] = $4; slope_note[parts[2], e] = $7 }
  else if (q ~ /^fs_(l|lC)_onset_L/) { split(q, parts, "_"); tfs_q[parts[2], substr(parts[4], 2), e] = $3; tfs_q_how[parts[2], substr(parts[4], 2), e] = $7 }
  else if (q == "fs_amplitude_fit_verdict") { fit_verdict = $3 }
  else if (q ~ /^fs_runs_L/) { L = substr(q, 10); runs[L, e] = $3; tmax[L, e] = $6; state[L, e] = $7; sub(/;.*/, "", state[L, e]); addL(L); addE(e) }
  else if (q ~ /^fs_onset_L/) { tfs[substr(q, 11), e] = $3; tfs_how[substr(q, 11), e] = $7 }
  else if (q ~ /^fs_zeta_L/) { L = substr(q, 10); z[L, e] = $3; zs[L, e] = $4; zw[L, e] = "[" tn($5) ", " tn($6) "]" }
  else if (q ~ /^fs_amplitude_ratio_L/) { L = substr(q, 21); r[L, e] = $3; rs[L, e] = $4; rw[L] = "[" tn($5) ", " tn($6) "]" }
  else if (q == "fs_amplitude_ratio_limit") { lim[e] = $3; lims[e] = $4; limv[e] = $7 }
  else if (q == "fs_amplitude_ratio_largest") { big[e] = $3; bigs[e] = $4; bigL = $5; bigv[e] = $7 }
  else if (q == "fs_verdict") { verdict = $3; vnote = $7; vL = $5 }
  else if (q == "fs_cpu_hours") cpu = $3
  else if (q == "fs_builds") { nbuilds = $3; builds = $7; gsub(/;/, ", ", builds) }
  # Longer runs beside a cell (fig8.sh, FS_LONG).
  else if (q ~ /^fs_long_runs_L/) { L = substr(q, 15); long_cell[++nLong] = L SUBSEP e; long_runs[L, e] = $3; long_tmax[L, e] = $6; long_state[L, e] = $7 }
  else if (q ~ /^fs_long_late_exponent_L/) { L = substr(q, 24); long_z[L, e] = $3; long_zs[L, e] = $4; long_w[L, e] = "[" tn($5) ", " tn($6) "]"; long_note[L, e] = $7 }
  else if (q ~ /^fs_long_onset_L/) { long_onset[substr(q, 16), e] = $3; long_onset_seen[substr(q, 16), e] = 1 }
  # Steps in the cluster count (count-steps.sh): one row per interval of a cell that runs past FS_STEP_FROM.
  else if (q ~ /^fs_count_step_verdict_L/) step_verdict[substr(q, 24), e] = $7
  else if (q ~ /^fs_count_step_L/) {
    L = substr(q, 16); if (!((L, e) in nstep)) step_cell[++nStepCells] = L SUBSEP e
    x = grab($7, "excess over the neighbouring intervals [^;]+", 39); sub(/ [+]- /, " ± ", x)
    b = grab($7, "[0-9]+ of [0-9]+ runs have a piece boundary", 0); sub(/ runs have.*/, "", b)
    step[L, e, ++nstep[L, e]] = tn($5) "-" tn($6) " | " pm($3, $4) " | " x " | " grab($7, "falls -?[0-9.]+%", 6) " | " b
  }
  # The three statements (answer.sh): per set (m of the paper's definition "fs", the lengths "l" and
  # "lC", or m of another definition's tag), L and e.
  if (q ~ /^(fs|fs_l|fs_lC|def_[^_]+)_(late_exponent|late_exponent_difference|equal_time_ratio|equal_energy_ratio|shift_factor|statement_[a-z]+|haff_time_ratio|onset_time_ratio)_L[0-9]+$/) {
    set = q ~ /^fs_lC_/ ? "lC" : q ~ /^fs_l_/ ? "l" : q ~ /^fs_/ ? "fs" : substr(q, 5, index(substr(q, 5), "_") - 1)
    rest = substr(q, set == "fs" ? 4 : set == "l" ? 6 : set == "lC" ? 7 : length(set) + 6)
    L = substr(rest, match(rest, /_L[0-9]+$/) + 2); what = substr(rest, 1, RSTART - 1)
    k = set SUBSEP L SUBSEP what SUBSEP e
    val[k] = $3; err[k] = $4; w1[k] = $5; w2[k] = $6; note[k] = $7
    if (set !~ /^(fs|l|lC)$/ && !(set in seenD)) { seenD[set] = 1; Ds[++nD] = set; defL = L }
    if (set == "fs" && what == "statement_exponent") { aL[++nA] = L }
  }
}
# The value of a statement row, and the note's verdict word in parentheses.
function get(set, L, what, e) { return val[set, L, what, e] }
function verdict_in(note_text,   m) { return match(note_text, /\((settled|still changing|collapses|does not collapse)\)/) ? substr(note_text, RSTART + 1, RLENGTH - 2) : "" }
function drift_of(note_text,   d) { if (!match(note_text, /d ln [a-zA-Z_]+ = [^;]*/)) return "n/a"; d = substr(note_text, RSTART, RLENGTH); sub(/^d ln [a-zA-Z_]+ = /, "", d); return d }
function masses(note_text) { return match(note_text, /[a-zA-Z_]+ from [^ ]+ to [^ ;]+/) ? ", " substr(note_text, RSTART, RLENGTH) : "" }
function checked_to(note_text) { return match(note_text, /checked only up to t = [0-9.e+]+/) ? substr(note_text, RSTART + 23, RLENGTH - 23) : "" }
# "rc0.4, w = 1, 4-connected" from g1w1rc0.4c4m1
function def_name(tag,   w, rc, c) {
  w = substr(tag, index(tag, "w") + 1); w = substr(w, 1, index(w, "rc") - 1)
  rc = substr(tag, index(tag, "rc") + 2); rc = substr(rc, 1, index(rc, "c") - 1)
  c = substr(tag, index(tag, "rc") + 2); c = substr(c, index(c, "c") + 1); c = substr(c, 1, index(c, "m") - 1)
  return "rho_c = " rc ", w = " w ", " c "-conn."
}
# The part of a note that matches RE, without its first SKIP characters ("n/a" if none).
function grab(note_text, re, skip) { return match(note_text, re) ? substr(note_text, RSTART + skip, RLENGTH - skip) : "n/a" }
function addL(x) { if (!(x in seenL)) { seenL[x] = 1; Ls[++nL] = x } }
function addE(x) { if (!(x in seenE)) { seenE[x] = 1; Es[++nE] = x } }
function def(x) { return x != "" && x !~ /nan|inf/ && x != "-" }
function tn(x) { return !def(x) ? "n/a" : (x + 0 >= 100 ? sprintf("%.0f", x) : sprintf("%.3g", x)) }
function pm(v, s) { return def(v) ? sprintf("%.3g", v) " ± " (def(s) ? sprintf("%.2g", s) : "n/a") : "n/a" }
function word(note) { sub(/.*verdict /, "", note); return note }
# A quantity's symbol in the text, and the onset of finite size of quantity q ("m", "l", "lC") of cell
# (a-th L, e) as the table shows it.
function qname(set) { return set == "fs" ? "m(t), before t_g" : set == "l" ? "l(t)" : set == "lC" ? "l_C(t)" : set }
function nrun(qq, L, e) { return qq == "m" ? runs[L, e] + 0 : ((L, e) in lruns ? lruns[L, e] + 0 : 0) }
function onset_text(qq, a, e,   L, t, how) {
  L = Ls[a]
  t = qq == "m" ? tfs[L, e] : tfs_q[qq, L, e]; how = qq == "m" ? tfs_how[L, e] : tfs_q_how[qq, L, e]
  if (nrun(qq, L, e) < 3) return "n/a (< 3 runs)"
  if (a < nL && nrun(qq, Ls[a + 1], e) < 3) return "n/a (< 3 runs at L = " Ls[a + 1] ")"
  if (def(t)) return tn(t) (how ~ /extrapolated/ ? " (extr.)" : "")
  if (how ~ /no larger box/) return "n/d (largest)"
  if (checked_to(how) != "") return "not by t = " checked_to(how)
  return "not by t_max"
}
function tg_text(what, L, e,   n) {
  if (!((what, L, e) in giant)) return "n/a"
  n = giant_note[what, L, e]
  if (!def(giant[what, L, e])) return match(n, /[0-9]+ of [0-9]+ runs reach it/) ? "not reached (" substr(n, RSTART, RLENGTH) ")" : "n/a"
  return pm(giant[what, L, e], giant_err[what, L, e]) (match(n, /[0-9]+ of [0-9]+ runs reach it/) ? " (" substr(n, RSTART, RLENGTH - 9) " reach)" : "")
}
# One box's statements of one quantity: a sentence and a table per e.
function statements(set, L,   i, e, k, lz, st, rr, cc, n7, chi, sym, nog) {
  sym = set == "fs" ? "m" : set == "l" ? "l" : "l_C"
  print ""
  if (get(set, L, "statement_exponent", "all") == "n/a" && get(set, L, "statement_shift", "all") == "") {
    printf "**L = %s, %s.** n/a: %s.\n", L, qname(set), note[set, L, "statement_exponent", "all"]; return
  }
  nog = ""
  if (set == "fs") for (i = 1; i <= nE; ++i) if (!def(giant["tg", L, Es[i]])) nog = nog (nog == "" ? "" : ", ") Es[i]
  printf "**L = %s, %s.**%s (1) late exponents agree: %s. (2) equal-time amplitude = 1: %s. (3) %s. Energy: %s.\n", L, qname(set),
         nog == "" ? "" : " (No t_g for e = " nog ": read up to min(t_fs, t_max).)",
         get(set, L, "statement_exponent", "all"), get(set, L, "statement_amplitude", "all"), note[set, L, "statement_shift", "all"],
         note[set, L, "statement_energy", "all"] == "" ? "n/a" : note[set, L, "statement_energy", "all"]
  print ""
  print "| e | late exponent of " sym " (window, " sym " over it) | settled? | " sym "(e)/" sym "(" Es[1] ") at equal t (window) | " sym "(e)/" sym "(" Es[1] ") at equal E (E range) | c(e) (t range) | chi^2/point (collapse, by the lag) | lag drift d ln lag/d ln " sym " | Haff-time ratio | onset-time ratio |"
  print "|---|---|---|---|---|---|---|---|---|---|"
  for (i = 1; i <= nE; ++i) {
    e = Es[i]; k = set SUBSEP L SUBSEP
    lz = pm(val[k "late_exponent" SUBSEP e], err[k "late_exponent" SUBSEP e]) " [" tn(w1[k "late_exponent" SUBSEP e]) ", " tn(w2[k "late_exponent" SUBSEP e]) "]" masses(note[k "late_exponent" SUBSEP e])
    st = verdict_in(note[k "late_exponent" SUBSEP e])
    if (i == 1) { printf "| %s | %s | %s | 1 (reference) | 1 (reference) | 1 (reference) | | | | |\n", e, lz, st; continue }
    rr = pm(val[k "equal_time_ratio" SUBSEP e], err[k "equal_time_ratio" SUBSEP e]) " [" tn(w1[k "equal_time_ratio" SUBSEP e]) ", " tn(w2[k "equal_time_ratio" SUBSEP e]) "]"
    cc = pm(val[k "shift_factor" SUBSEP e], err[k "shift_factor" SUBSEP e]) " [" tn(w1[k "shift_factor" SUBSEP e]) ", " tn(w2[k "shift_factor" SUBSEP e]) "]"
    n7 = note[k "shift_factor" SUBSEP e]; chi = n7; sub(/.*chi2 per point /, "", chi); sub(/;.*/, "", chi)
    printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", e, lz, st, rr,
           pm(val[k "equal_energy_ratio" SUBSEP e], err[k "equal_energy_ratio" SUBSEP e]) (def(val[k "equal_energy_ratio" SUBSEP e]) ? " [" tn(w1[k "equal_energy_ratio" SUBSEP e]) ", " tn(w2[k "equal_energy_ratio" SUBSEP e]) "]" : ""),
           def(val[k "shift_factor" SUBSEP e]) ? cc : "n/a",
           n7 == "" ? "n/a" : chi " (" verdict_in(n7) ")", n7 == "" ? "n/a" : drift_of(n7), tn(val[k "haff_time_ratio" SUBSEP e]),
           (k "onset_time_ratio" SUBSEP e) in val ? tn(val[k "onset_time_ratio" SUBSEP e]) : ""
  }
}
END {
  print ""
  print "## Finite-size study (Fig. 8): is cluster growth independent of e?"
  print ""
  if (verdict == "") { print "No finite-size rows (fig8.fits.tsv has none)."; exit }
  # The headline (fs-headline.awk): the word and, per quantity, its statements at that box.
  printf "**Verdict: e-independence of the late amplitude (q(e)/q(%s) = 1 at equal times) is %s**", Es[1], verdict
  if (def(vL)) {
    n = split(vnote, parts, "; ")
    printf " at the largest box where it has a verdict (L = %s), %s.", vL, parts[2]
    for (k = 3; k <= n; ++k) printf "%s%s", k == 3 ? " " : "; ", parts[k]
    print "."
  } else print ": " vnote "."
  print "Each statement at 2 sigma with Student's t of the jackknife's degrees of freedom (docs/PHYSICS.md \"Calibration of the"
  print "verdicts\"); \"supported\" needs every ratio within 1 ± 10%, \"rejected\" means 1 lies outside one interval. The lengths"
  print "are read up to their own onset of finite size; m only before t_g, when one cluster comes to hold most particles"
  print "(docs/PHYSICS.md \"The answer in lengths\")."
  # When the giant cluster forms.
  gtxt = ""
  for (i = 1; i <= nE; ++i) for (w = 1; w <= 2; ++w) {
    what = w == 1 ? "tg" : "twrap"
    if (!((what, Es[i]) in slope)) continue
    v = slope_note[what, Es[i]]; sub(/.*: /, "", v); sub(/ with x$/, " with L", v); sub(/ of x$/, " of L", v)
    gtxt = gtxt (gtxt == "" ? "" : "; ") (what == "tg" ? "t_g" : "t_wrap") "(e = " Es[i] ") ~ L^(" pm(slope[what, Es[i]], slope_err[what, Es[i]]) "): " v
  }
  print ""
  printf "**When the giant cluster forms.** t_g: the first time the largest cluster holds half of the clustered particles "
  printf "(ensemble mean of its share; ± the jackknife error); t_wrap: the first time the largest cluster wraps the box, "
  printf "the geometric mean of the runs' own times (± its standard error; n/a if a run does not wrap in its window) (gg-fit crossing). Against L: %s.\n", gtxt == "" ? "n/a (it needs two box sizes of >= 3 runs)" : gtxt
  print ""
  print "| L | e | runs | t_max | t_g | t_wrap | finite size from t = (m; l; l_C) | zeta of m (window) |"
  print "|---|---|---|---|---|---|---|---|"
  for (a = 1; a <= nL; ++a) for (i = 1; i <= nE; ++i) {
    L = Ls[a]; e = Es[i]
    printf "| %s | %s | %s | %s | %s | %s | %s; %s; %s | %s |\n", L, e, runs[L, e] ((L, e) in lruns && lruns[L, e] < runs[L, e] ? " (" lruns[L, e] " with l)" : ""),
           tmax[L, e], tg_text("tg", L, e), tg_text("twrap", L, e), onset_text("m", a, e), onset_text("l", a, e), onset_text("lC", a, e),
           def(z[L, e]) ? pm(z[L, e], zs[L, e]) " " zw[L, e] : "n/a"
  }
  print ""
  print "Finite size: a box's quantity is taken as affected from the first time it differs from the next larger box's by more"
  print "than 2 standard errors and 5% at 3 snapshots in a row (the largest box: extrapolated as a power of L from the two below it,"
  print "or not determined); every fit of it in that box ends there, m's also at t_g. Errors: jackknife over runs."
  missing = ""; complete = 0; cells = 0; nol = ""
  for (a = 1; a <= nL; ++a) for (i = 1; i <= nE; ++i) {
    ++cells
    if (state[Ls[a], Es[i]] ~ /^complete/) ++complete
    else missing = missing (missing == "" ? "" : "; ") "L = " Ls[a] ", e = " Es[i] ": " state[Ls[a], Es[i]]
    if (((Ls[a], Es[i]) in lruns) && lruns[Ls[a], Es[i]] + 0 < runs[Ls[a], Es[i]] + 0)
      nol = nol (nol == "" ? "" : "; ") "L = " Ls[a] ", e = " Es[i] ": " runs[Ls[a], Es[i]] - lruns[Ls[a], Es[i]] " of " runs[Ls[a], Es[i]]
  }
  printf "Cells complete: %d of %d (%s CPU h of simulation behind these numbers).%s%s\n", complete, cells, cpu,
         missing == "" ? "" : " Missing: " missing ".", nol == "" ? "" : " Results without l(t) and l_C(t) (made before they were kept; m only): " nol "."
  if (builds != "")
    printf "Every piece of every run was simulated by %s%s.\n", nbuilds + 0 == 1 ? "one build, " : nbuilds " builds: ", builds
  for (k = 1; k <= nLong; ++k) {
    split(long_cell[k], le, SUBSEP); L = le[1]; e = le[2]
    printf "\n**Longer runs, e = %s at L = %s:** %s runs to t = %s (%s). ", e, L, long_runs[L, e], long_tmax[L, e], long_state[L, e]
    if ((L, e) in long_z)
      if (def(long_z[L, e])) printf "Late exponent of m %s over %s (%s%s; past t_g: the fragments beside the giant). ", pm(long_z[L, e], long_zs[L, e]), long_w[L, e], verdict_in(long_note[L, e]), masses(long_note[L, e])
      else printf "Late exponent of m: n/a (%s). ", long_note[L, e]
    for (a = 1; a < nL; ++a) if (Ls[a + 1] == L && (Ls[a], e) in long_onset_seen)
      printf "L = %s departs from them %s.", Ls[a], def(long_onset[Ls[a], e]) ? "from t = " tn(long_onset[Ls[a], e]) : "at no time up to their end"
    print ""
  }
  for (k = 1; k <= nStepCells; ++k) {
    split(step_cell[k], le, SUBSEP); L = le[1]; e = le[2]
    printf "\n**Steps in the cluster count N(t), L = %s, e = %s (%s runs):** does N fall in a step the runs share, and do the pieces of resumed runs make it? Per interval between snapshots, d ln N / d ln t (mean over runs ± standard error) and its excess over the two neighbouring intervals (per run, then mean ± standard error: a shared step stands out of the runs' scatter).", L, e, runs[L, e]
    if ((L, e) in step_verdict) printf " %s.", toupper(substr(step_verdict[L, e], 1, 1)) substr(step_verdict[L, e], 2)
    print "\n\n| t | d ln N / d ln t | excess over neighbours | mean N falls | runs with a piece boundary inside |\n|---|---|---|---|---|"
    for (i = 1; i <= nstep[L, e]; ++i) print "| " step[L, e, i] " |"
  }
  if (nA > 0) {
    print ""
    print "### The statements without a common exponent, per quantity and box size"
    print ""
    print "For q = l (the paper's length, the first moment of the domain-length distribution), l_C (C(r, t) = 1/2) and m before"
    print "t_g: (1) the late exponent of q(t) over the last half-decade before each cell's end (and whether it has settled, against"
    print "the half-decade before); (2) q(e)/q(" Es[1] ") at equal times over the last half-decade all e share, against 1;"
    print "(3) the time factor c(e) with q_e(t) = q_" Es[1] "(t / c) over each e's growth range (gg-fit shift: no assumed form), whether"
    print "one master curve collapses every e within errors (neither the drift nor the curvature of the lag t_e(q)/t_" Es[1] "(q)"
    print "with q departs from 0) and whether c is a constant (the drift does not); beside c, the ratios of the Haff times and of"
    print "the onset times; q(e)/q(" Es[1] ") at equal energy E, the paper's closing question."
    for (a = 1; a <= nA; ++a) { statements("l", aL[a]); statements("lC", aL[a]); statements("fs", aL[a]) }
  }
  # The common-exponent amplitude fit of m: a model (one exponent for every e), kept for comparison.
  ratios = ""
  for (i = 2; i <= nE; ++i) if (def(big[Es[i]]))
    ratios = ratios (ratios == "" ? "" : ", ") "A(" Es[i] ")/A(" Es[1] ") = " pm(big[Es[i]], bigs[Es[i]])
  print ""
  print "### A model fit beside the statements: m = A(e) t^zeta with one exponent for every e, before t_g"
  print ""
  if (ratios == "")
    print "No box size has every e fitted over a window spanning a factor 2 before finite size or t_g: no amplitude ratio."
  else {
    printf "e-independence of A at one common exponent is %s at the largest box with every e fitted (L = %s): %s ", fit_verdict, bigL, ratios
    printf "(2 sigma, within 10%%). It assumes one exponent for every e, which statement (1) tests.\n"
    lims_txt = ""
    for (i = 2; i <= nE; ++i) if (def(lim[Es[i]]))
      lims_txt = lims_txt (lims_txt == "" ? "" : ", ") "A(" Es[i] ")/A(" Es[1] ") -> " pm(lim[Es[i]], lims[Es[i]]) " (" word(limv[Es[i]]) ")"
    if (lims_txt != "") printf "Extrapolated linearly in 1/L to 1/L = 0: %s.\n", lims_txt
    for (a = 1; a <= nL; ++a) {
      rl = ""
      for (i = 2; i <= nE; ++i) if (def(r[Ls[a], Es[i]])) rl = rl (rl == "" ? "" : ", ") "A(" Es[i] ")/A(" Es[1] ") = " pm(r[Ls[a], Es[i]], rs[Ls[a], Es[i]])
      if (rl != "") printf "L = %s over %s: %s.\n", Ls[a], rw[Ls[a]], rl
    }
  }
  if (nD == 0) exit
  print ""
  printf "### Every definition of a cluster: m before t_g (L = %s, the same runs)\n", defL
  print ""
  print "The three statements for m of the paper's definition (rho_c = 0.5, w = 1, 4-connected) and every other one; the"
  print "windows are the paper's definition's (finite size is the box's, not the definition's; t_g that of the paper's)."
  print ""
  hdr = "| definition | late z(e) |"
  for (i = 2; i <= nE; ++i) hdr = hdr " m(" Es[i] ")/m(" Es[1] ") |"
  for (i = 2; i <= nE; ++i) hdr = hdr " c(" Es[i] ") |"
  print hdr " (1) exponents agree | (2) amplitude = 1 | (3) collapse; c constant |"
  sep = "|---|---|"; for (i = 2; i <= 2 * nE - 1; ++i) sep = sep "---|"
  print sep "---|---|---|"
  Dall[1] = "fs"; for (j = 1; j <= nD; ++j) Dall[j + 1] = Ds[j]
  for (j = 1; j <= nD + 1; ++j) {
    set = Dall[j]; L = defL; zz = ""
    for (i = 1; i <= nE; ++i) zz = zz (i > 1 ? ", " : "") pm(get(set, L, "late_exponent", Es[i]), err[set, L, "late_exponent", Es[i]])
    row = "| " (set == "fs" ? "rho_c = 0.5, w = 1, 4-conn. (paper)" : def_name(set)) " | " zz " |"
    for (i = 2; i <= nE; ++i) row = row " " pm(get(set, L, "equal_time_ratio", Es[i]), err[set, L, "equal_time_ratio", Es[i]]) " |"
    for (i = 2; i <= nE; ++i) row = row " " pm(get(set, L, "shift_factor", Es[i]), err[set, L, "shift_factor", Es[i]]) " |"
    sh = note[set, L, "statement_shift", "all"]; c1 = sh; sub(/.*within errors: /, "", c1); sub(/;.*/, "", c1)
    c2 = sh; sub(/.*range of [a-zA-Z_]+: /, "", c2)
    printf "%s %s | %s | %s |\n", row, get(set, L, "statement_exponent", "all"), get(set, L, "statement_amplitude", "all"),
           get(set, L, "statement_shift", "all") == "n/a" || sh == "" ? "n/a" : c1 "; " c2
  }
}
