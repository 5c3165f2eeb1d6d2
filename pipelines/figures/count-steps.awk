# count-steps.awk -v L=L -v e=E -v from=T   (count-steps.sh feeds it)
# Input lines: "n RUN t N" (a snapshot of run RUN: time and cluster count, in time order; every run has
# the same snapshot times) and "b RUN t" (the end of one piece of RUN, from its .info; the last one ends
# the run and is not a boundary). Output: one fits row per interval between snapshots from t = from on
# (count-steps.sh says what they hold).
BEGIN { OFS = "\t" }
$1 == "b" { nb[$2]++; bt[$2, nb[$2]] = $3; next }
$1 == "n" { if (!($2 in seen)) { seen[$2] = ++R; name[R] = $2 } r = seen[$2]; k = ++n[r]; t[r, k] = $3; N[r, k] = $4 }
function stderr_of(sum, sum2, m) { return sqrt((sum2 / m - (sum / m)^2) / (m - 1)) }
# P(|T| >= t) for Student's t with nu dof (Abramowitz & Stegun 26.7.3-4: finite sums for whole nu).
function two_sided_p(t, nu,   th, c, s, sum, term, k) {
  if (t < 0) t = -t
  th = atan2(t, sqrt(nu)); c = cos(th); s = sin(th)
  if (nu % 2 == 1) {
    sum = 0
    if (nu > 1) { sum = term = c; for (k = 3; k <= nu - 2; k += 2) { term *= c * c * (k - 1) / k; sum += term } }
    return 1 - 2 / 3.141592653589793 * (th + s * sum)
  }
  sum = term = 1
  for (k = 2; k <= nu - 2; k += 2) { term *= c * c * (k - 1) / k; sum += term }
  return 1 - s * sum
}
# The t that K tests at nu dof need for a family-wise level alpha (Bonferroni: each at alpha / K).
function threshold(alpha, K, nu,   lo, hi, mid, i) {
  lo = 0; hi = 1e4
  for (i = 0; i < 100; i++) { mid = (lo + hi) / 2; if (K * two_sided_p(mid, nu) > alpha) lo = mid; else hi = mid }
  return hi
}
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
    excess = "no neighbour on both sides"
    if (i > 1 && i + 1 < K) {
      xs = stderr_of(sx, sxx, R); excess = sprintf("excess over the neighbouring intervals %.3g +- %.2g", sx / R, xs)
      tested++; se_sum += xs; ratio_sum += log(t[1, i + 1] / t[1, i])
      if (xs > 0 && (sx / R < 0 ? -sx / R : sx / R) / xs > tmax) { tmax = (sx / R < 0 ? -sx / R : sx / R) / xs; at1 = t[1, i]; at2 = t[1, i + 1] }
    }
    print "fs_count_step_L" L, e, sprintf("%.4g", sd / R), sprintf("%.3g", stderr_of(sd, sdd, R)), sprintf("%.6g", t[1, i]),
          sprintf("%.6g", t[1, i + 1]),
          sprintf("d ln N / d ln t of the cluster count over the interval (mean of %d runs); %s; the mean count falls %.1f%%; %d of %d runs have a piece boundary inside",
                  R, excess, fall[i], inside, R)
  }
  # The verdict: the largest |excess| / error against Student t with R - 1 dof, Bonferroni over the
  # intervals tested (a family-wise level of 5% however the intervals correlate), and the smallest step
  # it would see: the threshold times the mean error, as an extra fall of the count over one interval.
  if (!tested) exit
  p = tested * two_sided_p(tmax, R - 1); if (p > 1) p = 1
  need = threshold(0.05, tested, R - 1)
  print "fs_count_step_verdict_L" L, e, sprintf("%.3g", p), "nan", sprintf("%.6g", at1), sprintf("%.6g", at2),
        sprintf("the largest |excess| / error is %.2g, over t = %.6g-%.6g, of %d intervals (Student t, %d dof; Bonferroni: family-wise p = %.2g); a step the runs share: %s; at 5%% it finds half the time a step of excess %.2g (%.2g x the mean error), an extra fall of %.0f%% over one interval",
                tmax, at1, at2, tested, R - 1, p, p < 0.05 ? "yes" : "no", need * se_sum / tested, need,
                100 * (1 - exp(-need * se_sum / tested * ratio_sum / tested)))
}
