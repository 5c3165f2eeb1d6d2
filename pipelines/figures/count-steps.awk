# count-steps.awk -v L=L -v e=E -v from=T   (count-steps.sh feeds it)
# Input lines: "n RUN t N" (a snapshot of run RUN: time and cluster count, in time order; every run has
# the same snapshot times) and "b RUN t" (the end of one piece of RUN, from its .info; the last one ends
# the run and is not a boundary). Output: one fits row per interval between snapshots from t = from on
# (count-steps.sh says what they hold).
BEGIN { OFS = "\t" }
$1 == "b" { nb[$2]++; bt[$2, nb[$2]] = $3; next }
$1 == "n" { if (!($2 in seen)) { seen[$2] = ++R; name[R] = $2 } r = seen[$2]; k = ++n[r]; t[r, k] = $3; N[r, k] = $4 }
function stderr_of(sum, sum2, m) { return sqrt((sum2 / m - (sum / m)^2) / (m - 1)) }
END {
  K = n[1]
  for (r = 2; r <= R; r++) if (n[r] < K) K = n[r]
  # d[r, i]: run r's local exponent of N over interval i (snapshots i, i + 1); fall[i]: the mean count's.
  for (i = 1; i < K; i++) {
    mN0 = 0; mN1 = 0
    for (r = 1; r <= R; r++) {
      d[r, i] = log(N[r, i + 1] / N[r, i]) / log(t[1, i + 1] / t[1, i])
      mN0 += N[r, i] / R; mN1 += N[r, i + 1] / R
    }
    fall[i] = 100 * (1 - mN1 / mN0)
  }
  for (i = 1; i < K; i++) {
    if (t[1, i] + 0 < from + 0) continue
    sd = 0; sdd = 0; sx = 0; sxx = 0; inside = 0
    for (r = 1; r <= R; r++) {
      sd += d[r, i]; sdd += d[r, i]^2
      if (i > 1 && i + 1 < K) { x = d[r, i] - (d[r, i - 1] + d[r, i + 1]) / 2; sx += x; sxx += x^2 }
      for (b = 1; b < nb[name[r]]; b++) if (bt[name[r], b] > t[1, i] && bt[name[r], b] <= t[1, i + 1]) { inside++; break }
    }
    excess = (i > 1 && i + 1 < K) ? sprintf("excess over the neighbouring intervals %.3g +- %.2g", sx / R, stderr_of(sx, sxx, R)) \
                                  : "no neighbour on both sides"
    print "fs_count_step_L" L, e, sprintf("%.4g", sd / R), sprintf("%.3g", stderr_of(sd, sdd, R)), sprintf("%.6g", t[1, i]),
          sprintf("%.6g", t[1, i + 1]),
          sprintf("d ln N / d ln t of the cluster count over the interval (mean of %d runs); %s; the mean count falls %.1f%%; %d of %d runs have a piece boundary inside",
                  R, excess, fall[i], inside, R)
  }
}
