#!/bin/bash
# collect.sh SIM.h5 RESULT.h5   (called by finite-size.mk; from the environment CLUSTER, CLUSTER_OPTS and, for
# every analysis, CORRELATE, DOMAINS, VELOCITY with CORRELATE_OPTS, DOMAINS_OPTS, VELOCITY_OPTS)
# The small per-run result of the finite-size study, all that fig8 and the lengths' answer read:
# gg-cluster's output for the run (/cluster: m(t), weight-average mass, count, the largest cluster, its
# share of the particles and whether it wraps the box, the rest's mean mass; /parameters/provenance with
# the run's own provenance as an input), and copied from the simulation its E(t)
# (/observables/kinetic_energy) and gg-sim's provenance (/simulation/provenance). With CORRELATE, DOMAINS
# and VELOCITY set (the paper's cluster definition; the others take the clusters only), every other
# analysis of the run too, so that the next question needs no new simulation: /correlation (C(r,t), l_C,
# k1), /domains (l(t), the domain count), /velocity (T, a2, a3, the flow's energy fraction and lengths,
# the enstrophy), each with its tool's /parameters as <group>/parameters. Compressed (gzip).
# Beside it, RESULT.info: tab-separated "key value" lines
set -euo pipefail
sim=${1:?usage: collect.sh SIM.h5 RESULT.h5} out=${2:?usage: collect.sh SIM.h5 RESULT.h5}
: "${CLUSTER:?set CLUSTER to the gg-cluster binary}"
me=collect.sh
[ -e "$sim" ] || { echo "$me: no simulation $sim; run it first (make -f Makefile.study finite-size-sims)" >&2; exit 1; }
if [ -e "$sim.checkpoint.h5" ]; then
  echo "$me: $sim is unfinished (its checkpoint $sim.checkpoint.h5 is there); resume it before collecting" >&2
  exit 1
fi
part=${out%.h5}.part.h5
rm -f "$part"
trap 'rm -f "$part" "$out.info.tmp"' EXIT
# shellcheck disable=SC2086  # CLUSTER_OPTS is a list of flags
"$CLUSTER" --quiet "$sim" -o "$part" ${CLUSTER_OPTS:-}
h5copy -p -i "$sim" -o "$part" -s /observables/kinetic_energy -d /observables/kinetic_energy
h5copy -p -i "$sim" -o "$part" -s /parameters/provenance -d /simulation/provenance
# analysis TOOL GROUP "OPTIONS" DATASET...: the tool's output for the run, of which GROUP's DATASETs (and
# the tool's /parameters, as GROUP/parameters) go into the result.
analysis() {
  local tool=$1 group=$2 opts=$3 tmp=${out%.h5}.$2.part.h5 d; shift 3
  # shellcheck disable=SC2086  # a list of flags
  "$tool" --quiet "$sim" -o "$tmp" $opts
  for d in "$@"; do h5copy -p -i "$tmp" -o "$part" -s "/$group/$d" -d "/$group/$d"; done
  h5copy -p -i "$tmp" -o "$part" -s /parameters -d "/$group/parameters"
  rm -f "$tmp"
}
if [ -n "${CORRELATE:-}" ]; then
  : "${DOMAINS:?set DOMAINS with CORRELATE}" "${VELOCITY:?set VELOCITY with CORRELATE}"
  trap 'rm -f "$part" "$out.info.tmp" "${out%.h5}".*.part.h5' EXIT
  analysis "$CORRELATE" correlation "${CORRELATE_OPTS:-}" time step length k1 r C
  analysis "$DOMAINS" domains "${DOMAINS_OPTS:-}" time step length count
  analysis "$VELOCITY" velocity "${VELOCITY_OPTS:-}" time step temperature a2 a2_stderr a3 a3_stderr \
    flow_energy_fraction length_L length_T enstrophy
  h5repack -f GZIP=6 "$part" "$part.z" && mv "$part.z" "$part"
fi
# attr NAME: an attribute of the simulation's /parameters as text (array elements space-separated).
attr() {
  h5dump -a "/parameters/$1" "$sim" | awk '/DATA \{/ { on = 1; next } on && /^ *\}/ { exit }
    on { sub(/^ *\([0-9]+\): */, ""); gsub(/"/, ""); gsub(/, *$/, ""); gsub(/", "/, " "); printf "%s%s", (n++ ? " " : ""), $0 }'
}
# piece FIELD: one line per piece of the run (gg-sim's /parameters/provenance/pieces, whose text fields are
# attributes and numbers datasets).
piece() {
  local at=/parameters/provenance/pieces/$1
  { h5dump -a "$at" "$sim" 2>/dev/null || h5dump -d "$at" "$sim"; } | awk '/DATA \{/ { on = 1; next } on && /^ *\}/ { exit }
    on { sub(/^ *\([0-9]+\): */, ""); gsub(/"/, ""); n = split($0, a, /, */); for (i = 1; i <= n; ++i) if (a[i] != "") print a[i] }'
}
stop=$(attr stop_reason)
[ "$stop" = t_max ] || echo "$me: warning: $sim stopped by '$stop', not at t_max; its result is recorded as such" >&2
{
  for key in N L e tc delta seed t_max stop_reason; do printf '%s\t%s\n' "$key" "$(attr "$key")"; done
  paste <(piece git_hash) <(piece clean) <(piece t_start) <(piece t_end) <(piece cpu_seconds) <(piece utc_end) |
    awk -F'\t' '{ s += $5; n++; end = $6; line[n] = sprintf("piece\t%s\t%s\tclean=%s\tt=%s..%s\tcpu=%.1f\t%s", n, $1, $2, $3, $4, $5, $6) }
      END { printf "cpu_seconds\t%.1f\npieces\t%d\nended_utc\t%s\n", s, n, end; for (k = 1; k <= n; ++k) print line[k] }'
  h5dump -a /parameters/provenance/argv "$sim" | awk '/DATA \{/ { on = 1; next } on && /^ *\}/ { exit }
    on { sub(/^ *\([0-9]+\): */, ""); gsub(/"/, ""); gsub(/, */, " "); sub(/ +$/, ""); printf "%s%s", (n++ ? " " : "command\t"), $0 } END { print "" }'
  printf 'git_hash\t%s\n' "$(h5dump -a /parameters/provenance/git_hash "$sim" | sed -n 's/^ *(0): "\(.*\)"/\1/p')"
} > "$out.info.tmp"
mv "$out.info.tmp" "${out%.h5}.info"
mv "$part" "$out"
trap - EXIT
