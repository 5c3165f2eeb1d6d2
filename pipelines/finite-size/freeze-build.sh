#!/bin/bash
# freeze-build.sh COMMIT DIR
# Builds gg-sim of COMMIT in a checkout of its own (a committed tree, so every piece it runs says clean)
# and copies it to DIR/gg-sim, so that every simulation of a study is run by one build
# (results/finite-size/README.md): `make -f Makefile.study SCALE=large SIM=DIR/gg-sim ...`. The same
# commit built with the same compiler gives the same program, whichever machine builds it; gg-sim
# refuses to resume a checkpoint another build wrote. An existing DIR/gg-sim of COMMIT is kept as it is.
set -euo pipefail
me=freeze-build.sh
commit=${1:?usage: $me COMMIT DIR} dir=${2:?usage: $me COMMIT DIR}
hash=$(git rev-parse --short=12 "$commit^{commit}" 2>/dev/null) ||
  { echo "$me: '$commit' is not a commit of this repository; give a hash or a branch" >&2; exit 2; }
if [ -x "$dir/gg-sim" ] && "$dir/gg-sim" --version | grep -q "(git $hash)"; then echo "$dir/gg-sim"; exit 0; fi
mkdir -p "$dir"
src=$(mktemp -d)
trap 'git worktree remove --force "$src" 2>/dev/null || rm -rf "$src"' EXIT
git worktree add -q --detach "$src" "$hash"
cmake -S "$src" -B "$src/build" -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$src/build" -j"$(nproc)" --target gg-sim > /dev/null
"$src/build/simulate/gg-sim" --version | grep -q "(git $hash)" ||
  { echo "$me: the build of $hash does not name it ($("$src/build/simulate/gg-sim" --version))" >&2; exit 1; }
cp "$src/build/simulate/gg-sim" "$dir/gg-sim.tmp" && mv "$dir/gg-sim.tmp" "$dir/gg-sim"
echo "$dir/gg-sim"
