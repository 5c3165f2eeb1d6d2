# fs-headline.awk -v es="E1 E2 ..." FIG8.fits.tsv   (called by fig8.sh)
# The finite-size study's headline verdict, one fits row fs_verdict, drawn from the statements of
# answer.sh: is the late growth's amplitude independent of e (q(e)/q(first e) = 1 at equal late times)?
# The word comes from the paper's length l(t) (its Fig. 4) at the largest box edge L where it has a
# verdict, else from the correlation length l_C(t), else from m(t) before the giant cluster forms
# (docs/PHYSICS.md "The answer in lengths"); the note gives every quantity's three statements at that
# L and the comparison at equal energy, so that a reader sees whether they agree.
BEGIN { FS = "\t"; OFS = "\t"; n = split("l lC m", qs, " "); pre["l"] = "fs_l_"; pre["lC"] = "fs_lC_"; pre["m"] = "fs_"
        sym["l"] = "l"; sym["lC"] = "l_C"; sym["m"] = "m (before t_g)" }
/^#/ || NF < 4 { next }
{
  for (k = 1; k <= n; ++k) {
    q = qs[k]; p = pre[q]
    if (index($1, p "statement_") != 1 || !match($1, /_L[0-9]+$/)) continue
    what = substr($1, length(p) + 11, RSTART - length(p) - 11)
    if (what !~ /^(exponent|amplitude|shift|energy)$/) continue
    L = substr($1, RSTART + 2) + 0
    v[q, L, what] = $3; note[q, L, what] = $7
    if (what == "amplitude" && known($3) && L > top[q]) top[q] = L
  }
}
function known(x) { return x == "supported" || x == "rejected" || x == "undecided" }
END {
  word = ""
  for (k = 1; k <= n && word == ""; ++k) if (top[qs[k]]) { L = top[qs[k]]; word = v[qs[k], L, "amplitude"]; from = sym[qs[k]] }
  if (word == "") { print "fs_verdict", "all", "undecided", "nan", "-", "-", "no box size has the statements of every e yet"; exit }
  best = L
  text = "L = " best "; read in " from
  for (k = 1; k <= n; ++k) {
    q = qs[k]
    if (!((q, best, "exponent") in v)) continue
    if (v[q, best, "exponent"] == "n/a" && v[q, best, "amplitude"] == "") { text = text "; " sym[q] ": not measured"; continue }
    sh = note[q, best, "shift"]; sub(/.*within errors: /, "", sh); if (v[q, best, "shift"] == "n/a") sh = "n/a"
    text = text "; " sym[q] ": (1) late exponents agree: " v[q, best, "exponent"] ", (2) equal-time amplitude = 1: " \
           (v[q, best, "amplitude"] == "" ? "n/a" : v[q, best, "amplitude"]) ", (3) one master curve: " (sh == "" ? "n/a" : sh) \
           ", at equal energy: " (v[q, best, "energy"] == "" ? "n/a" : v[q, best, "energy"])
  }
  print "fs_verdict", "all", word, "nan", best, best, text
}
