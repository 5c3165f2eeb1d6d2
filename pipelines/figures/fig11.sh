#!/bin/bash
# fig11.sh "ES" "FRAC..." "A2..." "XI..." "DOML..." FIELDS.h5 E_FIELDS   (called by Makefile.study)
# Fig. 11: what the velocities say about the clustering of Figs. 3-5 (gg-velocity on the same ensemble
# runs, which store their velocities): per e (a) the fraction of the kinetic energy carried by the
# coarse-grained flow field, the paper's "progressive parallelization of velocities", (b) the Sonine
# coefficient a2 of the velocity distribution, (c) the longitudinal velocity correlation length xi_L
# against the cluster length l(t) of P(l_d) (Fig. 4); (d) one snapshot (the last of run 1 at e =
# E_FIELDS): the local density beside the vorticity of the flow field, with its arrows.
# FRAC, A2, XI: gg-fit averages of /velocity/flow_energy_fraction, /velocity/a2, /velocity/length_L;
# DOML: of /domains/length; FIELDS: gg-velocity --fields --frames -1. Environment: ZETA_WINS (the late
# window per e, as Fig. 3's fits), FIELD_STRIDE (arrows every that many cells).
# Writes $OUT/fig11.tsv, $OUT/fig11.fits.tsv and $OUT/fig11.{png,svg}.
set -euo pipefail
: "${FIT:?}" "${OUT:?}" "${FIGSRC:?}" "${ZETA_WINS:?}"
. "$FIGSRC/lib.sh"
read -r -a es <<< "$1"; read -r -a frac <<< "$2"; read -r -a a2 <<< "$3"; read -r -a xi <<< "$4"
read -r -a doml <<< "$5"
fields=$6 efield=$7 stride=${FIELD_STRIDE:-8}
read -r -a wins <<< "$ZETA_WINS"
mkdir -p "$OUT"

# attr FILE NAME K: component K of the attribute NAME of /velocity.
attr() { h5dump -a "/velocity/$2" "$1" | awk -v k="$3" '/\(0\):/ { sub(/.*\(0\): */, ""); split($0, a, ", *"); print a[k]; exit }'; }

# field_rows FIELDS.h5: "x y rho_loc omega ux uy" per cell of the 2D grid (cell centres, a blank line
# after each row of cells: gnuplot's grid format), from the first frame of gg-velocity --fields.
field_rows() {
  local tmp ds nx ny hx hy
  tmp=$(mktemp -d)
  for ds in rho_loc vorticity flow; do
    h5dump -d "/velocity/$ds" -y -w 0 -o "$tmp/$ds.txt" "$1" > /dev/null
    tr -s ', \n' '\n' < "$tmp/$ds.txt" | grep -v '^$' > "$tmp/$ds.col"
  done
  nx=$(attr "$1" cells_per_side 1) ny=$(attr "$1" cells_per_side 2)
  hx=$(attr "$1" cell_spacing 1) hy=$(attr "$1" cell_spacing 2)
  awk -v nx="$nx" -v ny="$ny" -v hx="$hx" -v hy="$hy" -v OFS='\t' '
    FILENAME ~ /rho_loc/ { r[FNR - 1] = $1; next }
    FILENAME ~ /vorticity/ { w[FNR - 1] = $1; next }
    { u[FNR - 1] = $1 }
    END {
      for (c = 0; c < nx * ny; c++) {
        i = int(c / ny); j = c % ny
        print (i + 0.5) * hx, (j + 0.5) * hy, r[c], w[c], u[2 * c], u[2 * c + 1]
        if (j == ny - 1) print ""
      }
    }' "$tmp/rho_loc.col" "$tmp/vorticity.col" "$tmp/flow.col"
  rm -rf "$tmp"
}

{
  per_e_blocks "${es[*]}" "${frac[*]}" "flow-field energy fraction" \
    "ensemble mean and standard error: time fraction stderr" /average/mean /average/stderr
  per_e_blocks "${es[*]}" "${a2[*]}" "Sonine a2" "ensemble mean and standard error: time a2 stderr" \
    /average/mean /average/stderr
  for i in "${!es[@]}"; do
    block "xi_L against l, e = ${es[i]}: ensemble means: time l xi_L xi_L_stderr" \
      "$FIT" table "${doml[i]}:/average/mean" "${xi[i]}:/average/mean" "${xi[i]}:/average/stderr"
  done
  block "flow field, last snapshot of run 1, e = $efield, t = $("$FIT" table --no-header "$fields:/velocity/time" | tail -1): x y rho_loc vorticity u_x u_y" \
    field_rows "$fields"
} > "$OUT/fig11.tsv.tmp"

# Rows from the ensemble tables: the flow-field energy fraction at the last snapshot over the first
# (the growth of the "parallelization"), and the growth of xi_L against that of l over the late window:
# ln(xi(t2)/xi(t1)) / ln(l(t2)/l(t1)) at the snapshots nearest t1 and t2 (1: the velocity domains grow
# with the clusters). Errors: the standard errors of the ensemble means, in quadrature.
{
  fits_header 11 "2D rho = 0.37, as Figs. 3-5; flow field on the density grid"
  for i in "${!es[@]}"; do
    e=${es[i]} t1=${wins[i]%_*} t2=${wins[i]#*_}
    "$FIT" table --no-header "${frac[i]}:/average/mean" "${frac[i]}:/average/stderr" |
      awk -F'\t' -v OFS='\t' -v e="$e" '
        NR == 1 { t0 = $1; f0 = $2; s0 = $3 } { t = $1; f = $2; s = $3 }
        END {
          printf "flow_fraction_early\t%s\t%.6g\t%.3g\t%s\t%s\tflow-field energy fraction at the first snapshot\n", e, f0, s0, t0, t0
          printf "flow_fraction_late\t%s\t%.6g\t%.3g\t%s\t%s\tat the last snapshot\n", e, f, s, t, t
          ok = (f0 > 0 && f == f + 0)
          r = ok ? f / f0 : "nan"
          print "flow_fraction_growth", e, ok ? sprintf("%.6g", r) : "nan",
                ok ? sprintf("%.3g", r * sqrt((s / f)^2 + (s0 / f0)^2)) : "nan", t0, t,
                "late over early flow-field energy fraction (> 1: velocities parallelize)"
        }'
    "$FIT" table --no-header "${a2[i]}:/average/mean" "${a2[i]}:/average/stderr" |
      awk -F'\t' -v OFS='\t' -v e="$e" '{ t = $1; a = $2; s = $3 }
        END { print "a2_late", e, sprintf("%.6g", a), sprintf("%.3g", s), t, t, "Sonine a2 at the last snapshot" }'
    "$FIT" table --no-header "${doml[i]}:/average/mean" "${doml[i]}:/average/stderr" "${xi[i]}:/average/mean" \
      "${xi[i]}:/average/stderr" |
      awk -F'\t' -v OFS='\t' -v e="$e" -v t1="$t1" -v t2="$t2" '
        function near(t, T) { return (T > 0) ? ((t > T) ? t / T : T / t) : 1e300 }
        $2 > 0 && $4 > 0 {
          if (near($1, t1) < b1) { b1 = near($1, t1); ta = $1; la = $2; sla = $3; xa = $4; sxa = $5 }
          if (near($1, t2) < b2) { b2 = near($1, t2); tb = $1; lb = $2; slb = $3; xb = $4; sxb = $5 }
        }
        BEGIN { b1 = b2 = 1e300 }
        END {
          ok = (b1 < 1e300 && b2 < 1e300 && tb > ta && lb != la)
          g = ok ? log(lb / la) : 1
          v = ok ? log(xb / xa) / g : "nan"
          s = ok ? sqrt((sxa / xa)^2 + (sxb / xb)^2 + (v * slb / lb)^2 + (v * sla / la)^2) / (g < 0 ? -g : g) : "nan"
          print "xi_over_l_growth", e, ok ? sprintf("%.6g", v) : "nan", ok ? sprintf("%.3g", s) : "nan",
                ok ? ta : "-", ok ? tb : "-", "ln(xi_L(t2)/xi_L(t1)) / ln(l(t2)/l(t1)) at the snapshots nearest the late window"
          print "xi_over_l_late", e, ok ? sprintf("%.6g", xb / lb) : "nan", "nan", ok ? tb : "-", ok ? tb : "-",
                "xi_L / l at the end of the late window"
        }'
  done
} > "$OUT/fig11.fits.tsv.tmp"

publish 11
get() { fits_column "$OUT/fig11.fits.tsv" "$@"; }
plot 11 "n=${#es[@]}; es='${es[*]}'; efield='$efield'; stride=$stride; growth='$(get flow_fraction_growth 3)'; xig='$(get xi_over_l_growth 3)'"
