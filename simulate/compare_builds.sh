#!/bin/bash
# compare_builds.sh OLD_GG_SIM NEW_GG_SIM [WORKDIR]
# Runs the same small scenes with two gg-sim binaries and compares their data: a change of the engine
# that is meant to keep every trajectory (a refactoring, a new effect that a scene does not use) must
# leave /observables, /particles and every value of /parameters but the provenance bit-identical
# (simulate/PERFORMANCE.md "How a decision is measured"). The scenes (build_scenes.sh) cover 1D, 2D and 3D
# and every effect, aggregation, walls and the shear included (a build older than an effect fails to run
# its scenes). Prints one line per scene and exits 1 if any differs.
set -uo pipefail
old=${1:?usage: compare_builds.sh OLD_GG_SIM NEW_GG_SIM [WORKDIR]}
new=${2:?usage: compare_builds.sh OLD_GG_SIM NEW_GG_SIM [WORKDIR]}
work=${3:-$(mktemp -d)}
mkdir -p "$work"
. "$(dirname "${BASH_SOURCE[0]}")/build_scenes.sh"
# attrs FILE: every attribute of /parameters but the provenance, one "name = value" block each.
attrs() {
  local name
  for name in $(h5dump -A -g /parameters "$1" | awk '/^   ATTRIBUTE "/ { gsub(/"/, "", $2); print $2 }'); do
    echo "$name"; h5dump -a "/parameters/$name" "$1" | tail -n +2
  done
}
failed=0
for scene in "${build_scenes[@]}"; do
  IFS='|' read -r name flags length _ <<< "$scene"
  args="$flags $length"
  verdict=identical
  # shellcheck disable=SC2086  # args is a list of flags
  if ! "$old" $args --seed 5 --quiet -o "$work/old-$name.h5" 2> "$work/old-$name.err" ||
     ! "$new" $args --seed 5 --quiet -o "$work/new-$name.h5" 2> "$work/new-$name.err"; then
    verdict="failed to run (see $work/*-$name.err)"
  else
    differs=()
    for group in /observables /particles; do
      h5diff -q "$work/old-$name.h5" "$work/new-$name.h5" "$group" > /dev/null 2>&1 || differs+=("$group")
    done
    [ "$(attrs "$work/old-$name.h5")" = "$(attrs "$work/new-$name.h5")" ] || differs+=(/parameters)
    [ ${#differs[@]} -eq 0 ] || verdict="differs in ${differs[*]}"
  fi
  printf '%-26s %s\n' "$name" "$verdict"
  [ "$verdict" = identical ] || failed=1
done
exit $failed
