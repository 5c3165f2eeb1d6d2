"""A 3D gg-sim trajectory read by MDAnalysis's H5MD reader (Debian python3-mdanalysis): every
frame's positions, velocities, time and box against the file's datasets (read with h5py) and
against the box the run was asked for.
MDAnalysis translates only the units it knows (Angstrom, ps, ...): the reduced units of the file
(sigma, tau) are registered with it as themselves, and read with convert_units=False, as any
reduced-unit H5MD file has to be.
Usage: mdanalysis_reader_test.py GG_SIM"""
import os
import sys

from fixture import check, require_modules, run, workdir

h5py, np = require_modules("h5py", "numpy")
(mda,) = require_modules("MDAnalysis")
from MDAnalysis.coordinates.H5MD import H5MDReader  # noqa: E402 (after the skip check)

gg_sim = sys.argv[1]
N, RHO = 500, 0.5  # packing fraction pi rho / 6 = 0.26
L = (N / RHO) ** (1 / 3)
TIMES = [0, 1, 2, 4]

for kind, unit in (("time", "tau"), ("length", "sigma"), ("velocity", "sigma tau-1")):
    H5MDReader._unit_translation[kind].setdefault(unit, unit)

with workdir() as tmp:
    h5 = os.path.join(tmp, "sim3d.h5")
    run(gg_sim, "--dim", 3, "--N", N, "--rho", RHO, "--e", 0.8, "--seed", 5, "--t-max", 4,
        "--snapshots", ",".join(map(str, TIMES)), "--velocities", "--quiet", "-o", h5)
    # H5MD holds no topology: an empty Universe of N atoms takes the trajectory.
    u = mda.Universe.empty(N, trajectory=False)
    u.load_new(h5, format="H5MD", convert_units=False)
    check(u.atoms.n_atoms == N, f"MDAnalysis sees {u.atoms.n_atoms} atoms, expected {N}")
    check(u.trajectory.n_frames == len(TIMES), f"MDAnalysis sees {u.trajectory.n_frames} frames")
    with h5py.File(h5, "r") as f:
        position = f["particles/all/position/value"][()]
        velocity = f["particles/all/velocity/value"][()]
        for k, ts in enumerate(u.trajectory):
            # MDAnalysis holds float32: agreement to float32 rounding of coordinates up to L.
            check(np.allclose(ts.positions, position[k], rtol=0, atol=2e-6 * L), f"frame {k}: positions differ")
            check(np.allclose(ts.velocities, velocity[k], rtol=1e-6, atol=1e-6), f"frame {k}: velocities differ")
            check(np.allclose(ts.dimensions, [L, L, L, 90, 90, 90], rtol=1e-6), f"frame {k}: box {ts.dimensions}")
            check(abs(ts.time - TIMES[k]) < 1e-12, f"frame {k}: time {ts.time}, expected {TIMES[k]}")
        check(np.all(position >= 0) and np.all(position < L), "positions outside [0, L)")
print("ok: MDAnalysis reads the 3D trajectory: positions, velocities, times and box")
