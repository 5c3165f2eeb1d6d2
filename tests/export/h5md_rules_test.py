"""gg-sim's output against the rules of H5MD 1.1 (https://www.nongnu.org/h5md/h5md.html and its
units module), checked with h5py alone, as pyh5md and MDAnalysis's reader look at a file: the /h5md
group, author, creator, the box, time-dependent elements (step, time, value with T rows), id and
species, and a `unit` attribute on every element with a unit.
Usage: h5md_rules_test.py GG_SIM"""
import os
import sys

from fixture import check, require_modules, simulate, workdir

h5py, np = require_modules("h5py", "numpy")
gg_sim = sys.argv[1]

UNITS = {"particles/all/position/value": "sigma", "particles/all/velocity/value": "sigma tau-1",
         "particles/all/box/edges": "sigma", "observables/kinetic_energy/value": "m sigma2 tau-2"}


def check_time_dependent(f, path, n, dim):
    g = f[path]
    check(isinstance(g, h5py.Group), path + " is not a group")
    step, time, value = g["step"], g["time"], g["value"]
    check(step.dtype.kind == "i", path + "/step is not an integer dataset")
    check(step.shape == time.shape == value.shape[:1], f"{path}: step {step.shape}, time {time.shape}, value {value.shape}")
    check(np.all(np.diff(step[()]) >= 0), path + "/step decreases")
    if n is not None:
        check(value.shape[1:] == (n, dim), f"{path}/value has shape {value.shape}")
    check(time.attrs.get("unit") == "tau", f"{path}/time has unit {time.attrs.get('unit')!r}, expected 'tau'")


with workdir() as tmp:
    for dim in (2, 1):
        os.environ["GG_AUTHOR"] = "A. Uthor"
        h5 = simulate(gg_sim, tmp, dim, ["--pressure"])
        with h5py.File(h5, "r") as f:
            check(list(f["h5md"].attrs["version"]) == [1, 1], "/h5md version is not [1, 1]")
            check(f["h5md/author"].attrs["name"] == "A. Uthor", "author is not taken from $GG_AUTHOR")
            check(f["h5md/creator"].attrs["name"] == "gg-sim" and "version" in f["h5md/creator"].attrs, "creator")
            check(list(f["h5md/modules/units"].attrs["version"]) == [1, 0], "no units module version [1, 0]")
            box = f["particles/all/box"]
            check(box.attrs["dimension"] == dim, "box dimension")
            check([b.decode() if isinstance(b, bytes) else b for b in box.attrs["boundary"]] == ["periodic"] * dim,
                  "box boundary")
            check(box["edges"].shape == (dim,), "box/edges shape")
            n = f["particles/all/position/value"].shape[1]
            for element in ("position", "velocity"):
                check_time_dependent(f, "particles/all/" + element, n, dim)
            for name in f["observables"]:
                check_time_dependent(f, "observables/" + name, None, dim)
            check(np.array_equal(f["particles/all/id"][()], np.arange(n)), "id is not 0..N-1")
            check(f["particles/all/species"].shape == (n,) and f["particles/all/species"].dtype.kind == "i",
                  "species is not an integer [N] dataset")
            for path, unit in dict(UNITS, **{"observables/pressure/value": "m tau-2" if dim == 2 else "m sigma tau-2"}).items():
                got = f[path].attrs.get("unit")
                check(got == unit, f"{dim}D {path}: unit {got!r}, expected {unit!r}")
            check("unit" not in f["observables/collisions_per_particle/value"].attrs, "a count has no unit")
        # --author takes precedence over the environment.
        h5 = simulate(gg_sim, tmp, dim, ["--author", "B. Other"])
        with h5py.File(h5, "r") as f:
            check(f["h5md/author"].attrs["name"] == "B. Other", "--author is not written")
        print(f"{dim}D: the file follows the H5MD 1.1 rules checked here")
