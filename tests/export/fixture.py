"""What the interoperability tests share: skipping cleanly without a Python package, and small
gg-sim runs to read (1D and 2D, with velocities, a few snapshots)."""
import importlib
import os
import subprocess
import sys
import tempfile

SKIP = 77  # ctest SKIP_RETURN_CODE


def require_modules(*names):
    """Imports the modules, or exits with the skip code naming the Debian package to install."""
    modules = []
    for name in names:
        try:
            modules.append(importlib.import_module(name))
        except ImportError:
            print(f"skipped: Python module {name} is missing (apt-get install python3-{name.split('.')[0]})")
            sys.exit(SKIP)
    return modules


def run(*argv):
    """Runs a tool; a failure stops the test with the tool's stderr."""
    result = subprocess.run([str(a) for a in argv], capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"{' '.join(map(str, argv))} failed ({result.returncode}): {result.stderr.strip()}")
    return result


def simulate(gg_sim, directory, dim, extra=()):
    """A short cooling run: N = 300 (2D) or 100 (1D), four snapshots with velocities."""
    out = os.path.join(directory, f"sim{dim}d.h5")
    n, rho = (300, 0.2) if dim == 2 else (100, 0.3)
    run(gg_sim, "--dim", dim, "--N", n, "--rho", rho, "--e", 0.8, "--seed", 3, "--t-max", 4,
        "--snapshots", "0,1,2,4", "--velocities", "--quiet", *extra, "-o", out)
    return out


def workdir():
    return tempfile.TemporaryDirectory(prefix="gg-export-test.")


def check(condition, message):
    if not condition:
        sys.exit("FAILED: " + message)
