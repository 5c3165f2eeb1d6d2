# Shared gnuplot settings for the study's figures (loaded by figN.gp).
# term(k): k = 1 -> PNG (pngcairo), k = 2 -> SVG; both headless.
set encoding utf8
set macros
col(i) = word("#0072B2 #D55E00 #009E73 #CC79A7 #E69F00 #56B4E9", i)
ok(s) = (s ne "nan" && s ne "-nan" && s ne "inf" && s ne "-inf" && s ne "")
fmt(s, d) = ok(s) ? sprintf(d, real(s)) : "n/a"
