"""pipelines/examples/plot_with_h5py.py on a small run and its gg-cluster result: it must write a PNG
of the figure's size and report the N, snapshot count, last m and last E that h5py reads here.
Usage: python_example_test.py GG_SIM GG_CLUSTER EXAMPLE"""
import os
import sys

from fixture import check, require_modules, run, simulate, workdir

h5py, _, np = require_modules("h5py", "matplotlib", "numpy")
gg_sim, gg_cluster, example = sys.argv[1:4]

with workdir() as tmp:
    sim = simulate(gg_sim, tmp, 2)
    clusters = f"{tmp}/cluster.h5"
    run(gg_cluster, sim, "-o", clusters, "--quiet")
    out = f"{tmp}/plot.png"
    printed = run(sys.executable, example, sim, clusters, out).stdout.strip()
    with h5py.File(sim, "r") as f, h5py.File(clusters, "r") as c:
        n, frames = f["particles/all/position/value"].shape[1], len(f["particles/all/position/value"])
        want = (f"{out}: N = {n}, snapshots = {frames}, last m = {c['cluster/mean_mass'][-1]:.6g}, "
                f"last E = {f['observables/kinetic_energy/value'][-1]:.6g}")
    check(printed == want, f"the example printed {printed!r}, expected {want!r}")
    with open(out, "rb") as png:
        head = png.read(24)
    check(head[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG")
    width, height = int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")
    check((width, height) == (1100, 500), f"PNG is {width} x {height}, expected 1100 x 500")
    check(os.path.getsize(out) > 10000, "the PNG is nearly empty")
    print(printed)
