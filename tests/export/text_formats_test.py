"""gg-export's extended XYZ and LAMMPS dump files read back by small readers written here from the
formats' descriptions, against the H5MD values read with h5py: every value exactly (17 digits).
Usage: text_formats_test.py GG_SIM GG_EXPORT"""
import shlex
import sys

from fixture import check, require_modules, run, simulate, workdir

h5py, np = require_modules("h5py", "numpy")
gg_sim, gg_export = sys.argv[1:3]


def read_xyz(path):
    """Frames of extended XYZ: (header key=value dict, rows of words)."""
    frames, lines = [], open(path).read().splitlines()
    at = 0
    while at < len(lines):
        n = int(lines[at])
        header = dict(token.split("=", 1) for token in shlex.split(lines[at + 1]))
        frames.append((header, [line.split() for line in lines[at + 2:at + 2 + n]]))
        at += 2 + n
    return frames


def read_dump(path):
    """Frames of a LAMMPS text dump: dict of ITEM name -> the lines under it."""
    frames, item = [], None
    for line in open(path).read().splitlines():
        if line.startswith("ITEM: "):
            item = line[6:]
            if item == "TIME":
                frames.append({})
            frames[-1][item] = []
        else:
            frames[-1][item].append(line.split())
    return frames


with workdir() as tmp:
    for dim in (2, 1):
        h5 = simulate(gg_sim, tmp, dim)
        with h5py.File(h5, "r") as f:
            edges = f["particles/all/box/edges"][()]
            r = f["particles/all/position/value"][()]
            v = f["particles/all/velocity/value"][()]
            step = f["particles/all/position/step"][()]
            time = f["particles/all/position/time"][()]
        pad = np.zeros((r.shape[1], 3 - dim))
        run(gg_export, h5, "-o", f"{tmp}/t.xyz", "--quiet")
        xyz = read_xyz(f"{tmp}/t.xyz")
        check(len(xyz) == len(r), f"{dim}D xyz: {len(xyz)} frames for {len(r)}")
        for k, (header, rows) in enumerate(xyz):
            lattice = np.array(header["Lattice"].split(), dtype=float).reshape(3, 3)
            want = np.diag(list(edges) + [1.0] * (3 - dim))
            check(np.array_equal(lattice, want), f"{dim}D xyz frame {k}: Lattice {lattice.tolist()}")
            check(header["Properties"] == "species:S:1:pos:R:3:velo:R:3:radius:R:1", "xyz Properties " + header["Properties"])
            check(header["pbc"] == " ".join("T" if a < dim else "F" for a in range(3)), "xyz pbc " + header["pbc"])
            check(float(header["Time"]) == time[k] and int(header["Step"]) == step[k], f"xyz frame {k}: Time/Step")
            values = np.array([row[1:] for row in rows], dtype=float)
            check(np.array_equal(values[:, 0:3], np.hstack([r[k], pad])), f"{dim}D xyz frame {k}: positions differ")
            check(np.array_equal(values[:, 3:6], np.hstack([v[k], pad])), f"{dim}D xyz frame {k}: velocities differ")
            check(np.all(values[:, 6] == 0.5), f"{dim}D xyz frame {k}: radius not 0.5")

        run(gg_export, h5, "-o", f"{tmp}/t.dump", "--quiet")
        dump = read_dump(f"{tmp}/t.dump")
        check(len(dump) == len(r), f"{dim}D dump: {len(dump)} frames for {len(r)}")
        bounds_header = "BOX BOUNDS pp pp pp"
        atoms_header = "ATOMS id type x y z vx vy vz radius"
        for k, frame in enumerate(dump):
            check(float(frame["TIME"][0][0]) == time[k] and int(frame["TIMESTEP"][0][0]) == step[k], f"dump frame {k}: time")
            check(int(frame["NUMBER OF ATOMS"][0][0]) == r.shape[1], f"dump frame {k}: atom count")
            bounds = np.array(frame[bounds_header], dtype=float)
            want = [[0, edges[a]] if a < dim else [-0.5, 0.5] for a in range(3)]
            check(np.array_equal(bounds, want), f"{dim}D dump frame {k}: bounds {bounds.tolist()}")
            atoms = np.array(frame[atoms_header], dtype=float)
            check(np.array_equal(atoms[:, 0], np.arange(1, r.shape[1] + 1)), f"dump frame {k}: ids not 1..N in order")
            check(np.array_equal(atoms[:, 2:5], np.hstack([r[k], pad])), f"{dim}D dump frame {k}: positions differ")
            check(np.array_equal(atoms[:, 5:8], np.hstack([v[k], pad])), f"{dim}D dump frame {k}: velocities differ")
        print(f"{dim}D: xyz and dump, {len(r)} frames, every value as in the H5MD file")
