"""The Python module granular_gas against the command-line tools on the same files: frames of every
format against the H5MD they came from, every analysis against gg-cluster, gg-correlate and gg-domains
(non-default options, every frame), the fits against gg-fit, and a few values known by hand.

Run by ctest (python_module) with PYTHONPATH at the built module and the tools in GG_SIM, GG_CLUSTER,
GG_CORRELATE, GG_DOMAINS, GG_FIT, GG_EXPORT.
"""
import os
import re
import subprocess

import h5py
import numpy as np
import pytest

import granular_gas as gg

TOOL = {name: os.environ[f"GG_{name.upper()}"]
        for name in ("sim", "cluster", "correlate", "domains", "velocity", "fit", "export")}
GRAIN = dict(grid=2.0, coarse=1, rho_c=0.4)
GRAIN_FLAGS = ["--grid", "2", "--coarse", "1", "--rho-c", "0.4"]


def run(*argv):
    subprocess.run([str(a) for a in argv], check=True, capture_output=True, text=True)


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    """A short 2D cooling run (L = 64) with velocities, and its GSD, XYZ and LAMMPS exports."""
    d = tmp_path_factory.mktemp("gg")
    run(TOOL["sim"], "--L", 64, "--rho", 0.37, "--e", 0.5, "--tc", 1e-4, "--equilibrate", 2, "--seed", 7,
        "--t-max", 100, "--snapshots-per-decade", 4, "--velocities", "--quiet", "-o", d / "run.h5")
    for suffix in ("gsd", "xyz", "dump"):
        run(TOOL["export"], d / "run.h5", "-o", d / f"run.{suffix}", "--quiet")
    return d


def h5md_frames(path):
    with h5py.File(path, "r") as f:
        p = f["particles/all"]
        return p["position/value"][()], p["velocity/value"][()], p["box/edges"][()], p["position/time"][()]


@pytest.mark.parametrize("suffix,tolerance", [("h5", 0), ("xyz", 0), ("dump", 0), ("gsd", 4e-6)])
def test_frames_hold_the_h5md_values(files, suffix, tolerance):
    x, v, box, time = h5md_frames(files / "run.h5")
    t = gg.Trajectory(str(files / f"run.{suffix}"))
    assert len(t) == len(x)
    for k in (0, len(x) // 2, -1):
        f = t[k]
        assert f.dim == 2 and f.n == x.shape[1]
        np.testing.assert_array_equal(f.box, box)
        # GSD holds float32 positions centred on the box: one float rounding of x - L/2.
        np.testing.assert_allclose(f.position, x[k], rtol=0, atol=tolerance * box[0])
        np.testing.assert_allclose(f.velocity, v[k], rtol=tolerance, atol=tolerance)
        assert f.time == pytest.approx(time[k], rel=1e-15)
        assert f.radius is None


def test_dump_rows_follow_the_atom_ids(files):
    """A dump whose rows come in no order and whose columns are its own: row i is atom id i + 1."""
    x, v, box, _ = h5md_frames(files / "run.h5")
    order = np.random.default_rng(3).permutation(x.shape[1])
    with open(files / "shuffled.dump", "w") as f:
        f.write(f"ITEM: TIMESTEP\n5\nITEM: NUMBER OF ATOMS\n{len(order)}\nITEM: BOX BOUNDS pp pp pp\n"
                f"0 {box[0]!r}\n0 {box[1]!r}\n-0.5 0.5\nITEM: ATOMS ys vx type xs id zs vy\n")
        for i in order:
            f.write(f"{x[-1, i, 1] / box[1]!r} {v[-1, i, 0]!r} 1 {x[-1, i, 0] / box[0]!r} {i + 1} 0.5 {v[-1, i, 1]!r}\n")
    (frame,) = gg.read_frames(str(files / "shuffled.dump"))
    assert frame.step == 5 and frame.time == 5
    np.testing.assert_allclose(frame.position, x[-1], rtol=0, atol=1e-12)
    np.testing.assert_array_equal(frame.velocity, v[-1])


def tool_output(tool, inp, out, *flags):
    run(TOOL[tool], inp, "-o", out, "--quiet", *GRAIN_FLAGS, *flags)
    return h5py.File(out, "r")


@pytest.mark.parametrize("suffix", ["h5", "gsd"])
def test_analyses_give_the_tools_numbers(files, suffix):
    inp = files / f"run.{suffix}"
    frames = gg.read_frames(str(inp))
    with tool_output("cluster", inp, files / f"c-{suffix}.h5", "--connectivity", "8", "--min-size", "2",
                     "--particle-clusters") as f, \
            tool_output("correlate", inp, files / f"k-{suffix}.h5", "--a", "0.3") as g, \
            tool_output("domains", inp, files / f"d-{suffix}.h5", "--phase", "rich") as h:
        c, k, d = f["cluster"], g["correlation"], h["domains"]
        for i, fr in enumerate(frames):
            cl = gg.clusters(fr.position, fr.box, connectivity=8, min_size=2, **GRAIN)
            np.testing.assert_array_equal([cl.mean_mass, cl.weight_mass, cl.count, cl.largest],
                                          [c["mean_mass"][i], c["weight_mass"][i], c["count"][i], c["largest"][i]])
            np.testing.assert_array_equal(
                [cl.largest_share, cl.largest_share_of_clustered, cl.rest_mean_mass],
                [c["largest_share"][i], c["largest_share_of_clustered"][i], c["rest_mean_mass"][i]])
            np.testing.assert_array_equal(cl.wraps, c["wraps"][i])
            np.testing.assert_array_equal(cl.cluster_idx, c["particle_cluster"][i])
            co = gg.correlation(fr.position, fr.box, a=0.3, **GRAIN)
            np.testing.assert_array_equal(co.r, k["r"][()])
            np.testing.assert_array_equal(co.C, k["C"][i])
            np.testing.assert_array_equal(co.length, k["length"][i])
            np.testing.assert_array_equal(co.k, k["k"][()])
            np.testing.assert_array_equal(co.S, k["S"][i])
            np.testing.assert_array_equal(co.k1, k["k1"][i])
            do = gg.domains(fr.position, fr.box, phase="rich", **GRAIN)
            np.testing.assert_array_equal(do.histogram, d["histogram"][i])
            np.testing.assert_array_equal(do.bin_edges, d["bin_edges"][()])
            assert (do.length, do.count) == (pytest.approx(d["length"][i], rel=0, abs=0), d["count"][i])
        assert np.nanmax(c["mean_mass"][()]) > 2, "no clusters: the comparison would prove nothing"


def test_velocity_statistics_give_gg_velocity_numbers(files):
    inp = files / "run.h5"
    run(TOOL["velocity"], inp, "-o", files / "v.h5", "--quiet")
    with h5py.File(files / "v.h5", "r") as f:
        g = f["velocity"]
        for i, fr in enumerate(gg.read_frames(str(inp))):
            s = gg.velocity_statistics(fr.velocity)
            assert (s.T, s.a2, s.a3) == (g["temperature"][i], g["a2"][i], g["a3"][i])
            assert s.a2_stderr == g["a2_stderr"][i]
    # Two particles of mass 1 moving apart at +-1 along x: T_x = 1, T_y = 0, every w = 1, so a2 = 1/2 * 1 - 1.
    s = gg.velocity_statistics(np.array([[1.0, 0.0], [-1.0, 0.0]]))
    assert list(s.temperature) == [1.0, 0.0] and s.T == 0.5 and s.a2 == pytest.approx(-0.5, abs=1e-15)


def test_density_by_hand():
    """Four particles in a 4 x 4 box, cells of 1, blocks of 3 x 3: each particle counts in 9 blocks."""
    pos = np.array([[0.5, 0.5], [0.5, 1.5], [3.5, 3.5], [2.2, 0.1]])
    field = gg.density(pos, np.array([4.0, 4.0]), grid=1.0, coarse=1, rho_c=3 / 9 - 1e-9)
    assert field.rho.shape == (4, 4) and field.counts.sum() == 4
    assert field.rho.mean() == pytest.approx(4 / 16, abs=1e-15)
    # Cell (0, 0) sees (0,0), (0,1) and the corner (3,3) through the periodic edges: 3 particles.
    assert field.rho[0, 0] == pytest.approx(3 / 9, abs=1e-15) and field.psi[0, 0] == 1
    assert field.rho[2, 2] == pytest.approx(1 / 9, abs=1e-15) and field.psi[2, 2] == -1
    cl = gg.clusters(pos, np.array([4.0, 4.0]), grid=1.0, coarse=1, rho_c=0.3)
    assert list(cl.masses) == sorted(cl.masses, reverse=True) and cl.labels.shape == (4, 4)


def test_cluster_idx_and_wrapping_by_hand():
    """A row of particles across an 8 x 8 box (cells of 1, no averaging) wraps along x only; a pair of
    particles is the second cluster; a lone particle in a cell below rho_c is in none."""
    row = [[x + 0.5, 2.5] for x in range(8)] * 2  # 2 per cell: 16 particles in y-row 2
    pair = [[5.5, 5.5], [5.5, 5.6], [5.5, 6.5], [5.5, 6.6]]  # 2 cells, 2 each
    lone = [[0.5, 6.5]]
    pos = np.array(row + pair + lone)
    cl = gg.clusters(pos, np.array([8.0, 8.0]), grid=1.0, coarse=0, rho_c=1.5)
    assert list(cl.masses) == [16, 4] and cl.count == 2
    assert list(cl.wraps) == [1, 0] and cl.cluster_wraps.tolist() == [[1, 0], [0, 0]]
    assert cl.cluster_idx.tolist() == [0] * 16 + [1] * 4 + [-1]
    assert (cl.largest_share, cl.largest_share_of_clustered, cl.rest_mean_mass) == (16 / 21, 16 / 20, 4.0)
    assert (cl.labels[1, 2], cl.labels[5, 6], cl.labels[0, 6]) == (0, 1, -1)  # labels[x, y]


def test_fits_give_gg_fit_numbers(files):
    """y = 3 t^0.7 exactly, then m(t) of the run against gg-fit power-law and local-exponent."""
    t = np.logspace(0, 3, 31)
    exact = gg.fit_power_law(t, 3 * t ** 0.7, (1, 1000))
    assert exact.exponent == pytest.approx(0.7, abs=1e-12) and exact.amplitude == pytest.approx(3, rel=1e-12)
    z = gg.local_exponent(t, 3 * t ** 0.7)
    np.testing.assert_allclose(z.exponent, 0.7, atol=1e-12)

    with tool_output("cluster", files / "run.h5", files / "m.h5") as f:
        time, m = f["cluster/time"][()], f["cluster/mean_mass"][()]
    run(TOOL["fit"], "power-law", f"{files / 'm.h5'}:/cluster/mean_mass", "--window", 10, 100, "-o", files / "fit.h5")
    run(TOOL["fit"], "local-exponent", f"{files / 'm.h5'}:/cluster/mean_mass", "-o", files / "le.h5")
    fit = gg.fit_power_law(time, m, (10, 100))
    with h5py.File(files / "fit.h5", "r") as f:
        assert fit.exponent == pytest.approx(float(np.ravel(f["fit/exponent"][()])[0]), rel=1e-12)
        assert fit.amplitude == pytest.approx(float(np.ravel(f["fit/amplitude"][()])[0]), rel=1e-12)
        assert fit.exponent_stderr == pytest.approx(float(np.ravel(f["fit/exponent_stderr"][()])[0]), rel=1e-12)
    positive = m > 0
    le = gg.local_exponent(time[positive], m[positive])
    with h5py.File(files / "le.h5", "r") as f:
        np.testing.assert_allclose(le.t, f["local_exponent/time"][()], rtol=1e-15)
        np.testing.assert_allclose(le.exponent, f["local_exponent/exponent"][()], rtol=1e-12)


def test_bad_input_is_refused_in_python_terms(tmp_path):
    (tmp_path / "notes.txt").write_text("time,mean_mass\n1,2\n")
    with pytest.raises(OSError, match="notes.txt.*not an HDF5 file"):
        gg.Trajectory(str(tmp_path / "notes.txt"))
    with pytest.raises(ValueError, match="N x 2"):
        gg.clusters(np.zeros((5, 3)), np.array([8.0, 8.0]))
    with pytest.raises(ValueError, match="--grid|grid"):
        gg.density(np.zeros((5, 2)), np.array([8.0, 8.0]), grid=20.0)
    with pytest.raises(ValueError, match="connectivity"):
        gg.clusters(np.zeros((5, 2)), np.array([8.0, 8.0]), connectivity=6)


def test_example_script_runs(files):
    """pipelines/examples/granular_gas_module.py on the GSD export: one line per frame, then the fit."""
    script = os.path.join(os.path.dirname(__file__), "..", "..", "pipelines", "examples", "granular_gas_module.py")
    out = subprocess.run([os.sys.executable, script, str(files / "run.gsd")], check=True, capture_output=True,
                         text=True).stdout
    frames = len(gg.Trajectory(str(files / "run.gsd")))
    assert f"GSD (HOOMD schema), {frames} frames" in out
    assert len([line for line in out.splitlines() if line.strip()[:1].isdigit() and "particles" not in line]) == frames
    # The printed exponent against a least-squares line of log m on log t written here, from the
    # module's m(t) of the same frames over the same window (the later half in log t).
    snapshots = list(gg.Trajectory(str(files / "run.gsd")))
    t = np.array([f.time for f in snapshots])
    m = np.array([gg.clusters(f.position, f.box, radius=f.radius).mean_mass for f in snapshots])
    ok = (t > 0) & np.isfinite(m) & (m > 0)
    t, m = t[ok], m[ok]
    inside = t >= np.sqrt(t[0] * t[-1])
    slope = np.polyfit(np.log(t[inside]), np.log(m[inside]), 1)[0]
    printed = float(re.search(r"z = (-?[0-9.]+)", out).group(1))
    assert printed == pytest.approx(slope, abs=1e-4)
