"""gg-cluster, gg-correlate, gg-domains and gg-velocity on files that no code of the toolkit wrote: a GSD file from
python3-gsd's own writer, LAMMPS text dumps written here line by line as the LAMMPS dump documentation
lays them out (scaled coordinates, shuffled ids and a column order of our own; unwrapped coordinates
with images), and extended XYZ as ASE writes it (species, pos, momenta at 8 decimals, pbc "T T F").
Each must give the numbers of the same configuration in H5MD, itself written here with h5py: every
dataset of every analysis, to 1e-12 (gg-velocity on ASE's XYZ to 1e-6: its momenta have 8 decimals).
The configurations come from gg-sim runs (2D, a 2D mixture with radii and masses, 3D), their positions
and velocities rounded to multiples of 2^-12, so that float32 (GSD) holds them exactly and 8 decimals
(ASE) keep every particle on the same side of every cell edge. Bad files get one line on stderr, exit status 1
and no output.

usage: other_writers_test.py GG-SIM GG-CLUSTER GG-CORRELATE GG-DOMAINS GG-VELOCITY
"""
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "export"))
from fixture import check, require_modules, run, workdir  # noqa: E402

np, h5py, gsd_hoomd = require_modules("numpy", "h5py", "gsd.hoomd")
gg_sim, gg_cluster, gg_correlate, gg_domains, gg_velocity = sys.argv[1:6]
TOOLS = {"cluster": gg_cluster, "correlation": gg_correlate, "domains": gg_domains, "velocity": gg_velocity}
QUANTUM = 2.0 ** -12


def configuration(h5md):
    """The frames of a gg-sim output: box, steps, positions rounded to QUANTUM, velocities, radii."""
    with h5py.File(h5md, "r") as f:
        p = f["particles/all"]
        box = p["box/edges"]  # 3D: box vectors per frame (docs/DESIGN.md "Files")
        edges = box[()] if isinstance(box, h5py.Dataset) else box["value"][0].diagonal()
        x = np.floor(p["position/value"][()] / QUANTUM) * QUANTUM
        x[x >= edges] = 0.0
        v = np.round(p["velocity/value"][()] / QUANTUM) * QUANTUM
        radius = p["radius/value"][()] if "radius" in p else None
        mass = p["mass/value"][()] if "mass" in p else None
        return {"edges": edges, "step": p["position/step"][()], "time": p["position/time"][()], "x": x, "v": v,
                "radius": radius, "mass": mass}


def write_h5md(c, path):
    """The configuration as H5MD 1.1, by h5py."""
    frames, n, d = c["x"].shape
    with h5py.File(path, "w") as f:
        f.create_group("h5md").attrs["version"] = [1, 1]
        box = f.create_group("particles/all/box")
        box.attrs["dimension"] = d
        box.attrs["boundary"] = [b"periodic"] * d
        box["edges"] = c["edges"]
        for name, values in (("position", c["x"]), ("velocity", c["v"])) + (
                (("radius", c["radius"]), ("mass", c["mass"])) if c["radius"] is not None else ()):
            g = f.create_group("particles/all/" + name)
            g["value"], g["step"], g["time"] = values, c["step"], c["time"]


def padded(values):
    """[N][d] as [N][3], the missing axes 0."""
    out = np.zeros((values.shape[0], 3))
    out[:, :values.shape[1]] = values
    return out


def write_gsd(c, path):
    """HOOMD schema by gsd.hoomd: the box centred on 0, float32 positions, diameters when sized."""
    frames, n, d = c["x"].shape
    with gsd_hoomd.open(path, "wb") as f:
        for k in range(frames):
            s = gsd_hoomd.Snapshot()
            s.configuration.step = int(c["step"][k])
            s.configuration.dimensions = d
            s.configuration.box = [c["edges"][0], c["edges"][1], c["edges"][2] if d == 3 else 0, 0, 0, 0]
            s.particles.N = n
            s.particles.position = padded(c["x"][k] - c["edges"] / 2).astype(np.float32)
            s.particles.velocity = padded(c["v"][k]).astype(np.float32)
            if c["radius"] is not None:
                s.particles.diameter = (2 * c["radius"][k]).astype(np.float32)
                s.particles.mass = c["mass"][k].astype(np.float32)
            f.append(s)


def write_lammps_scaled(c, path, seed):
    """A dump as LAMMPS's `dump custom ... vy type xs id ys vx zs` writes it: rows in no order, ids
    from 1, scaled coordinates, a box whose lower corner is not the origin."""
    rng = np.random.default_rng(seed)
    frames, n, d = c["x"].shape
    lo = np.array([-17.5, 3.25, -8.0])
    L = np.append(c["edges"], [1.0] * (3 - d))
    lines = []
    for k in range(frames):
        xs = padded(c["x"][k]) / L
        xs[:, d:] = 0.5
        v = padded(c["v"][k])
        lines += ["ITEM: TIMESTEP", str(c["step"][k]), "ITEM: NUMBER OF ATOMS", str(n), "ITEM: BOX BOUNDS pp pp pp"]
        lines += [f"{lo[a]!r} {lo[a] + L[a]!r}" for a in range(3)]
        lines.append("ITEM: ATOMS vy type xs id ys vx zs" + (" radius mass" if c["radius"] is not None else "") +
                     (" vz" if d == 3 else ""))
        for i in rng.permutation(n):
            row = [v[i, 1], 1, xs[i, 0], i + 1, xs[i, 1], v[i, 0], xs[i, 2]]
            if c["radius"] is not None:
                row += [c["radius"][k][i], c["mass"][k][i]]
            if d == 3:
                row.append(v[i, 2])
            lines.append(" ".join(repr(float(x)) if isinstance(x, (float, np.floating)) else str(x) for x in row))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def write_lammps_unwrapped(c, path, seed):
    """`dump custom ... id type xu yu zu ix iy iz [diameter]`: unwrapped coordinates x + i L with images."""
    rng = np.random.default_rng(seed)
    frames, n, d = c["x"].shape
    L = np.append(c["edges"], [1.0] * (3 - d))
    with open(path, "w") as f:
        for k in range(frames):
            image = rng.integers(-3, 4, size=(n, 3))
            image[:, d:] = 0
            xu = padded(c["x"][k]) + image * L
            f.write(f"ITEM: TIMESTEP\n{c['step'][k]}\nITEM: NUMBER OF ATOMS\n{n}\nITEM: BOX BOUNDS pp pp pp\n")
            f.write("".join(f"0 {L[a]!r}\n" for a in range(3)))
            sized = c["radius"] is not None
            v = padded(c["v"][k])
            f.write("ITEM: ATOMS id type xu yu zu ix iy iz vx vy vz" + (" diameter mass\n" if sized else "\n"))
            for i in range(n):
                f.write(f"{i + 1} 1 {xu[i, 0]!r} {xu[i, 1]!r} {xu[i, 2]!r} {image[i, 0]} {image[i, 1]} {image[i, 2]} "
                        f"{v[i, 0]!r} {v[i, 1]!r} {v[i, 2]!r}" +
                        (f" {2 * c['radius'][k][i]!r} {c['mass'][k][i]!r}\n" if sized else "\n"))


def write_ase_xyz(c, path):
    """Extended XYZ as ase.io.write(..., format='extxyz') lays it out: Lattice, Properties with momenta,
    pbc, each value %16.8f."""
    frames, n, d = c["x"].shape
    cell = np.diag(np.append(c["edges"], [0.0] * (3 - d)))
    pbc = " ".join("T" if a < d else "F" for a in range(3))
    sized = c["radius"] is not None
    props = "species:S:1:pos:R:3:momenta:R:3" + (":radius:R:1:masses:R:1" if sized else "")
    with open(path, "w") as f:
        for k in range(frames):
            lattice = " ".join(f"{x:.8f}" for x in cell.ravel())
            f.write(f'{n}\nLattice="{lattice}" Properties={props} pbc="{pbc}"\n')
            m = c["mass"][k] if sized else np.ones(n)
            x, p = padded(c["x"][k]), padded(c["v"][k]) * m[:, None]
            for i in range(n):
                f.write("Ar " + "".join(f"{val:16.8f}" for val in (*x[i], *p[i])) +
                        (f"{c['radius'][k][i]:16.8f}{m[i]:16.8f}" if sized else "") + "\n")


def analyses(inp, out_stem):
    """Every dataset of the three tools' outputs but time and step, by analysis."""
    results = {}
    for group, tool in TOOLS.items():
        out = f"{out_stem}.{group}.h5"
        run(tool, inp, "-o", out, "--quiet")
        with h5py.File(out, "r") as f:
            g = f[group]
            results[group] = {name: g[name][()] for name in g if name not in ("time", "step")}
    return results


def largest_difference(a, b, where, tolerance=1e-12):
    worst = 0.0
    for name in a:
        x, y = np.asarray(a[name], float), np.asarray(b[name], float)
        check(x.shape == y.shape, f"{where}/{name}: shape {y.shape}, H5MD gives {x.shape}")
        check(np.array_equal(np.isnan(x), np.isnan(y)), f"{where}/{name}: NaN where H5MD has none, or the reverse")
        if x.size:
            worst = max(worst, float(np.nanmax(np.abs(x - y), initial=0.0)))
    check(worst <= tolerance, f"{where}: differs from H5MD by {worst}")
    return worst


def refuses(tool, inp, needles, directory):
    """One line on stderr naming the problem, exit status 1, no output."""
    out = os.path.join(directory, "refused.h5")
    r = subprocess.run([tool, inp, "-o", out], capture_output=True, text=True)
    check(r.returncode == 1, f"{os.path.basename(inp)}: exit {r.returncode}, expected 1: {r.stderr}")
    check(r.stderr.count("\n") == 1, f"{os.path.basename(inp)}: not one line on stderr: {r.stderr!r}")
    for needle in needles:
        check(needle in r.stderr, f"{os.path.basename(inp)}: '{needle}' not in: {r.stderr}")
    check(not os.path.exists(out), f"{os.path.basename(inp)}: an output was written")


def main():
    with workdir() as d:
        j = lambda name: os.path.join(d, name)  # noqa: E731
        runs = {
            "2d": ["--dim", 2, "--L", 64, "--rho", 0.37, "--e", 0.5, "--tc", 1e-4, "--equilibrate", 2,
                   "--t-max", 60, "--snapshots", "0,20,60"],
            "mixture": ["--dim", 2, "--L", 48, "--rho", 0.3, "--e", 0.5, "--tc", 1e-4, "--radii", "0.5,0.35",
                        "--masses", "1,0.5",
                        "--t-max", 40, "--snapshots", "0,40"],
            "3d": ["--dim", 3, "--L", 12, "--rho", 0.5, "--e", 0.5, "--tc", 1e-4, "--t-max", 20,
                   "--snapshots", "0,20"],
        }
        report = []
        for name, args in runs.items():
            run(gg_sim, *args, "--seed", 5, "--velocities", "--quiet", "-o", j(f"sim-{name}.h5"))
            c = configuration(j(f"sim-{name}.h5"))
            write_h5md(c, j(f"{name}.h5"))
            reference = analyses(j(f"{name}.h5"), j(f"{name}-h5md"))
            check(any(np.nanmax(r["mean_mass"]) > 1 for r in [reference["cluster"]]), f"{name}: no clusters to compare")
            writers = {"gsd": write_gsd, "scaled.dump": lambda c, p: write_lammps_scaled(c, p, 1),
                       "unwrapped.dump": lambda c, p: write_lammps_unwrapped(c, p, 2), "xyz": write_ase_xyz}
            for suffix, write in writers.items():
                path = j(f"{name}.{suffix}")
                write(c, path)
                other = analyses(path, j(f"{name}-{suffix}"))
                for group in TOOLS:
                    tolerance = 1e-6 if suffix == "xyz" and group == "velocity" else 1e-12
                    worst = largest_difference(reference[group], other[group], f"{name}.{suffix} {group}", tolerance)
                    report.append(f"{name:8s} {suffix:15s} {group:12s} largest difference {worst:g}")

        # What the analyses cannot use, refused in one line.
        c = configuration(j("sim-2d.h5"))
        write_gsd(c, j("tilted.gsd"))
        with gsd_hoomd.open(j("tilted.gsd"), "rb") as f:
            s = f[0]
        s.configuration.box = [64, 64, 0, 0.5, 0, 0]
        with gsd_hoomd.open(j("tilted.gsd"), "wb") as f:
            f.append(s)
        refuses(gg_cluster, j("tilted.gsd"), ["tilted.gsd", "triclinic"], d)
        write_lammps_scaled(c, j("walls.dump"), 1)
        text = open(j("walls.dump")).read().replace("BOX BOUNDS pp pp pp", "BOX BOUNDS pp ff pp")
        open(j("walls.dump"), "w").write(text)
        refuses(gg_correlate, j("walls.dump"), ["walls.dump", "not periodic along y"], d)
        open(j("tilted.dump"), "w").write(text.replace("BOX BOUNDS pp ff pp", "BOX BOUNDS xy xz yz pp pp pp", 1))
        refuses(gg_domains, j("tilted.dump"), ["tilted.dump", "triclinic"], d)
        open(j("truncated.dump"), "w").write(text[: len(text) // 2])
        refuses(gg_cluster, j("truncated.dump"), ["truncated.dump", "truncated"], d)
        write_ase_xyz(c, j("skew.xyz"))
        lines = open(j("skew.xyz")).read().split("\n")
        lines[1] = lines[1].replace('Lattice="64.00000000 0.00000000', 'Lattice="64.00000000 3.00000000')
        open(j("skew.xyz"), "w").write("\n".join(lines))
        refuses(gg_cluster, j("skew.xyz"), ["skew.xyz", "triclinic"], d)
        lines[1] = 'Properties=species:S:1:pos:R:3 pbc="T T F"'
        open(j("nobox.xyz"), "w").write("\n".join(lines))
        refuses(gg_cluster, j("nobox.xyz"), ["nobox.xyz", "Lattice"], d)
        open(j("notes.txt"), "w").write("time,mean_mass\n1,2\n")
        refuses(gg_cluster, j("notes.txt"), ["notes.txt", "not an HDF5 file", "GSD", "LAMMPS", "XYZ"], d)
        text = open(j("walls.dump")).read().replace("BOX BOUNDS pp ff pp", "BOX BOUNDS pp pp pp")
        open(j("still.dump"), "w").write(text.replace(" vy type xs id ys vx zs", " type type xs id ys id2 zs"))
        refuses(gg_velocity, j("still.dump"), ["still.dump", "no velocities"], d)
        print("\n".join(report))
        print(f"{len(report)} comparisons with H5MD, largest difference "
              f"{max(float(r.split()[-1]) for r in report):g}")


main()
