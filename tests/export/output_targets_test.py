"""Where gg-export writes, as the HDF5 tools do (common/src/output_target.hpp): a named pipe gets the
whole file and stays a pipe; /dev/null and /dev/full stay devices, whether the write succeeds or fails;
a symbolic link keeps pointing to the file it names, which the output replaces (or creates); an output
under a path that is a file, a frame named twice and a --format other than the output's name says are
refused in one line, nothing written.
Usage: output_targets_test.py GG_SIM GG_EXPORT"""
import os
import stat
import subprocess
import sys
import threading

from fixture import check, run, simulate, workdir

gg_sim, gg_export = sys.argv[1:3]


def export(h5, out, *extra):
    return subprocess.run([gg_export, h5, "-o", out, "--quiet", *extra], capture_output=True, text=True)


with workdir() as tmp:
    h5 = simulate(gg_sim, tmp, 2)
    run(gg_export, h5, "-o", f"{tmp}/plain.xyz", "--quiet")
    want = open(f"{tmp}/plain.xyz", "rb").read()

    fifo = f"{tmp}/out.fifo"
    os.mkfifo(fifo)
    received = []
    reader = threading.Thread(target=lambda: received.append(open(fifo, "rb").read()))
    reader.start()
    result = export(h5, fifo, "--format", "xyz")
    reader.join()
    check(result.returncode == 0, f"export to a FIFO: {result.returncode} {result.stderr.strip()}")
    check(stat.S_ISFIFO(os.lstat(fifo).st_mode), "the FIFO was replaced")
    check(received == [want], "the FIFO did not receive the whole file")

    check(export(h5, "/dev/null", "--format", "xyz").returncode == 0, "export to /dev/null failed")
    full = export(h5, "/dev/full", "--format", "xyz")
    check(full.returncode == 1 and len(full.stderr.strip().splitlines()) == 1 and "/dev/full" in full.stderr,
          f"export to /dev/full: {full.returncode} {full.stderr.strip()}")
    for device in ("/dev/null", "/dev/full"):
        check(stat.S_ISCHR(os.lstat(device).st_mode), f"{device} is no longer a device")

    os.mkdir(f"{tmp}/data")
    os.symlink("data/target.xyz", f"{tmp}/link.xyz")
    for round_ in ("dangling link", "link to a file"):
        result = export(h5, f"{tmp}/link.xyz")
        check(result.returncode == 0, f"{round_}: {result.returncode} {result.stderr.strip()}")
        check(os.path.islink(f"{tmp}/link.xyz"), f"{round_}: the link was replaced")
        check(open(f"{tmp}/data/target.xyz", "rb").read() == want, f"{round_}: the link's file is not the export")
        check(sorted(os.listdir(f"{tmp}/data")) == ["target.xyz"], f"{round_}: {os.listdir(f'{tmp}/data')}")

    under_a_file = export(h5, f"{tmp}/plain.xyz/out.xyz")
    check(under_a_file.returncode == 2 and len(under_a_file.stderr.strip().splitlines()) == 1 and
          "not a directory" in under_a_file.stderr, f"output under a file: {under_a_file.stderr.strip()}")
    check(open(f"{tmp}/plain.xyz", "rb").read() == want, "the file above the output was changed")
    for args, needle in ((("--frames", "1,-3"), "twice"), (("--format", "gsd"), "--format gsd")):
        refused = export(h5, f"{tmp}/refused.xyz", *args)
        check(refused.returncode == 2 and len(refused.stderr.strip().splitlines()) == 1 and needle in refused.stderr,
              f"{args}: {refused.returncode} {refused.stderr.strip()}")
        check(not os.path.exists(f"{tmp}/refused.xyz"), f"{args}: an output was written")
    print("FIFO, /dev/null, /dev/full, symlinks, an output under a file, a frame twice, a wrong --format: as for "
          "the HDF5 tools")
