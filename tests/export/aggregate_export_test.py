"""gg-sim --aggregate's radii and masses through gg-export: the extended XYZ and LAMMPS radius column
and GSD's per-frame particles/diameter (twice the radius) and particles/mass (HOOMD schema), read by
small readers and Debian's python3-gsd, against the H5MD /particles/all/{radius,mass} read with h5py.
Usage: aggregate_export_test.py GG_SIM GG_EXPORT"""
import sys

from fixture import check, require_modules, run, workdir

h5py, np, gsd_hoomd = require_modules("h5py", "numpy", "gsd.hoomd")
gg_sim, gg_export = sys.argv[1:3]

with workdir() as tmp:
    h5 = f"{tmp}/bam.h5"
    run(gg_sim, "--dim", 2, "--N", 400, "--rho", 0.2, "--aggregate", "--seed", 2, "--t-max", 20,
        "--snapshots", "0,5,20", "--quiet", "-o", h5)
    with h5py.File(h5, "r") as f:
        radius = f["particles/all/radius/value"][()]
        mass = f["particles/all/mass/value"][()]
    check(radius.shape == (3, 400) and mass.shape == (3, 400), f"radius {radius.shape}, mass {mass.shape}")
    check(np.all(radius[0] == 0.5) and radius[-1].max() > 0.5, "the run shows no aggregate: the test shows nothing")

    run(gg_export, h5, "-o", f"{tmp}/bam.xyz", "--quiet")
    lines = open(f"{tmp}/bam.xyz").read().splitlines()
    for k in range(3):
        at = k * (400 + 2)
        check(lines[at + 1].split("Properties=")[1].startswith("species:S:1:pos:R:3:radius:R:1 "), "xyz Properties")
        column = np.array([line.split()[-1] for line in lines[at + 2:at + 402]], dtype=float)
        check(np.array_equal(column, radius[k]), f"xyz frame {k}: radii differ from the H5MD radii")

    run(gg_export, h5, "-o", f"{tmp}/bam.dump", "--frames", "-1", "--quiet")
    rows = open(f"{tmp}/bam.dump").read().splitlines()[-400:]
    check(np.array_equal(np.array([r.split()[-1] for r in rows], dtype=float), radius[-1]), "dump: radii differ")

    run(gg_export, h5, "-o", f"{tmp}/bam.gsd", "--quiet")
    with gsd_hoomd.open(f"{tmp}/bam.gsd", "rb") as traj:
        check(len(traj) == 3, f"GSD: {len(traj)} frames")
        for k, frame in enumerate(traj):
            d = np.asarray(frame.particles.diameter, dtype=float)
            m = np.asarray(frame.particles.mass, dtype=float)
            check(np.allclose(d, 2 * radius[k], rtol=2.0 ** -23, atol=0), f"GSD frame {k}: diameter is not 2 x radius")
            check(np.allclose(m, mass[k], rtol=2.0 ** -23, atol=0), f"GSD frame {k}: mass differs")
    print(f"radii up to {radius[-1].max():.3g} and masses up to {mass[-1].max():.0f}: the same in XYZ, the dump and GSD")
