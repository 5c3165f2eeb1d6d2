"""The analyses from Python, notebook style: read a trajectory of any format the tools read, follow the
clusters, C(r) and domains frame by frame, fit m(t).

    PYTHONPATH=build/python python3 pipelines/examples/granular_gas_module.py run.h5      # or run.gsd, run.dump, run.xyz

(after `cmake --install build --prefix ~/.local`, no PYTHONPATH is needed). Prints one line per frame
and the power-law fit of m(t) over the second half of the run in log time.
"""
import sys

import numpy as np

import granular_gas as gg

path = sys.argv[1] if len(sys.argv) > 1 else "run.h5"

# %% The frames: numpy arrays of the file's positions, box, velocities (None when absent), radii.
trajectory = gg.Trajectory(path)
print(f"{path}: {trajectory.format}, {len(trajectory)} frames")
first = trajectory[0]
print(f"{first.n} particles in a {first.dim}D box of edges {first.box}")

# %% Each frame's clusters, correlation length and mean domain length, with the tools' defaults
# (grid 1, coarse 1, rho_c 0.5): the numbers gg-cluster, gg-correlate and gg-domains write.
times, mean_mass = [], []
print(f"{'t':>10} {'clusters':>9} {'m(t)':>9} {'largest':>8} {'l_C':>7} {'l_d':>7}")
for frame in trajectory:
    clusters = gg.clusters(frame.position, frame.box, radius=frame.radius)
    corr = gg.correlation(frame.position, frame.box, radius=frame.radius)
    dom = gg.domains(frame.position, frame.box, radius=frame.radius)
    print(f"{frame.time:10.4g} {clusters.count:9d} {clusters.mean_mass:9.2f} {clusters.largest:8d} "
          f"{corr.length:7.3f} {dom.length:7.3f}")
    times.append(frame.time)
    mean_mass.append(clusters.mean_mass)

# %% m(t) ~ t^z over the later half of the run (in log t), and the local exponent.
t, m = np.array(times), np.array(mean_mass)
ok = (t > 0) & np.isfinite(m) & (m > 0)
t, m = t[ok], m[ok]
if len(t) >= 3:
    window = (np.sqrt(t[0] * t[-1]), t[-1])
    fit = gg.fit_power_law(t, m, window)
    print(f"m(t) = A t^z over t in [{window[0]:.3g}, {window[1]:.3g}]: z = {fit.exponent:.4f} +/- "
          f"{fit.exponent_stderr:.4f}, A = {fit.amplitude:.4g}")
    z = gg.local_exponent(t, m)
    if len(z.t):
        print("local exponent at the last time:", f"{z.exponent[-1]:.3f}")
