"""Boxes that are not periodic cubes, as gg-sim writes them and gg-export passes them on (docs/DESIGN.md
"Files", "Frames from other codes"). Walls (gg-sim --walls H, 2D and 3D): the H5MD box says "none"
along the walls' axis (h5py), the LAMMPS dump "ff" and the extended XYZ pbc "F" there, GSD keeps
HOOMD's periodic box of edge H + 1; gg-cluster still reads the file.
Usage: boundaries_test.py GG_SIM GG_EXPORT GG_CLUSTER"""
import shlex
import sys

from fixture import check, require_modules, run, workdir

gsd_hoomd, h5py, np = require_modules("gsd.hoomd", "h5py", "numpy")
gg_sim, gg_export, gg_cluster = sys.argv[1:4]


def header_line(path, start):
    """The first line of a text file that starts with `start`."""
    return next(line for line in open(path) if line.startswith(start))


def check_walls(tmp, dim, n, L, H):
    h5 = f"{tmp}/walls{dim}d.h5"
    run(gg_sim, "--dim", dim, "--N", n, "--L", L, "--walls", H, "--e", 0.9, "--seed", 2, "--t-max", 2,
        "--snapshots", "0,2", "--velocities", "--quiet", "-o", h5)
    with h5py.File(h5, "r") as f:
        box = f["particles/all/box"]
        boundary = [b.decode() if isinstance(b, bytes) else b for b in box.attrs["boundary"]]
        edges = box["edges"][()] if dim < 3 else np.diag(box["edges/value"][0])
        check(f["parameters"].attrs["walls"] == H, f"{dim}D walls: /parameters walls")
    want = ["periodic"] * (dim - 1) + ["none"]
    check(boundary == want, f"{dim}D walls: H5MD boundary {boundary}, expected {want}")
    check(edges[-1] == H + 1, f"{dim}D walls: edge {edges[-1]} along the walls' axis, expected H + 1 = {H + 1}")

    run(gg_export, h5, "-o", f"{tmp}/w.dump", "--quiet")
    flags = header_line(f"{tmp}/w.dump", "ITEM: BOX BOUNDS").split()[3:]
    want_flags = ["pp"] * (dim - 1) + ["ff"] + ["pp"] * (3 - dim)
    check(flags == want_flags, f"{dim}D walls: LAMMPS flags {flags}, expected {want_flags}")

    run(gg_export, h5, "-o", f"{tmp}/w.xyz", "--quiet")
    comment = dict(token.split("=", 1) for token in shlex.split(open(f"{tmp}/w.xyz").read().splitlines()[1]))
    want_pbc = " ".join(["T"] * (dim - 1) + ["F"] * (4 - dim))
    check(comment["pbc"] == want_pbc, f"{dim}D walls: XYZ pbc {comment['pbc']}, expected {want_pbc}")

    run(gg_export, h5, "-o", f"{tmp}/w.gsd", "--quiet")
    with gsd_hoomd.open(f"{tmp}/w.gsd", "rb") as traj:
        gsd_box = list(traj[0].configuration.box)
    want_box = list(edges) + [0] * (3 - dim) + [0, 0, 0]
    check(np.allclose(gsd_box, want_box, rtol=1e-7, atol=0), f"{dim}D walls: GSD box {gsd_box}, expected {want_box}")

    run(gg_cluster, h5, "-o", f"{tmp}/c{dim}d.h5", "--quiet")
    print(f"{dim}D walls: H5MD {boundary}, LAMMPS {' '.join(flags)}, XYZ pbc {want_pbc}, GSD box {want_box[:3]}; "
          "gg-cluster reads it")


with workdir() as tmp:
    check_walls(tmp, 2, 150, 20.0, 12.0)
    check_walls(tmp, 3, 150, 8.0, 8.0)
