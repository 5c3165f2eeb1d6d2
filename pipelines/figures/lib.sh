# shellcheck shell=bash
# lib.sh: what the figure scripts share (sourced by figN.sh: . "$FIGSRC/lib.sh"; uses FIT, FIGSRC, OUT,
# SCALE, ERRORS, GNUPLOT from the environment Makefile.study sets).
#   figN.tsv       the plotted data: gnuplot blocks, each headed "# what it is: columns", two blank lines
#                  between blocks (gnuplot 'index')
#   figN.fits.tsv  the fitted numbers: rows  quantity e value stderr t1 t2 note  (fitrow.sh)
# Both are written as .tmp and renamed together (publish), so a failed script leaves no half table.

# block LABEL CMD [ARG ...]: one data block, the output of CMD headed "# LABEL".
gg_blocks=0
block() {
  [ "$gg_blocks" = 0 ] || printf '\n\n'
  gg_blocks=1
  printf '# %s\n' "$1"
  "${@:2}"
}

# table_block LABEL FILE.h5 DS1 DS2: block of `time DS1 DS2` (gg-fit table), e.g. a mean and its stderr.
table_block() { block "$1" "$FIT" table "$2:$3" "$2:$4"; }

# per_e_blocks "ES" "FILES" PREFIX SUFFIX DS1 DS2: one table_block per e (FILES in the order of ES),
# labelled "PREFIX, e = E, SUFFIX".
per_e_blocks() {
  local -a es files
  local i
  read -r -a es <<< "$1"; read -r -a files <<< "$2"
  for i in "${!es[@]}"; do table_block "$3, e = ${es[i]}, $4" "${files[i]}" "$5" "$6"; done
}

# haff_rows SUFFIX E HAFF.h5 ENSKOG_NOTE: rows haff_t0, haff_E0, haff_t0_enskog, haff_t0_ratio (each
# name followed by SUFFIX) of a gg-fit haff, over the window it fitted.
haff_rows() {
  local h1 h2
  h1=$("$FIT" table --no-header "$3:/fit/window" | head -1 | cut -f1)
  h2=$("$FIT" table --no-header "$3:/fit/window" | tail -1 | cut -f1)
  "$FIGSRC/fitrow.sh" "haff_t0$1" "$2" "$3" /fit/t0 /fit/t0_stderr 1 "$h1" "$h2" \
    "Haff fit E = E0/(1+t/t0)^2 over the early window"
  "$FIGSRC/fitrow.sh" "haff_E0$1" "$2" "$3" /fit/E0 /fit/E0_stderr 1 "$h1" "$h2" "E0 of that fit"
  "$FIGSRC/fitrow.sh" "haff_t0_enskog$1" "$2" "$3" /fit/t0_enskog - 1 - - "$4"
  "$FIGSRC/fitrow.sh" "haff_t0_ratio$1" "$2" "$3" /fit/t0_ratio /fit/t0_ratio_stderr 1 "$h1" "$h2" \
    "fitted t0 / Enskog t0 (1 = Haff's law with the Enskog rate)"
}

# curve_block E T CORR.h5 DOML.h5: block of the ensemble C(r,t) at the snapshot nearest T vs r and r/l.
curve_block() {
  block "e = $1, snapshot nearest t = $2, ensemble mean: r r/l C" \
    "$FIGSRC/corr.sh" curve "$3:/average/mean" "$4:/average/mean" "$2"
}

# fits_header N CONDITIONS: first line of the fits table of Fig. N whose errors come from the runs.
fits_header() {
  printf '# Fig. %s fits (SCALE=%s; %s; errors: %s over runs). Columns: quantity e value stderr t1 t2 note\n' \
    "$1" "${SCALE:-?}" "$2" "${ERRORS:-jackknife}"
}

# power_law_rows NAME E FIT.h5 SIGN T1 T2 NOTE AMPLITUDE_NOTE: rows NAME (the exponent of a gg-fit
# power-law, times SIGN) and NAME_amplitude.
power_law_rows() {
  "$FIGSRC/fitrow.sh" "$1" "$2" "$3" /fit/exponent /fit/exponent_stderr "$4" "$5" "$6" "$7"
  "$FIGSRC/fitrow.sh" "$1_amplitude" "$2" "$3" /fit/amplitude /fit/amplitude_stderr 1 "$5" "$6" "$8"
}

# ratio_rows NAME SYMBOL COLLAPSE.h5 "ES" T1 T2: one row NAME per e from a gg-fit collapse (one input per
# e, in the order of ES): the amplitude relative to the first e's at the common exponent, and whether
# they agree.
ratio_rows() {
  "$FIT" table --no-header "$3:/fit/amplitude_ratio" "$3:/fit/amplitude_ratio_stderr" "$3:/fit/agree" |
    awk -F'\t' -v OFS='\t' -v q="$1" -v a="$2" -v es="$4" -v c1="$5" -v c2="$6" '
      BEGIN { split(es, e, " ") }
      { print q, e[NR], sprintf("%.4g", $1), sprintf("%.3g", $2), c1, c2,
              a "(e)/" a "(" e[1] ") at the common exponent; gg-fit agree (2 sigma) = " $3 }'
}

# shape_fits WHAT: the rows of shape-stats.sh on stdin (one label after another: several e, or several
# times), then the largest deviation of l_C/l and of r_0/l between the labels (WHAT: e or time).
shape_fits() {
  local rows q
  rows=$(cat)
  [ -z "$rows" ] || printf '%s\n' "$rows"
  for q in lC_over_l r0_over_l; do
    awk -v q="$q" -v what="$1" -v lab="$1" -f "$FIGSRC/collapse-metric.awk" <<< "$rows"
  done
}

# fits_column FITS.tsv QUANTITY COLUMN: that column of every row of QUANTITY, space-separated (gnuplot word()).
fits_column() { awk -F'\t' -v q="$2" -v c="$3" '$1 == q { printf "%s%s", (n++ ? " " : ""), $c }' "$1"; }

# profile_column PROFILE.h5 NAME: gg-velocity's /velocity/profile/NAME, one value per line (a vector's
# components one after the other).
profile_column() {
  local tmp
  tmp=$(mktemp)
  h5dump -y -w 0 -m '%.9g' -o "$tmp" -d "/velocity/profile/$2" "$1" > /dev/null
  tr -d ' \n' < "$tmp" | tr ',' '\n'
  rm -f "$tmp"
}

# scene_value SCENE.ini KEY: the value a scene file gives KEY ("key = value" lines), empty if none.
scene_value() { awk -F'=' -v k="$2" '{ gsub(/[ \t]/, "", $1); gsub(/[ \t]/, "", $2) } $1 == k { print $2 }' "$1"; }

# publish N: figN.tsv and figN.fits.tsv from their .tmp files; publish_as NAME: NAME.tsv and NAME.fits.tsv.
publish() { publish_as "fig$1"; }
publish_as() {
  mv "$OUT/$1.tsv.tmp" "$OUT/$1.tsv"
  mv "$OUT/$1.fits.tsv.tmp" "$OUT/$1.fits.tsv"
}

# plot N 'GNUPLOT ASSIGNMENTS': figN.png and figN.svg by figN.gp, given dir, figsrc, scale and these;
# plot_as NAME '...': NAME.png and NAME.svg by NAME.gp.
plot() { plot_as "fig$1" "$2"; }
plot_as() {
  "${GNUPLOT:-gnuplot}" -e "dir='$OUT'; figsrc='$FIGSRC'; scale='${SCALE:-}'; $2" "$FIGSRC/$1.gp"
}
