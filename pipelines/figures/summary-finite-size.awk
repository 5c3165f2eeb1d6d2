# summary-finite-size.awk FIG8.fits.tsv   (called by summary.sh)
# The finite-size section of figures/summary.md from Fig. 8's fits rows (fig8.sh): the verdict sentence,
# computed from the rows, then one table row per box edge L and e, then what is complete and missing.
BEGIN { FS = "\t" }
/^#/ || NF < 4 { next }
{
  q = $1; e = $2
  if (q ~ /^fs_runs_L/) { L = substr(q, 10); runs[L, e] = $3; tmax[L, e] = $6; state[L, e] = $7; sub(/;.*/, "", state[L, e]); addL(L); addE(e) }
  else if (q ~ /^fs_onset_L/) { tfs[substr(q, 11), e] = $3; tfs_how[substr(q, 11), e] = $7 }
  else if (q ~ /^fs_zeta_L/) { L = substr(q, 10); z[L, e] = $3; zs[L, e] = $4; zw[L, e] = "[" tn($5) ", " tn($6) "]" }
  else if (q ~ /^fs_amplitude_ratio_L/) { L = substr(q, 21); r[L, e] = $3; rs[L, e] = $4; rw[L] = "[" tn($5) ", " tn($6) "]" }
  else if (q == "fs_amplitude_ratio_limit") { lim[e] = $3; lims[e] = $4; limv[e] = $7 }
  else if (q == "fs_amplitude_ratio_largest") { big[e] = $3; bigs[e] = $4; bigL = $5; bigv[e] = $7 }
  else if (q == "fs_verdict") { verdict = $3; vnote = $7 }
  else if (q == "fs_cpu_hours") cpu = $3
  # Longer runs beside a cell (fig8.sh, FS_LONG).
  else if (q ~ /^fs_long_runs_L/) { L = substr(q, 15); long_cell[++nLong] = L SUBSEP e; long_runs[L, e] = $3; long_tmax[L, e] = $6; long_state[L, e] = $7 }
  else if (q ~ /^fs_long_late_exponent_L/) { L = substr(q, 24); long_z[L, e] = $3; long_zs[L, e] = $4; long_w[L, e] = "[" tn($5) ", " tn($6) "]"; long_note[L, e] = $7 }
  else if (q ~ /^fs_long_onset_L/) { long_onset[substr(q, 16), e] = $3; long_onset_seen[substr(q, 16), e] = 1 }
  # The three statements (answer.sh): per set (the paper's definition "fs", or another one's tag), L and e.
  if (q ~ /^(fs|def_[^_]+)_(late_exponent|equal_time_ratio|equal_energy_ratio|shift_factor|statement_[a-z]+|haff_time_ratio|onset_time_ratio)_L[0-9]+$/) {
    set = q ~ /^fs_/ ? "fs" : substr(q, 5, index(substr(q, 5), "_") - 1)
    rest = substr(q, set == "fs" ? 4 : length(set) + 6)
    L = substr(rest, match(rest, /_L[0-9]+$/) + 2); what = substr(rest, 1, RSTART - 1)
    k = set SUBSEP L SUBSEP what SUBSEP e
    val[k] = $3; err[k] = $4; w1[k] = $5; w2[k] = $6; note[k] = $7
    if (set != "fs" && !(set in seenD)) { seenD[set] = 1; Ds[++nD] = set; defL = L }
    if (set == "fs" && what == "statement_shift") { aL[++nA] = L }
  }
}
# The value of a statement row, and the note's verdict word in parentheses.
function get(set, L, what, e) { return val[set, L, what, e] }
function verdict_in(note_text,   m) { return match(note_text, /\((settled|still changing|collapses|does not collapse)\)/) ? substr(note_text, RSTART + 1, RLENGTH - 2) : "" }
function drift_of(note_text) { return match(note_text, /d ln m = [^;]*/) ? substr(note_text, RSTART + 9, RLENGTH - 9) : "n/a" }
function masses(note_text) { return match(note_text, /m from [^ ]+ to [^ ;]+/) ? ", " substr(note_text, RSTART, RLENGTH) : "" }
function checked_to(note_text) { return match(note_text, /checked only up to t = [0-9.e+]+/) ? substr(note_text, RSTART + 23, RLENGTH - 23) : "" }
# "rc0.4, w = 1, 4-connected" from g1w1rc0.4c4m1
function def_name(tag,   w, rc, c) {
  w = substr(tag, index(tag, "w") + 1); w = substr(w, 1, index(w, "rc") - 1)
  rc = substr(tag, index(tag, "rc") + 2); rc = substr(rc, 1, index(rc, "c") - 1)
  c = substr(tag, index(tag, "rc") + 2); c = substr(c, index(c, "c") + 1); c = substr(c, 1, index(c, "m") - 1)
  return "rho_c = " rc ", w = " w ", " c "-conn."
}
function addL(x) { if (!(x in seenL)) { seenL[x] = 1; Ls[++nL] = x } }
function addE(x) { if (!(x in seenE)) { seenE[x] = 1; Es[++nE] = x } }
function def(x) { return x != "" && x !~ /nan|inf/ && x != "-" }
function tn(x) { return !def(x) ? "n/a" : (x + 0 >= 100 ? sprintf("%.0f", x) : sprintf("%.3g", x)) }
function pm(v, s) { return def(v) ? sprintf("%.3g", v) " ± " (def(s) ? sprintf("%.2g", s) : "n/a") : "n/a" }
function word(note) { sub(/.*verdict /, "", note); return note }
END {
  print ""
  print "## Finite-size study (Fig. 8): is the late-time amplitude of m(t) independent of e?"
  print ""
  if (verdict == "") { print "No finite-size rows (fig8.fits.tsv has none)."; exit }
  ratios = ""
  for (i = 2; i <= nE; ++i) if (def(big[Es[i]]))
    ratios = ratios (ratios == "" ? "" : ", ") "A(" Es[i] ")/A(" Es[1] ") = " pm(big[Es[i]], bigs[Es[i]])
  if (ratios == "")
    printf "**Verdict: undecided.** No box size yet has every e fitted before finite size sets in, so there is no amplitude ratio to judge.\n"
  else {
    printf "**Verdict: e-independence of the amplitude is %s** at the largest box with every e fitted (L = %s): %s ", verdict, bigL, ratios
    printf "(± one standard error; judged on the 2-sigma intervals, with Student's t of the jackknife's degrees of freedom: \"supported\" needs every one inside 1 ± 10%%, \"rejected\" means 1 lies outside one of them, else undecided).\n"
    lims_txt = ""
    for (i = 2; i <= nE; ++i) if (def(lim[Es[i]]))
      lims_txt = lims_txt (lims_txt == "" ? "" : ", ") "A(" Es[i] ")/A(" Es[1] ") -> " pm(lim[Es[i]], lims[Es[i]]) " (" word(limv[Es[i]]) ")"
    if (lims_txt != "") printf "Extrapolated linearly in 1/L to 1/L = 0 (an infinite box): %s.\n", lims_txt
    else printf "No extrapolation to 1/L = 0 yet (it needs ratios at two or more box sizes).\n"
  }
  print ""
  print "| L | e | runs | t_max | finite size from t = | zeta (window) | A(e)/A(" Es[1] ") (window) |"
  print "|---|---|---|---|---|---|---|"
  for (a = 1; a <= nL; ++a) for (i = 1; i <= nE; ++i) {
    L = Ls[a]; e = Es[i]
    ratio = (i == 1) ? "1 (reference)" : (def(r[L, e]) ? pm(r[L, e], rs[L, e]) " " rw[L] : "n/a")
    printf "| %s | %s | %s | %s | %s | %s | %s |\n", L, e, runs[L, e], tmax[L, e],
           runs[L, e] < 3 ? "n/a (< 3 runs)" : (a < nL && runs[Ls[a + 1], e] < 3) ? "n/a (< 3 runs at L = " Ls[a + 1] ")" : def(tfs[L, e]) ? tn(tfs[L, e]) (tfs_how[L, e] ~ /extrapolated/ ? " (extrapolated)" : "") \
                          : (tfs_how[L, e] ~ /no larger box/ ? "n/d (largest box)" : checked_to(tfs_how[L, e]) != "" ? \
                             "not by t = " checked_to(tfs_how[L, e]) " (the larger box's end)" : "not by t_max"), def(z[L, e]) ? pm(z[L, e], zs[L, e]) " " zw[L, e] : "n/a", ratio
  }
  print ""
  print "Finite size: a box's m(t) is taken as affected from the first time it differs from the next larger box's by more"
  print "than 2 standard errors and 5% at 3 snapshots in a row (the largest box: extrapolated as a power of L from the two below it,"
  print "or not determined); every fit of that box ends there. Errors: jackknife over runs."
  missing = ""; complete = 0; cells = 0
  for (a = 1; a <= nL; ++a) for (i = 1; i <= nE; ++i) {
    ++cells
    if (state[Ls[a], Es[i]] ~ /^complete/) ++complete
    else missing = missing (missing == "" ? "" : "; ") "L = " Ls[a] ", e = " Es[i] ": " state[Ls[a], Es[i]]
  }
  printf "Cells complete: %d of %d (%s CPU h of simulation behind these numbers).%s\n", complete, cells, cpu,
         missing == "" ? "" : " Missing: " missing "."
  for (k = 1; k <= nLong; ++k) {
    split(long_cell[k], le, SUBSEP); L = le[1]; e = le[2]
    printf "\n**Longer runs, e = %s at L = %s:** %s runs to t = %s (%s). ", e, L, long_runs[L, e], long_tmax[L, e], long_state[L, e]
    if ((L, e) in long_z)
      if (def(long_z[L, e])) printf "Late exponent %s over %s (%s%s). ", pm(long_z[L, e], long_zs[L, e]), long_w[L, e], verdict_in(long_note[L, e]), masses(long_note[L, e])
      else printf "Late exponent: n/a (%s). ", long_note[L, e]
    for (a = 1; a < nL; ++a) if (Ls[a + 1] == L && (Ls[a], e) in long_onset_seen)
      printf "L = %s departs from them %s.", Ls[a], def(long_onset[Ls[a], e]) ? "from t = " tn(long_onset[Ls[a], e]) : "at no time up to their end"
    print ""
  }
  if (nA == 0) exit
  print ""
  print "### The answer without a common exponent: three statements per box size"
  print ""
  print "(1) the late exponent of m(t) over the last half-decade before each cell's end (and whether it has settled, against"
  print "the half-decade before); (2) m(e)/m(" Es[1] ") at equal times over the last half-decade all e share, against 1;"
  print "(3) the time factor c(e) with m_e(t) = m_" Es[1] "(t / c) over each e's growth range (gg-fit shift: no assumed form), whether"
  print "one master curve collapses every e within errors (neither the drift nor the curvature of the lag t_e(m)/t_" Es[1] "(m)"
  print "with m departs from 0) and whether c is a constant (the drift does not); beside c, the ratios of the Haff times and of"
  print "the onset times; m(e)/m(" Es[1] ") at equal energy E. Errors: jackknife over runs; every verdict at 2 sigma with Student's"
  print "t of the jackknife's degrees of freedom, its error rates measured on synthetic truth (docs/PHYSICS.md \"Calibration of"
  print "the verdicts\")."
  for (a = 1; a <= nA; ++a) {
    L = aL[a]
    print ""
    printf "**L = %s.** (1) late exponents agree: %s. (2) equal-time amplitude = 1: %s. (3) %s. Energy: %s.\n", L,
           get("fs", L, "statement_exponent", "all"), get("fs", L, "statement_amplitude", "all"), note["fs", L, "statement_shift", "all"],
           note["fs", L, "statement_energy", "all"] == "" ? "n/a" : note["fs", L, "statement_energy", "all"]
    print ""
    print "| e | late exponent (window, m over it) | settled? | m(e)/m(" Es[1] ") at equal t (window) | m(e)/m(" Es[1] ") at equal E (E range) | c(e) (m range of t) | chi^2/point (collapse, by the lag) | lag drift d ln lag/d ln m | Haff-time ratio | onset-time ratio |"
    print "|---|---|---|---|---|---|---|---|---|---|"
    for (i = 1; i <= nE; ++i) {
      e = Es[i]; k = "fs" SUBSEP L SUBSEP
      lz = pm(val[k "late_exponent" SUBSEP e], err[k "late_exponent" SUBSEP e]) " [" tn(w1[k "late_exponent" SUBSEP e]) ", " tn(w2[k "late_exponent" SUBSEP e]) "]" masses(note[k "late_exponent" SUBSEP e])
      st = verdict_in(note[k "late_exponent" SUBSEP e])
      if (i == 1) { printf "| %s | %s | %s | 1 (reference) | 1 (reference) | 1 (reference) | | | | |\n", e, lz, st; continue }
      rr = pm(val[k "equal_time_ratio" SUBSEP e], err[k "equal_time_ratio" SUBSEP e]) " [" tn(w1[k "equal_time_ratio" SUBSEP e]) ", " tn(w2[k "equal_time_ratio" SUBSEP e]) "]"
      cc = pm(val[k "shift_factor" SUBSEP e], err[k "shift_factor" SUBSEP e]) " [" tn(w1[k "shift_factor" SUBSEP e]) ", " tn(w2[k "shift_factor" SUBSEP e]) "]"
      n7 = note[k "shift_factor" SUBSEP e]; chi = n7; sub(/.*chi2 per point /, "", chi); sub(/;.*/, "", chi)
      printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", e, lz, st, rr,
             pm(val[k "equal_energy_ratio" SUBSEP e], err[k "equal_energy_ratio" SUBSEP e]) (def(val[k "equal_energy_ratio" SUBSEP e]) ? " [" tn(w1[k "equal_energy_ratio" SUBSEP e]) ", " tn(w2[k "equal_energy_ratio" SUBSEP e]) "]" : ""),
             def(val[k "shift_factor" SUBSEP e]) ? cc : "n/a",
             n7 == "" ? "n/a" : chi " (" verdict_in(n7) ")", n7 == "" ? "n/a" : drift_of(n7), tn(val[k "haff_time_ratio" SUBSEP e]), tn(val[k "onset_time_ratio" SUBSEP e])
    }
  }
  if (nD == 0) exit
  print ""
  printf "### Every definition of a cluster (L = %s, the same runs)\n", defL
  print ""
  print "The three statements for the paper's definition (rho_c = 0.5, w = 1, 4-connected) and every other one; the"
  print "windows are the paper's definition's (finite size is the box's, not the definition's)."
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
    c2 = sh; sub(/.*range of m: /, "", c2)
    printf "%s %s | %s | %s |\n", row, get(set, L, "statement_exponent", "all"), get(set, L, "statement_amplitude", "all"),
           get(set, L, "statement_shift", "all") == "n/a" ? "n/a" : c1 "; " c2
  }
}
