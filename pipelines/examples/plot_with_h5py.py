#!/usr/bin/env python3
"""Reading the toolkit's outputs from Python: a gg-sim trajectory (H5MD) and a gg-cluster result,
with h5py, in one matplotlib figure: the last snapshot's disks to scale in the periodic box, and
E(t) with the mean cluster mass m(t) on log axes (the paper's Fig. 2 and 3 in miniature).
Needs Debian's python3-h5py, python3-matplotlib and python3-numpy.

Usage: plot_with_h5py.py SIM.h5 CLUSTER.h5 OUT.png
  e.g. gg-sim --scene pipelines/scenes/fig2-e0.8.ini --L 128 --t-max 300 -o sim.h5
       gg-cluster sim.h5 -o cluster.h5
       /usr/bin/python3 pipelines/examples/plot_with_h5py.py sim.h5 cluster.h5 plot.png
"""
import sys

import h5py
import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import EllipseCollection  # noqa: E402

sim_path, cluster_path, out = sys.argv[1:4]
with h5py.File(sim_path, "r") as sim:
    box = sim["particles/all/box/edges"][()]
    positions = sim["particles/all/position/value"]
    frames, unit = len(positions), positions.attrs["unit"]
    last = positions[-1]                       # [N][2], in [0, L), unit: sigma
    t_last = sim["particles/all/position/time"][-1]
    energy_t = sim["observables/kinetic_energy/time"][()]
    energy = sim["observables/kinetic_energy/value"][()]
with h5py.File(cluster_path, "r") as clusters:
    cluster_t = clusters["cluster/time"][()]
    mean_mass = clusters["cluster/mean_mass"][()]

fig, (left, right) = plt.subplots(1, 2, figsize=(11, 5))
# Diameter 1 in data units on both axes: disks to scale.
left.add_collection(EllipseCollection(1, 1, 0, units="xy", offsets=last, offset_transform=left.transData))
left.set(xlim=(0, box[0]), ylim=(0, box[1]), aspect="equal", xlabel=f"x / {unit}", ylabel=f"y / {unit}",
         title=f"t = {t_last:g}: {len(last)} disks, periodic box {box[0]:g} x {box[1]:g}")
positive = energy_t > 0
right.loglog(energy_t[positive], energy[positive], label="E(t), kinetic energy per particle")
right.loglog(cluster_t[cluster_t > 0], mean_mass[cluster_t > 0], "o-", label="m(t), mean cluster mass")
right.set(xlabel="t / tau", title="cooling and clustering")
right.legend()
fig.tight_layout()
fig.savefig(out, dpi=100)
print(f"{out}: N = {len(last)}, snapshots = {frames}, last m = {mean_mass[-1]:.6g}, "
      f"last E = {energy[-1]:.6g}")
