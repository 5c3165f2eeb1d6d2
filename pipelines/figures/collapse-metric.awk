# collapse-metric.awk: from fits-table rows of one quantity (lC_over_l or r0_over_l) for several labels
# (several e, or several times), the largest relative deviation from the first label and its error:
#   dev = max_j |x_j / x_1 - 1|, error from the two standard errors. Variables: q (quantity), what (text), lab (label written in the e column).
BEGIN { FS = "\t"; OFS = "\t" }
$1 == q && $3 !~ /nan/ { n++; nm[n] = $2; x[n] = $3; s[n] = ($4 ~ /nan/ ? 0 : $4) }
END {
  if (n < 2) { print q "_max_deviation", lab, "nan", "nan", "-", "-", "fewer than two defined values"; exit }
  best = -1
  for (j = 2; j <= n; ++j) {
    r = x[j] / x[1]; d = r - 1; if (d < 0) d = -d
    err = r * sqrt((s[j] / x[j])^2 + (s[1] / x[1])^2)
    if (d > best) { best = d; be = err; bl = nm[j] }
  }
  print q "_max_deviation", lab, sprintf("%.4g", best), sprintf("%.3g", be), "-", "-",
        "largest |x/x_ref - 1| over " what " (ref " nm[1] ", worst " bl ")"
}
