#!/bin/bash
# `cmake --install` into a fresh prefix, then an outside project finds the package two ways
# (find_package(GranularGas) and pkg-config), links the analysis library and reads a gg-sim output
# made by the installed gg-sim: the N and box it prints must be the run's, and a threshold below the
# density of any 3x3 block of 4-sigma cells (each expects 36 particles) must give one cluster of all N.
# Usage: install_test.sh BUILD_DIR
set -euo pipefail
build=$1
tmp=$(mktemp -d "${TMPDIR:-/tmp}/gg-install-test.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix
cmake --install "$build" --prefix "$prefix" > "$tmp/install.log"
for tool in gg-sim gg-cluster gg-correlate gg-domains gg-fit gg-export; do
  [ -x "$prefix/bin/$tool" ] || { echo "FAILED: $tool not installed"; exit 1; }
done
"$prefix/bin/gg-sim" --N 400 --L 40 --e 0.9 --t-max 2 --snapshots 0,2 --quiet -o "$tmp/run.h5"

mkdir "$tmp/outside"
cat > "$tmp/outside/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.22)
project(outside CXX)
find_package(GranularGas REQUIRED)
add_executable(outside main.cpp)
target_link_libraries(outside PRIVATE GranularGas::ggstructure)
CMAKE
cat > "$tmp/outside/main.cpp" <<'CPP'
#include <cstdio>
#include "cluster.hpp"
#include "gg/h5file.hpp"
#include "gg/trajectory.hpp"
int main(int, char** argv) {  // the last frame; no block of cells is empty: one cluster
  const gg::Snapshots s = gg::read_snapshots(gg::H5Input(argv[1]), {-1});
  gg::DensityGrid grid(s.edges, gg::CoarseGrain{4.0, 1, 1e-9});
  grid.assign(s.position.data(), s.n_particles);
  const gg::ClusterResult r = gg::find_clusters(grid, gg::Connectivity::face);
  std::printf("N = %zu, L = %g, clusters %zu of mass %lld\n", s.n_particles, s.edges[0], r.clusters.size(),
              static_cast<long long>(r.clusters.at(0).mass));
}
CPP
cmake -S "$tmp/outside" -B "$tmp/outside/build" -DCMAKE_PREFIX_PATH="$prefix" > "$tmp/configure.log"
cmake --build "$tmp/outside/build" > "$tmp/build.log"
got=$("$tmp/outside/build/outside" "$tmp/run.h5")
want="N = 400, L = 40, clusters 1 of mass 400"
[ "$got" = "$want" ] || { echo "FAILED: find_package build printed '$got', expected '$want'"; exit 1; }

PKG_CONFIG_PATH=$(dirname "$(find "$prefix" -name granular-gas.pc)") \
  bash -c 'c++ "$1/outside/main.cpp" -o "$1/pc" $(pkg-config --cflags --libs granular-gas)' _ "$tmp"
got=$("$tmp/pc" "$tmp/run.h5")
[ "$got" = "$want" ] || { echo "FAILED: pkg-config build printed '$got', expected '$want'"; exit 1; }

# The Python module, where the Python it was built for looks under this prefix (site-packages), and
# the installed gg-cluster on a GSD file: the same largest cluster from both.
module=$(find "$prefix" -name 'granular_gas*.so')
[ -n "$module" ] || { echo "FAILED: the Python module granular_gas is not installed"; exit 1; }
case $module in */lib/python3.*/site-packages/*) ;; *) echo "FAILED: granular_gas installed at $module"; exit 1;; esac
"$prefix/bin/gg-export" "$tmp/run.h5" -o "$tmp/run.gsd" --quiet
"$prefix/bin/gg-cluster" "$tmp/run.gsd" -o "$tmp/clusters.h5" --quiet --grid 4 --rho-c 1e-9
tool=$(h5dump -d /cluster/largest -y "$tmp/clusters.h5" | tr ', ' '\n\n' | grep -E '^[0-9]+$' | tail -1)
python=$(PYTHONPATH=$(dirname "$module") /usr/bin/python3 -c '
import sys, granular_gas as gg
f = gg.Trajectory(sys.argv[1])[-1]
print(gg.clusters(f.position, f.box, grid=4.0, rho_c=1e-9).largest)' "$tmp/run.gsd")
[ "$tool" = 400 ] && [ "$python" = 400 ] || { echo "FAILED: largest cluster $tool (gg-cluster), $python (Python), expected 400"; exit 1; }
echo "installed: six tools, libraries, headers, the Python module; find_package and pkg-config builds read the output: $got"
