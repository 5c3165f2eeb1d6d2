#!/bin/bash
# shape-stats.sh LABEL T CORR_RUNS DOM_RUNS   (comma-separated per-run files; needs FIT, FIGSRC, A)
# Shape of C(r,t) vs r/l at the snapshot nearest T, run by run, then mean and standard error over runs:
# prints fits-table rows  l, lC_over_l, r0_over_l  (quantity LABEL mean stderr t t note).
set -euo pipefail
label=$1 T=$2
IFS=, read -r -a cr <<< "$3"; IFS=, read -r -a dr <<< "$4"
for i in "${!cr[@]}"; do
  "$FIGSRC/corr.sh" shape "${cr[i]}:/correlation/C" "${dr[i]}:/domains/length" "$T"
done | awk -F'\t' -v OFS='\t' -v lab="$label" -v a="${A:-0.5}" '
  function stat(k, name, note,   m, s, j, n) {
    n = cnt[k]; if (n == 0) { print name, lab, "nan", "nan", t, t, note; return }
    m = sum[k] / n; s = 0
    if (n > 1) { for (j = 1; j <= n; ++j) s += (v[k, j] - m)^2; s = sqrt(s / (n - 1) / n) } else s = "nan"
    print name, lab, sprintf("%.5g", m), (s == "nan" ? s : sprintf("%.3g", s)), t, t, note " (" n " runs)"
  }
  { t = $1; for (k = 2; k <= 4; ++k) if ($k !~ /nan/) { v[k, ++cnt[k]] = $k; sum[k] += $k } }
  END {
    stat(2, "l", "domain length l = mean distance between interfaces (gg-domains), mean over runs")
    stat(3, "lC_over_l", "l_C / l, l_C = first r with C(r) = " a)
    stat(4, "r0_over_l", "r_0 / l, r_0 = first zero of C(r)")
  }'
