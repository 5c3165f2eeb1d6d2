#!/bin/bash
# markdown.sh ACCURACY.tsv: the accuracy table as markdown, one table per knob (called by table.sh).
set -euo pipefail
export LC_ALL=C
awk -F'\t' '
  function num(x) { return x !~ /nan|inf|n\/a|^-?$/ }
  function pm(v, e, q) {
    if (!num(v)) return "n/a"
    if (q ~ /max/) return sprintf("%.2g%%", 100 * v) (num(e) ? sprintf(" ± %.2g%%", 100 * e) : "")
    return sprintf("%.4g", v) (num(e) ? sprintf(" ± %.2g", e) : "")
  }
  function dev(d, s, q) {
    if (!num(d)) return "n/a"
    if (q ~ /max/) return sprintf("%.2g%%", 100 * d) (num(s) ? sprintf(" (%.1f σ)", s) : "")
    return sprintf("%+.3g", d) (num(s) ? sprintf(" (%+.1f σ)", s) : "")
  }
  /^# What/ { sub(/^# /, ""); sub(/ \(make -f Makefile.study accuracy\)\. /, ".\n\n"); title = $0; next }
  /^# Reference/ { sub(/^# /, ""); ref = $0; next }
  /^# deviation/ { sub(/^# /, ""); legend = $0; next }
  /^knob\t/ {
    split(title, t, "\n"); print "# " t[1]; print ""; print "Made by `make -f Makefile.study accuracy` (pipelines/accuracy/). " t[3]; print ""
    print "**" ref "**"; print ""
    print "Every row: the CPU seconds of the simulations and analyses behind the number (user + system time of each"
    print "gg-sim, gg-cluster, gg-domains run, summed over the runs), the disk the simulations take, the number, and"
    print "its deviation from the reference named in the row. " legend; print ""
    next }
  {
    for (i = 1; i <= NF; i++) gsub(/\|/, "\\|", $i)
    if ($1 != knob) {
      knob = $1
      printf "\n## %s\n\n", knob
      print "| value | runs | CPU s (sim + analysis) | disk MB | quantity | value ± error | reference | deviation | note |"
      print "|---|---|---|---|---|---|---|---|---|"
    }
    ref = ($11 == "0" && $12 == "0" && $7 ~ /max/) ? $10 : ($10 == "-" ? "-" : $10 ": " pm($11, $12, $7))
    printf "| %s | %s | %s + %s | %s | %s | %s | %s | %s | %s |\n", $2, $3, $4, $5, $6, $7, pm($8, $9, $7), ref, dev($13, $14, $7), $15
  }' "$1"
