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
    printf "(± one standard error; judged on the 2-sigma intervals: \"supported\" needs every one inside 1 ± 10%%, \"rejected\" means 1 lies outside one of them, else undecided).\n"
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
                          : (tfs_how[L, e] ~ /no larger box/ ? "n/d (largest box)" : "not by t_max"), def(z[L, e]) ? pm(z[L, e], zs[L, e]) " " zw[L, e] : "n/a", ratio
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
}
