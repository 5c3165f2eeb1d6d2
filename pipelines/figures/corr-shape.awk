# corr-shape.awk: C(r,t) at the snapshot nearest a requested time, scaled by the domain length l(t).
# Input files: (1) "time l" rows (gg-fit table of /domains/length or its ensemble mean),
#              (2) "time r C" rows (gg-fit table of /correlation/C or its ensemble mean).
# Variables: T = requested time, a = level for l_C (C(l_C) = a), mode = curve | shape.
#   curve: rows "r  r/l  C" at that snapshot;
#   shape: one row "t  l  l_C/l  r_0/l" (l_C: first r where C falls to a; r_0: first zero of C;
#          linear interpolation; nan when C never gets there).
BEGIN { FS = "\t"; OFS = "\t"; best = -1 }
FNR == 1 { file++ }
/^#/ || NF < 2 { next }
file == 1 {
  d = log($1 > 0 ? $1 : 1e-300) - log(T); if (d < 0) d = -d
  if (best < 0 || d < best) { best = d; tt = $1; l = $2 }
  next
}
file == 2 {
  if (($1 - tt) > 1e-9 * tt || (tt - $1) > 1e-9 * tt) next
  r = $2 + 0; c = $3
  if (mode == "curve") { print r, (l > 0 ? r / l : "nan"), c; next }
  if (c ~ /nan/) next
  c += 0
  if (n > 0) {
    if (xh == "" && c <= a && pc > a) xh = pr + (a - pc) * (r - pr) / (c - pc)
    if (x0 == "" && c <= 0 && pc > 0) x0 = pr + (0 - pc) * (r - pr) / (c - pc)
  }
  pr = r; pc = c; n++
}
END {
  if (mode == "shape") {
    if (!(l > 0)) { print tt, l, "nan", "nan"; exit }
    print tt, l, (xh == "" ? "nan" : sprintf("%.5g", xh / l)), (x0 == "" ? "nan" : sprintf("%.5g", x0 / l))
  }
}
