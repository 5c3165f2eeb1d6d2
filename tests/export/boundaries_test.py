"""Boxes that are not periodic cubes, as gg-sim writes them and gg-export passes them on (docs/DESIGN.md
"Files", "Frames from other codes"). Walls (gg-sim --walls H, 2D and 3D): the H5MD box says "none"
along the walls' axis (h5py), the LAMMPS dump "ff" and the extended XYZ pbc "F" there, GSD keeps
HOOMD's periodic box of edge H + 1; gg-cluster still reads the file. Lees-Edwards shear (gg-sim
--shear-rate a): at time t the images one L_y above are shifted by s = a L_y t (mod L_x) along x, the
lattice of a triclinic box a1 = (L_x, 0, 0), a2 = (s, L_y, 0). GSD (python3-gsd) has HOOMD's tilt
xy = s / L_y with |xy| <= 1/2, every position inside HOOMD's cell and the same particle as in H5MD
modulo the lattice (its velocity a L_y larger along x per a2), and no two disks overlap under the
tilted box's nearest images; the dump's triclinic bounds and the XYZ Lattice hold the same s.
Usage: boundaries_test.py GG_SIM GG_EXPORT GG_CLUSTER"""
import math
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


def sliding_shift(a, Lx, Ly, t):
    """s(t) = a L_y t modulo L_x, in [-L_x/2, L_x/2)."""
    s = math.fmod(a * Ly * t, Lx)
    return s - Lx if s >= Lx / 2 else s + Lx if s < -Lx / 2 else s


def check_sheared_gsd(path, a, edges, time, r_h5, v_h5):
    Lx, Ly = edges
    tol = 2.0 ** -22 * max(Lx, Ly)  # float32: the positions, the half-box shift and one L_x
    moved = 0
    with gsd_hoomd.open(path, "rb") as traj:
        check(len(traj) == len(time), f"sheared GSD: {len(traj)} frames for {len(time)}")
        for k, frame in enumerate(traj):
            box = np.asarray(frame.configuration.box, dtype=float)
            s = sliding_shift(a, Lx, Ly, time[k])
            xy = box[3]
            check(np.allclose(box[:3], [Lx, Ly, 0], rtol=1e-7, atol=0) and np.all(box[4:] == 0), f"frame {k}: box {box}")
            check(abs(xy - s / Ly) <= 1e-7 and abs(xy) <= 0.5, f"frame {k}: tilt xy {xy}, expected s/L_y = {s / Ly}")
            r = np.asarray(frame.particles.position, dtype=float)[:, :2]
            v = np.asarray(frame.particles.velocity, dtype=float)[:, :2]
            lean = r[:, 0] - xy * r[:, 1]  # HOOMD's cell: y and x - xy y in [-L/2, L/2)
            check(np.all(r[:, 1] >= -Ly / 2) and np.all(r[:, 1] < Ly / 2) and np.all(lean >= -Lx / 2) and
                  np.all(lean < Lx / 2), f"frame {k}: a position outside HOOMD's triclinic cell")
            d = r + edges / 2 - r_h5[k]  # m a1 + n a2 for each particle
            n = np.rint(d[:, 1] / Ly)
            m = np.rint((d[:, 0] - n * s) / Lx)
            off = np.abs(d - np.column_stack([m * Lx + n * s, n * Ly])).max()
            check(off <= tol, f"frame {k}: positions are not the H5MD ones modulo the lattice (off by {off})")
            jump = np.abs(v - v_h5[k] - np.column_stack([n * a * Ly, 0 * n])).max()
            check(jump <= 2.0 ** -22 * (np.abs(v_h5[k]).max() + abs(a) * Ly), f"frame {k}: velocities off by {jump}")
            moved += int(np.count_nonzero(m) + np.count_nonzero(n))
            # Nearest images in the tilted box (HOOMD's minimum image): disks touch, never overlap.
            dr = r[:, None, :] - r[None, :, :]
            ny = np.rint(dr[..., 1] / Ly)
            dr[..., 1] -= ny * Ly
            dr[..., 0] -= ny * xy * Ly
            dr[..., 0] -= np.rint(dr[..., 0] / Lx) * Lx
            dist = np.hypot(dr[..., 0], dr[..., 1]) + 2 * np.eye(len(r))
            check(dist.min() >= 1 - 1e-4, f"frame {k}: two disks {dist.min()} apart in the tilted box")
    check(moved > 0, "no particle was moved into HOOMD's cell: the frames do not try the tilt")
    return moved


def check_shear(tmp, a):
    h5 = f"{tmp}/shear.h5"
    run(gg_sim, "--dim", 2, "--N", 200, "--rho", 0.3, "--shear-rate", a, "--e", 1, "--seed", 4, "--t-max", 3,
        "--snapshots", "1,1.7,2.3,3", "--velocities", "--quiet", "-o", h5)
    with h5py.File(h5, "r") as f:
        edges = f["particles/all/box/edges"][()]
        time = f["particles/all/position/time"][()]
        r_h5 = f["particles/all/position/value"][()]
        v_h5 = f["particles/all/velocity/value"][()]
        check(f["parameters"].attrs["shear_rate"] == a, "/parameters shear_rate")
    Lx, Ly = edges
    shifts = [sliding_shift(a, Lx, Ly, t) for t in time]

    run(gg_export, h5, "-o", f"{tmp}/s.gsd", "--quiet")
    moved = check_sheared_gsd(f"{tmp}/s.gsd", a, edges, time, r_h5, v_h5)

    run(gg_export, h5, "-o", f"{tmp}/s.dump", "--quiet")
    lines = open(f"{tmp}/s.dump").read().splitlines()
    heads = [i for i, line in enumerate(lines) if line.startswith("ITEM: BOX BOUNDS")]
    check(len(heads) == len(time), f"dump: {len(heads)} frames")
    for k, at in enumerate(heads):
        check(lines[at] == "ITEM: BOX BOUNDS xy xz yz pp pp pp", f"dump frame {k}: {lines[at]}")
        (xlo_b, xhi_b, xy), (ylo, yhi, xz), (_, _, yz) = [[float(w) for w in lines[at + j].split()] for j in (1, 2, 3)]
        # LAMMPS: xlo_bound = xlo + min(0, xy, xz, xy + xz), xhi_bound = xhi + max(0, xy, xz, xy + xz)
        xlo, xhi = xlo_b - min(0, xy), xhi_b - max(0, xy)
        check(abs(xy - shifts[k]) <= 1e-12 * Lx and xz == 0 and yz == 0, f"dump frame {k}: tilt {xy}, expected {shifts[k]}")
        check(xlo == 0 and abs(xhi - Lx) <= 1e-12 * Lx and (ylo, yhi) == (0, Ly), f"dump frame {k}: bounds")
        rows = np.array([line.split() for line in lines[at + 5:at + 5 + r_h5.shape[1]]], dtype=float)
        check(np.array_equal(rows[:, 2:4], r_h5[k]), f"dump frame {k}: positions are not the H5MD ones")

    run(gg_export, h5, "-o", f"{tmp}/s.xyz", "--quiet")
    lines = open(f"{tmp}/s.xyz").read().splitlines()
    for k in range(len(time)):
        comment = dict(token.split("=", 1) for token in shlex.split(lines[k * (r_h5.shape[1] + 2) + 1]))
        lattice = np.array(comment["Lattice"].split(), dtype=float)
        want = [Lx, 0, 0, shifts[k], Ly, 0, 0, 0, 1]
        check(np.allclose(lattice, want, rtol=0, atol=1e-12 * Lx), f"xyz frame {k}: Lattice {lattice}, expected {want}")
    print(f"2D shear a = {a}: shifts s(t) = {', '.join(f'{s:.6g}' for s in shifts)} (L = {Lx:.6g}) as GSD tilts "
          f"{', '.join(f'{s / Ly:.6g}' for s in shifts)}, dump xy and XYZ Lattice; {moved} positions moved into "
          "HOOMD's cell, no disks overlap")


with workdir() as tmp:
    check_walls(tmp, 2, 150, 20.0, 12.0)
    check_walls(tmp, 3, 150, 8.0, 8.0)
    check_shear(tmp, 0.5)
