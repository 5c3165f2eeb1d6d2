#!/bin/bash
# fig2.sh SIM.h5 L   (called by Makefile.study)
# Paper Fig. 2: the particles of one run (e = 0.8, rho = 0.37) at the snapshot times (2.5, 20.8, 64.9, late).
# Writes $OUT/fig2.tsv (one block per snapshot: x y cluster, the particle's cluster from gg-cluster
# --particle-clusters: 0 = the largest, -1 = none), $OUT/fig2.fits.tsv (m, cluster count, largest cluster
# and its share of N at each snapshot, from gg-cluster) and $OUT/fig2.{png,svg}.
set -euo pipefail
: "${FIT:?}" "${CLUSTER:?}" "${OUT:?}" "${FIGSRC:?}"
. "$FIGSRC/lib.sh"
sim=$1 L=$2
mkdir -p "$OUT"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# shellcheck disable=SC2086
"$CLUSTER" --quiet "$sim" -o "$tmp/cluster.h5" --particle-clusters ${CLUSTER_OPTS:-}
"$FIT" table --no-header "$tmp/cluster.h5:/cluster/mean_mass" "$tmp/cluster.h5:/cluster/count" \
  "$tmp/cluster.h5:/cluster/largest" "$tmp/cluster.h5:/cluster/largest_share" > "$tmp/m.tsv"
times=$(cut -f1 "$tmp/m.tsv" | tr '\n' ' ')
nf=$(wc -l < "$tmp/m.tsv")
np=$(h5ls "$tmp/cluster.h5/cluster/particle_cluster" | sed -n 's/.*Dataset {[^,]*, *\([0-9]*\)}.*/\1/p')
{
  for ((k = 0; k < nf; ++k)); do
    [ $k = 0 ] || printf '\n\n'
    printf '# snapshot %d, t = %s: x y cluster\n' $k "$(sed -n "$((k + 1))p" "$tmp/m.tsv" | cut -f1)"
    "$FIGSRC/positions.sh" "$sim" $k > "$tmp/xy"
    h5dump -d /cluster/particle_cluster -s "$k,0" -c "1,$np" -y -w 0 -o "$tmp/cluster.txt" "$tmp/cluster.h5" > /dev/null
    tr -s ', \n' '\n' < "$tmp/cluster.txt" | awk 'NF' | paste "$tmp/xy" -
  done
} > "$tmp/fig2.tsv"
{
  printf '# Fig. 2 (SCALE=%s, L = %s, e = 0.8, rho = 0.37, T0 = 1, one run). Columns: quantity e value stderr t1 t2 note\n' "${SCALE:-?}" "$L"
  awk -F'\t' -v OFS='\t' '{ print "mean_mass", 0.8, $2, "-", $1, $1, "number-average cluster mass at this snapshot";
                            print "cluster_count", 0.8, $3, "-", $1, $1, "clusters";
                            print "largest_cluster", 0.8, $4, "-", $1, $1, "particles in the largest cluster";
                            print "largest_share", 0.8, $5, "-", $1, $1, "the largest cluster'"'"'s share of all particles" }' "$tmp/m.tsv"
} > "$tmp/fig2.fits.tsv"
mv "$tmp/fig2.tsv" "$OUT/fig2.tsv"; mv "$tmp/fig2.fits.tsv" "$OUT/fig2.fits.tsv"
plot 2 "nf=$nf; times='$times'; L=$L"
