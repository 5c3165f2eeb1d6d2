"""gg-export's GSD files read by the GSD project's own reader (Debian python3-gsd): the same frame
count, box, positions (shifted to HOOMD's centred box) and velocities as the H5MD file, read with
h5py. Usage: gsd_reader_test.py GG_SIM GG_EXPORT"""
import sys

from fixture import check, require_modules, run, simulate, workdir

gsd_hoomd, h5py, np = require_modules("gsd.hoomd", "h5py", "numpy")
gg_sim, gg_export = sys.argv[1:3]

with workdir() as tmp:
    for dim in (2, 1):
        h5 = simulate(gg_sim, tmp, dim)
        out = f"{tmp}/sim{dim}d.gsd"
        run(gg_export, h5, "-o", out, "--quiet")
        with h5py.File(h5, "r") as f:
            edges = f["particles/all/box/edges"][()]
            position = f["particles/all/position/value"][()]
            velocity = f["particles/all/velocity/value"][()]
            step = f["particles/all/position/step"][()]
            time = f["particles/all/position/time"][()]
        with gsd_hoomd.open(out, "rb") as traj:
            check(len(traj) == len(position), f"{dim}D: {len(traj)} GSD frames for {len(position)} snapshots")
            for k, frame in enumerate(traj):
                n = position.shape[1]
                check(frame.particles.N == n, f"{dim}D frame {k}: N = {frame.particles.N}, expected {n}")
                check(frame.configuration.dimensions == 2, f"{dim}D frame {k}: dimensions {frame.configuration.dimensions}")
                box = np.asarray(frame.configuration.box)
                want_box = [edges[0], edges[1] if dim == 2 else 1.0, 0, 0, 0, 0]
                check(np.allclose(box, want_box, rtol=1e-7, atol=0), f"{dim}D frame {k}: box {box}, expected {want_box}")
                check(frame.configuration.step == step[k], f"{dim}D frame {k}: step {frame.configuration.step} != {step[k]}")
                check(frame.log["time"][0] == time[k], f"{dim}D frame {k}: time {frame.log['time']} != {time[k]}")
                r = np.asarray(frame.particles.position, dtype=float)
                v = np.asarray(frame.particles.velocity, dtype=float)
                # float32 keeps 24 bits: |error| <= 2^-24 |x| plus the half-box shift's rounding.
                tol = 2.0 ** -23 * edges.max()
                check(np.abs(r[:, :dim] - (position[k] - edges / 2)).max() <= tol,
                      f"{dim}D frame {k}: positions differ by {np.abs(r[:, :dim] - (position[k] - edges / 2)).max()}")
                check(np.all(r[:, dim:] == 0), f"{dim}D frame {k}: the unused axes are not 0")
                check(np.all(r[:, :dim] >= -edges / 2) and np.all(r[:, :dim] < edges / 2),
                      f"{dim}D frame {k}: positions outside HOOMD's box [-L/2, L/2)")
                check(np.abs(v[:, :dim] - velocity[k]).max() <= 2.0 ** -23 * np.abs(velocity[k]).max(),
                      f"{dim}D frame {k}: velocities differ")
                check(np.all(frame.particles.diameter == 1) and np.all(frame.particles.mass == 1),
                      f"{dim}D frame {k}: diameters or masses are not 1")
        print(f"{dim}D: {len(position)} frames of {position.shape[1]} particles agree")
