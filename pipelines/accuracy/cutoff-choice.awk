# cutoff-choice.awk ACCURACY.tsv: which collapse cutoff the study can afford (called by table.sh).
# A cutoff passes when, against the reference cutoff on the same seeds, it moves E(t) and m(t) by less than
# 2 sigma at every sampled time and by less than 1 sigma rms over each range (the rows "E(t) max rel. dev."
# and "m(t) max rel. dev." of the cutoff knob; the rms is in their note), and no run collapses. A maximum
# over some 30 log-spaced times reaches ~2 sigma by chance alone; the rms of a real shift of the curve
# does not stay below 1. Prints one markdown paragraph: every value with pass/fail, and the cheapest that
# passes against the study's own.
BEGIN { FS = "\t" }
/^#/ || $1 == "knob" || $1 !~ /^cutoff/ { next }
{
  v = $2; sub(/ \(study\)| \(ref\)/, "", v)
  if ($2 ~ /\(ref\)/) { ref = v; next }
  if (!(v in cpu)) { order[++n] = v; cpu[v] = $4 + 0; worst[v] = 0; rms[v] = 0; bad[v] = "" }
  if ($2 ~ /\(study\)/) study = v
  if ($7 == "collapse time") { bad[v] = "runs collapse"; next }
  if ($7 !~ /max rel\. dev\./) next
  q = substr($7, 1, 4)
  s = $14 + 0; if (s < 0) s = -s
  if (s > worst[v]) { worst[v] = s; worstq[v] = q }
  r = $15; sub(/.*rms deviation in sigmas: /, "", r); r += 0
  if (r > rms[v]) { rms[v] = r; rmsq[v] = q }
  knob = $1
}
END {
  if (n == 0) exit
  best = ""
  for (i = 1; i <= n; i++) {
    v = order[i]
    if (bad[v] == "" && worst[v] >= 2) bad[v] = sprintf("%s off by %.1f sigma", worstq[v], worst[v])
    if (bad[v] == "" && rms[v] >= 1) bad[v] = sprintf("%s off by %.2g sigma rms", rmsq[v], rms[v])
    verdict = bad[v] == "" ? sprintf("passes (at most %.1f sigma, %.2g sigma rms)", worst[v], rms[v]) : "fails: " bad[v]
    list = list sprintf("%s%s, %.1f CPU s: %s", (i > 1 ? "; " : ""), v, cpu[v], verdict)
    if (bad[v] == "" && (best == "" || cpu[v] < cpu[best])) best = v
  }
  printf "\n## Choice of the cutoff\n\n"
  printf "Against %s on the same seeds (%s), a cutoff passes when it moves E(t) and m(t) by less than 2 sigma at " \
         "every time and less than 1 sigma rms in each range, and no run collapses. %s.\n", ref, knob, list
  if (best == "") { printf "\n**No cutoff passes.**\n"; exit }
  printf "\n**Cheapest that passes: %s** (%.1f CPU s", best, cpu[best]
  if (study != "" && best != study) printf "; the study's %s: %.1f CPU s, %s", study, cpu[study], (bad[study] == "" ? "passes" : "fails")
  printf ").\n"
}
