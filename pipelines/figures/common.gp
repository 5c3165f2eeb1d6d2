# Shared gnuplot settings for the study's figures (loaded by figN.gp).
set encoding utf8
set macros
col(i) = word("#0072B2 #D55E00 #009E73 #CC79A7 #E69F00 #56B4E9", i)
ok(s) = (s ne "nan" && s ne "-nan" && s ne "inf" && s ne "-inf" && s ne "")
fmt(s, d) = ok(s) ? sprintf(d, real(s)) : "n/a"
# term(k, name, w, h): the terminal of pass k of `do for [k = 1:2] { eval term(k, 'figN', w, h) ... }`:
# k = 1 -> dir/figN.png (pngcairo), k = 2 -> dir/figN.svg; both headless, w x h pixels.
term(k, name, w, h) = sprintf(k == 1 ? 'set terminal pngcairo size %d, %d enhanced font ",12"; set output ''%s.png''' \
                                     : 'set terminal svg size %d, %d enhanced font ",12" background rgb "white"; set output ''%s.svg''', \
                              w, h, dir.'/'.name)
# powerlaw(x, a, z, s, t1, t2): a fitted power law a x^(s z) (s = 1, or -1 for a decay fitted as t^-z),
# drawn over its fit window [t1, t2] only, and not at all when the fit is undefined (a or z "nan").
# a, z: fits-table strings; t1, t2: numbers or strings.
powerlaw(x, a, z, s, t1, t2) = (ok(a) && ok(z) && x >= real(t1) && x <= real(t2)) ? real(a) * x**(s * real(z)) : 1/0
