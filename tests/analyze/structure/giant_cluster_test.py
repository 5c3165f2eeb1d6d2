"""gg-cluster's giant-cluster outputs against an independent reading of the same snapshots.

Two 2D gg-sim runs (e = 0.5; L = 64 to t = 3000, L = 128 to t = 1000) go from a homogeneous gas to a
largest cluster that wraps the box, along one axis or both. This script reads its snapshots with h5py, coarse-grains them as docs/DESIGN.md
"Coarse-grained density" defines (cells of spacing L/n, n = round(L/grid); 3x3 block counts; psi = +1
where rho_loc > rho_c), labels the clusters with scipy.ndimage and its own merging across the periodic
faces, and decides wrapping by another method than gg-cluster's union-find: the grid tiled k times
along an axis, with periodic boundaries, is a k-fold covering of the box; a cluster's copies there
form fewer than k clusters exactly when some loop through it winds around the box along that axis a
number of times not divisible by k (k = 2 and 3 together miss only windings that are all multiples of 6).
Frame by frame and for 4 and 8 neighbours, /cluster/largest, largest_share, largest_share_of_clustered,
rest_mean_mass (exactly) and wraps must agree, the runs must hold frames that wrap and frames that do not,
and --particle-clusters must put in cluster 0 exactly the particles in the largest cluster's cells.

usage: giant_cluster_test.py GG-SIM GG-CLUSTER SCENE.ini
"""
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "export"))
from fixture import check, require_modules, run, workdir  # noqa: E402

np, h5py, ndimage = require_modules("numpy", "h5py", "scipy.ndimage")
gg_sim, gg_cluster, scene = sys.argv[1:4]
GRID, W, RHO_C = 1.0, 1, 0.5  # gg-cluster's defaults


def coarse_grain(x, edges):
    """Particle counts per cell and psi, as docs/DESIGN.md defines them (2D)."""
    n = [max(1, int(round(L / GRID))) for L in edges]
    idx = []
    for k in range(2):
        c = np.floor(np.mod(x[:, k], edges[k]) * n[k] / edges[k]).astype(np.int64)
        idx.append(np.minimum(c, n[k] - 1))
    counts = np.zeros(n, dtype=np.int64)
    np.add.at(counts, (idx[0], idx[1]), 1)
    block = np.zeros_like(counts)
    for dx in range(-W, W + 1):
        for dy in range(-W, W + 1):
            block += np.roll(counts, (dx, dy), axis=(0, 1))
    volume = (2 * W + 1) ** 2 * (edges[0] / n[0]) * (edges[1] / n[1])
    return counts, block / volume > RHO_C, (idx[0], idx[1])


def periodic_labels(rich, neighbours):
    """Cluster labels (0 = none) of a periodic boolean grid: scipy.ndimage.label on the open grid, then
    labels joined across the faces by a union-find over the pairs of touching cells that disagree."""
    structure = np.ones((3, 3), dtype=bool) if neighbours == 8 else None
    label, count = ndimage.label(rich, structure=structure)
    parent = list(range(count + 1))

    def root(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a

    shifts = [(1, 0), (0, 1)] + ([(1, 1), (1, -1)] if neighbours == 8 else [])
    for s in shifts:
        other = np.roll(label, s, axis=(0, 1))
        touching = (label > 0) & (other > 0) & (label != other)
        for a, b in set(zip(label[touching].tolist(), other[touching].tolist())):
            ra, rb = root(a), root(b)
            if ra != rb:
                parent[max(ra, rb)] = min(ra, rb)
    roots = np.array([root(a) for a in range(count + 1)])
    return roots[label]


def largest_cluster(counts, rich, neighbours):
    """The cells of the heaviest cluster (ties: the one holding the smallest row-major cell), its mass,
    and the masses of all clusters of at least one particle (gg-cluster's --min-size 1); (None, 0, [])
    without such a cluster."""
    label = periodic_labels(rich, neighbours).ravel()
    ids, first = np.unique(label, return_index=True)
    mass = np.bincount(label, weights=counts.ravel())[ids].astype(np.int64)
    keep = (ids > 0) & (mass >= 1)
    ids, first, mass = ids[keep], first[keep], mass[keep]
    if ids.size == 0:
        return None, 0, mass
    best = min(range(ids.size), key=lambda j: (-mass[j], first[j]))
    return (label == ids[best]).reshape(counts.shape), int(mass[best]), mass


def wraps(cells, rich, neighbours):
    """Per axis: 1 if the cluster `cells` wraps the box, read from its copies in the k-fold covers."""
    out = []
    for axis in range(2):
        wrapped = False
        for k in (2, 3):
            reps = (k, 1) if axis == 0 else (1, k)
            tiled = periodic_labels(np.tile(rich, reps), neighbours)
            copies = np.tile(cells, reps)
            wrapped |= np.unique(tiled[copies]).size < k
        out.append(int(wrapped))
    return out


def same(a, b):
    """Equal, or both NaN."""
    return a == b or (np.isnan(a) and np.isnan(b))


def compare(sim, out, neighbours, tally):
    """gg-cluster on `sim` against the reading here, frame by frame; counts frames in `tally`."""
    with h5py.File(sim, "r") as f:
        p = f["particles/all"]
        edges = p["box/edges"][()]
        positions = p["position/value"][()]
    run(gg_cluster, sim, "-o", out, "--connectivity", neighbours, "--particle-clusters", "--quiet")
    with h5py.File(out, "r") as f:
        g = {k: f["cluster"][k][()] for k in ("largest", "largest_share", "largest_share_of_clustered",
                                              "rest_mean_mass", "wraps", "largest_wraps", "particle_cluster")}
    check(g["wraps"].shape == (len(positions), 2), f"wraps has shape {g['wraps'].shape}, not [T][2]")
    for t, x in enumerate(positions):
        where = f"{os.path.basename(sim)}, {neighbours} neighbours, frame {t}"
        counts, rich, cell = coarse_grain(x, edges)
        cells, mass, masses = largest_cluster(counts, rich, neighbours)
        clustered = int(masses.sum())
        mine = {"largest": mass, "largest_share": mass / len(x),
                "largest_share_of_clustered": mass / clustered if clustered else np.nan,
                "rest_mean_mass": (clustered - mass) / (masses.size - 1) if masses.size > 1 else np.nan,
                "wraps": wraps(cells, rich, neighbours) if cells is not None else [0, 0]}
        for name in ("largest", "largest_share", "largest_share_of_clustered", "rest_mean_mass"):
            check(same(g[name][t], mine[name]), f"{where}: {name} {g[name][t]}, read {mine[name]}")
        check(list(g["wraps"][t]) == mine["wraps"], f"{where}: wraps {list(g['wraps'][t])}, read {mine['wraps']}")
        check(g["largest_wraps"][t] == float(any(mine["wraps"])),
              f"{where}: largest_wraps {g['largest_wraps'][t]}, read wraps {mine['wraps']}")
        in_largest = cells[cell] if cells is not None else np.zeros(len(x), dtype=bool)
        check(np.array_equal(g["particle_cluster"][t] == 0, in_largest),
              f"{where}: particle_cluster 0 is not the largest cluster's particles")
        tally["frames"] += 1
        tally[tuple(mine["wraps"])] = tally.get(tuple(mine["wraps"]), 0) + 1


def main():
    with workdir() as d:
        runs = []
        for L, t_max, per_decade in ((64, 3000, 12), (128, 1000, 8)):
            runs.append(os.path.join(d, f"run{L}.h5"))
            run(gg_sim, "--scene", scene, "--L", L, "--t-max", t_max, "--snapshots-per-decade", per_decade,
                "--seed", 1, "--quiet", "-o", runs[-1])
        for neighbours in (4, 8):
            tally = {"frames": 0}
            for sim in runs:
                compare(sim, os.path.join(d, "cluster.h5"), neighbours, tally)
            frames = tally.pop("frames")
            wrapping = {"".join(map(str, k)): v for k, v in sorted(tally.items()) if any(k)}
            print(f"{neighbours} neighbours: {frames} of {frames} frames agree; the largest cluster wraps along "
                  f"(x, y) = {wrapping}, along neither in {tally.get((0, 0), 0)}")
            check(0 < sum(wrapping.values()) < frames, "the runs should hold frames that wrap and frames that do not")


if __name__ == "__main__":
    main()
