"""gg-sim --unwrapped's periodic images, read with h5py as H5MD 1.1 describes `image`
(https://www.nongnu.org/h5md/h5md.html, "Particles group": an Integer element whose step and time are
position's, hard-linked; R = r + L a is the absolute position), then through gg-export: GSD's
particles/image read by Debian's python3-gsd (HOOMD: unwrapped = position + image x box), the
LAMMPS dump's ix iy iz and the extended XYZ's image column. An elastic gas over a long time with
snapshots close together: between two snapshots dt apart a particle moves at most its speed times
dt, while a missing or wrong image jumps by a box edge. The same for a sheared run, whose images slide.
Usage: unwrapped_image_test.py GG_SIM GG_EXPORT"""
import sys

from fixture import check, require_modules, run, workdir

h5py, np, gsd_hoomd = require_modules("h5py", "numpy", "gsd.hoomd")
gg_sim, gg_export = sys.argv[1:3]
DT = 0.25

with workdir() as tmp:
    for dim, n, L in ((2, 100, 30.0), (1, 40, 80.0), (3, 200, 12.0)):
        h5 = f"{tmp}/u{dim}.h5"
        times = ",".join(str(DT * k) for k in range(161))
        run(gg_sim, "--dim", dim, "--N", n, "--L", L, "--e", 1, "--seed", 5, "--t-max", 40, "--snapshots", times,
            "--velocities", "--unwrapped", "--quiet", "-o", h5)
        with h5py.File(h5, "r") as f:
            pos, img = f["particles/all/position"], f["particles/all/image"]
            check(img["value"].dtype.kind == "i", f"{dim}D: image/value is {img['value'].dtype}, not an integer")
            check(img["value"].shape == pos["value"].shape, f"{dim}D: image {img['value'].shape}, position {pos['value'].shape}")
            # Hard links: the very same HDF5 objects, not copies.
            for name in ("step", "time"):
                check(h5py.h5o.get_info(img[name].id).addr == h5py.h5o.get_info(pos[name].id).addr,
                      f"{dim}D: image/{name} is not a hard link to position/{name}")
            check("unit" not in img["value"].attrs, f"{dim}D: an image counts box edges and has no unit")
            edges = f["particles/all/box/edges"]
            edges = edges["value"][0].diagonal() if isinstance(edges, h5py.Group) else edges[()]
            r, a, v = pos["value"][()], img["value"][()], f["particles/all/velocity/value"][()]
            collisions = f["observables/collisions_per_particle/value"][-1]
        unwrapped = r + a * edges
        step = np.diff(unwrapped, axis=0)
        # Twice the fastest speed seen in any snapshot times dt: far below the edge a wrong image adds.
        bound = 2 * np.abs(v).max() * DT
        check(bound < edges.min() / 4, f"{dim}D: the bound {bound:.3g} tells nothing in a box of {edges.min()}")
        check(np.abs(step).max() <= bound, f"{dim}D: unwrapped positions jump by up to {np.abs(step).max():.3g} "
              f"between snapshots {DT} apart (bound {bound:.3g})")
        crossings = np.abs(np.diff(a, axis=0)).sum()
        # (Rods stay in their order, so in 1D only those next to the boundary cross it.)
        check(crossings > 10, f"{dim}D: only {crossings} boundary crossings: the test shows nothing")
        check(np.all(a[0] == 0), f"{dim}D: a fresh start is not in image 0")
        check(collisions > 5, f"{dim}D: only {collisions} collisions per particle")

        out = f"{tmp}/u{dim}.gsd"
        run(gg_export, h5, "-o", out, "--quiet")
        with gsd_hoomd.open(out, "rb") as traj:
            check(len(traj) == len(r), f"{dim}D GSD: {len(traj)} frames")
            for k, frame in enumerate(traj):
                gi = np.asarray(frame.particles.image)
                check(gi.dtype.kind == "i" and gi.shape == (n, 3), f"{dim}D GSD frame {k}: image {gi.dtype} {gi.shape}")
                check(np.array_equal(gi[:, :dim], a[k]) and np.all(gi[:, dim:] == 0), f"{dim}D GSD frame {k}: image differs")
                box = np.asarray(frame.configuration.box[:3], dtype=float)[:dim]
                gsd_unwrapped = np.asarray(frame.particles.position, dtype=float)[:, :dim] + gi[:, :dim] * box
                # HOOMD's box is centred: its unwrapped position is H5MD's less half a box, in float32.
                check(np.abs(gsd_unwrapped - (unwrapped[k] - edges / 2)).max() <= 2.0 ** -22 * np.abs(unwrapped).max(),
                      f"{dim}D GSD frame {k}: unwrapped positions differ")

        run(gg_export, h5, "-o", f"{tmp}/u{dim}.dump", "--quiet")
        lines = open(f"{tmp}/u{dim}.dump").read().splitlines()
        header = "ITEM: ATOMS id type x y z ix iy iz vx vy vz radius"
        starts = [i for i, line in enumerate(lines) if line == header]
        check(len(starts) == len(r), f"{dim}D dump: {len(starts)} frames with '{header}'")
        for k, at in enumerate(starts):
            rows = np.array([line.split() for line in lines[at + 1:at + 1 + n]], dtype=float)
            x, ix = rows[:, 2:2 + dim], rows[:, 5:5 + dim]
            check(np.array_equal(ix, a[k]) and np.all(rows[:, 5 + dim:8] == 0), f"{dim}D dump frame {k}: ix iy iz differ")
            check(np.array_equal(x + ix * edges, unwrapped[k]), f"{dim}D dump frame {k}: x + ix L differs")

        # Extended XYZ: the image as a column of integers after the positions (Properties names it).
        run(gg_export, h5, "-o", f"{tmp}/u{dim}.xyz", "--quiet")
        lines = open(f"{tmp}/u{dim}.xyz").read().splitlines()
        frames = [i for i, line in enumerate(lines) if line == str(n)]
        check(len(frames) == len(r), f"{dim}D xyz: {len(frames)} frames")
        for k, at in enumerate(frames):
            check("Properties=species:S:1:pos:R:3:image:I:3:velo:R:3:radius:R:1 " in lines[at + 1],
                  f"{dim}D xyz frame {k}: Properties without the image: {lines[at + 1]}")
            words = [line.split() for line in lines[at + 2:at + 2 + n]]
            x = np.array([w[1:1 + dim] for w in words], dtype=float)
            ix = np.array([w[4:4 + dim] for w in words], dtype=np.int64)
            check(all(w[4 + a].lstrip("-").isdigit() for w in words for a in range(3)), f"{dim}D xyz frame {k}: image not integers")
            check(np.array_equal(ix, a[k]), f"{dim}D xyz frame {k}: image differs")
            check(np.array_equal(x + ix * edges, unwrapped[k]), f"{dim}D xyz frame {k}: x + image L differs")
        print(f"{dim}D: {crossings} crossings, unwrapped positions continuous, the same in GSD, the dump and XYZ")

    # A sheared run (gg-sim --shear-rate a): the images one L_y above have slid by a L_y t along x, so
    # the unwrapped position is r + image L + image_y a L_y t x^ (docs/DESIGN.md "Files"), on which a
    # particle moves at its velocity plus image_y a L_y along x. The formats' images are those of the
    # tilted box of the frame (a2 = (s, L_y, 0), s = a L_y t taken into [-L_x/2, L_x/2)).
    for dim, n, L in ((2, 100, 15.0), (3, 150, 9.0)):
        rate, h5, dt = 0.4, f"{tmp}/sheared{dim}.h5", 0.1
        times = ",".join(str(dt * k) for k in range(151))
        run(gg_sim, "--dim", dim, "--N", n, "--L", L, "--e", 1, "--shear-rate", rate, "--seed", 6, "--t-max", 15,
            "--snapshots", times, "--velocities", "--unwrapped", "--quiet", "-o", h5)
        with h5py.File(h5, "r") as f:
            r, a = f["particles/all/position/value"][()], f["particles/all/image/value"][()]
            v, t = f["particles/all/velocity/value"][()], f["particles/all/position/time"][()]
        jump = rate * L
        unwrapped = r + a * L
        unwrapped[:, :, 0] += a[:, :, 1] * jump * t[:, None]
        lab_v = v.copy()
        lab_v[:, :, 0] += a[:, :, 1] * jump
        # A wrong image moves a particle by L or more; the images slide by a L_y dt per snapshot.
        step, bound = np.abs(np.diff(unwrapped, axis=0)).max(), 2 * np.abs(lab_v).max() * dt
        check(bound < L / 2 and jump * dt < L / 4, f"sheared {dim}D: the bound {bound:.3g} tells nothing in a box of {L}")
        check(step <= bound, f"sheared {dim}D: unwrapped positions jump by {step:.3g} between snapshots (bound {bound:.3g})")
        crossings = np.abs(np.diff(a[:, :, 1], axis=0)).sum()
        check(crossings > 20, f"sheared {dim}D: only {crossings} crossings of the sliding edge")
        shift = np.mod(jump * t, L)
        shift = np.where(shift >= L / 2, shift - L, shift)

        def tilted(x, ix, k):  # x + ix a1 + iy a2 + iz a3 in the tilted box of frame k
            u = x + ix * L
            u[:, 0] += ix[:, 1] * shift[k]
            return u

        run(gg_export, h5, "-o", f"{tmp}/sheared{dim}.gsd", "--quiet")
        with gsd_hoomd.open(f"{tmp}/sheared{dim}.gsd", "rb") as traj:
            for k, frame in enumerate(traj):
                gi = np.asarray(frame.particles.image, dtype=float)[:, :dim]
                u = tilted(np.asarray(frame.particles.position, dtype=float)[:, :dim], gi, k)
                check(np.abs(u - (unwrapped[k] - L / 2)).max() <= 2.0 ** -21 * np.abs(unwrapped).max(),
                      f"sheared {dim}D GSD frame {k}: unwrapped positions differ")
        run(gg_export, h5, "-o", f"{tmp}/sheared{dim}.dump", "--quiet")
        lines = open(f"{tmp}/sheared{dim}.dump").read().splitlines()
        starts = [i for i, line in enumerate(lines) if line.startswith("ITEM: ATOMS")]
        for k, at in enumerate(starts):
            rows = np.array([line.split() for line in lines[at + 1:at + 1 + n]], dtype=float)
            u = tilted(rows[:, 2:2 + dim], rows[:, 5:5 + dim], k)
            check(np.abs(u - unwrapped[k]).max() <= 1e-12 * np.abs(unwrapped).max(),
                  f"sheared {dim}D dump frame {k}: x + ix a + iy b differs")
        run(gg_export, h5, "-o", f"{tmp}/sheared{dim}.xyz", "--quiet")
        lines = open(f"{tmp}/sheared{dim}.xyz").read().splitlines()
        frames = [i for i, line in enumerate(lines) if line == str(n)]
        check(len(frames) == len(r), f"sheared {dim}D xyz: {len(frames)} frames")
        for k, at in enumerate(frames):
            words = [line.split() for line in lines[at + 2:at + 2 + n]]
            x = np.array([w[1:1 + dim] for w in words], dtype=float)
            ix = np.array([w[4:4 + dim] for w in words], dtype=float)
            check(np.abs(tilted(x, ix, k) - unwrapped[k]).max() <= 1e-12 * np.abs(unwrapped).max(),
                  f"sheared {dim}D xyz frame {k}: x + image . Lattice differs")
        print(f"sheared {dim}D: {crossings} crossings of the sliding edge, unwrapped positions continuous, "
              "the same in GSD, the dump and XYZ")

    # --init FILE --continue starts in the images of the file's last frame, so the unwrapped
    # trajectory goes on where it stopped.
    run(gg_sim, "--init", f"{tmp}/u2.h5", "--e", 1, "--continue", "--t-max", 50, "--snapshots", 40, "--unwrapped",
        "--quiet", "-o", f"{tmp}/more.h5")
    with h5py.File(f"{tmp}/u2.h5", "r") as f, h5py.File(f"{tmp}/more.h5", "r") as g:
        last = f["particles/all/image/value"][-1]
        check(np.abs(last).sum() > 0 and np.array_equal(g["particles/all/image/value"][0], last),
              "--continue does not start from the file's images")

    # Without --unwrapped there is no image, and every reader goes on as before.
    h5 = f"{tmp}/plain.h5"
    run(gg_sim, "--N", 50, "--L", 20, "--e", 1, "--t-max", 2, "--snapshots", "1,2", "--quiet", "-o", h5)
    with h5py.File(h5, "r") as f:
        check("image" not in f["particles/all"], "an image without --unwrapped")
    run(gg_export, h5, "-o", f"{tmp}/plain.dump", "--quiet")
    check("ITEM: ATOMS id type x y z radius" in open(f"{tmp}/plain.dump").read(), "dump header without images changed")
    run(gg_export, h5, "-o", f"{tmp}/plain.xyz", "--quiet")
    check("Properties=species:S:1:pos:R:3:radius:R:1 " in open(f"{tmp}/plain.xyz").read(), "xyz header without images changed")
