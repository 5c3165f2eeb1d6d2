#!/bin/bash
# A snapshot as a PNG, or every snapshot as an animated GIF, of a gg-sim H5MD file (2D): each disk
# drawn to scale (diameter 1 in box units) in the periodic box, coloured by the local density
# around it, the particles in its cell of CELL x CELL diameters divided by the cell's area
# (default CELL = 4). The frames go through gg-export's extended XYZ text, so gnuplot reads them.
# Usage: render.sh GG_EXPORT IN.h5 OUT.png [FRAME (default -1, the last)]
#        render.sh GG_EXPORT IN.h5 OUT.gif            (every frame; DELAY in 1/100 s, default 40)
set -euo pipefail
[ $# -ge 3 ] || { echo "usage: render.sh GG_EXPORT IN.h5 OUT.png [FRAME] | OUT.gif" >&2; exit 2; }
export_tool=$1 in=$2 out=$3 frame=${4:--1}
cell=${CELL:-4} delay=${DELAY:-40} size=${SIZE:-900}
case $out in
  *.png) frames=(--frames "$frame"); terminal="pngcairo size $size,$size" ;;
  *.gif) frames=(); terminal="gif animate delay $delay size $size,$size optimize" ;;
  *) echo "render.sh: $out: give an output ending in .png or .gif" >&2; exit 2 ;;
esac
command -v gnuplot >/dev/null || { echo "render.sh: gnuplot is missing; apt-get install gnuplot-nox" >&2; exit 1; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/gg-render.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
"$export_tool" "$in" "${frames[@]}" --format xyz --quiet -o "$tmp/frames.xyz"

# One gnuplot data block per frame (two blank lines between): x y radius local-density; the box and
# the time of each frame in frames.meta.
awk -v cell="$cell" -v meta="$tmp/frames.meta" '
  function flush(   i) {
    for (i = 1; i <= n; i++) print x[i], y[i], 0.5, count[key[i]] / (cell * cell)
    printf "\n\n"
  }
  state == 0 { n = 0; total = $1; delete count; state = 1; next }
  state == 1 {
    match($0, /Lattice="[^"]*"/); split(substr($0, RSTART + 9, RLENGTH - 10), lat, " ")
    match($0, /Time=[^ ]*/); t = substr($0, RSTART + 5, RLENGTH - 5)
    if (lat[9] != 1) { print "render.sh: only 2D runs are drawn" > "/dev/stderr"; exit 3 }
    print lat[1], lat[5], t > meta
    state = total > 0 ? 2 : 0; if (total == 0) flush(); next
  }
  {
    n++; x[n] = $2; y[n] = $3; key[n] = int($2 / cell) "," int($3 / cell); count[key[n]]++
    if (n == total) { flush(); state = 0 }
  }' "$tmp/frames.xyz" > "$tmp/frames.dat"

frames_count=$(wc -l < "$tmp/frames.meta")
read -r Lx Ly _ < "$tmp/frames.meta"
# The colour scale is fixed over the frames, so a movie shows the clusters getting denser.
dmax=$(awk 'NF == 4 && $4 > m { m = $4 } END { print m > 0 ? m : 1 }' "$tmp/frames.dat")
gnuplot <<GP
set terminal $terminal
set output "$out"
set size ratio -1
set xrange [0:$Lx]
set yrange [0:$Ly]
set border lw 2
unset key
set tics out
set xlabel "x / sigma"
set ylabel "y / sigma"
set palette defined (0 "#2c3e91", 0.5 "#ffffbf", 1 "#b2182b")
set cbrange [0:$dmax]
set cblabel "local density (particles / sigma^2 in ${cell} x ${cell} cells)"
set style fill solid 1.0 noborder
do for [k=0:$frames_count-1] {
  t = system(sprintf("awk 'NR == %d { print \$3 }' $tmp/frames.meta", k + 1))
  set title sprintf("t = %s tau, periodic box %g x %g", t, $Lx, $Ly)
  plot "$tmp/frames.dat" index k using 1:2:3:4 with circles lc palette
}
GP
echo "render.sh: $out ($frames_count frame(s), $(head -1 "$tmp/frames.xyz") disks)"
