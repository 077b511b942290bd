"""I/O failures of `granule run`: the disk fills up at many points of a run (the
LD_PRELOAD library tests/faults/fail_writes.c makes writes fail with ENOSPC or EIO once a byte
budget is spent), --out names a regular file or an unwritable directory, an output is /dev/full,
and stdout is /dev/full.  Each failure must end with exit code 4 (never an abort), one line on
stderr naming the file, and no incomplete file under a final name: what is there opens and is
whole (HDF5 per-frame datasets of equal length, JSON and TOML that parse, CSV rows complete, a
PNG that ends).  Run as `python3 test_io_faults.py GRANULE WORKDIR FAULT_LIBRARY`."""
import csv
import json
import os
import subprocess
import sys
import tomllib
from pathlib import Path

import h5py

from harness import GRANULE, WORK, check, finish

LIBRARY = sys.argv[3]
# A small run that writes every output: snapshots and fields frames every collision per
# particle, impact parameters, time series, summary and picture.
RUN = ["run", "--set", "system.particles=300", "--set", "run.until_collisions_per_particle=3",
       "--set", "output.snapshot_every_collisions_per_particle=1"]
OUTPUTS = ["config.toml", "snapshots.h5", "fields.h5", "timeseries.csv", "summary.json", "collisions.h5",
           "impact_parameters.csv", "configuration.png", "checkpoint.h5"]
EXIT_IO_FAILURE = 4


def run(out, fault=None, stdout=subprocess.PIPE):
    """granule run into `out`, with the fault library's settings `fault` (None: not loaded)."""
    env = dict(os.environ)
    if fault is not None:
        env["LD_PRELOAD"] = LIBRARY
        env["ASAN_OPTIONS"] = "verify_asan_link_order=0"  # sanitizer builds: the library comes first
        env.update({f"GRANULE_FAULT_{key}": str(value) for key, value in fault.items()})
    return subprocess.run([GRANULE, *RUN, "--out", str(out)], stdout=stdout, stderr=subprocess.PIPE, text=True,
                          env=env, timeout=120)


def frame_datasets(group):
    found = []
    group.visititems(lambda name, item: found.append(item) if isinstance(item, h5py.Dataset) and item.maxshape
                     and item.maxshape[0] is None else None)
    return found


def problems_of(path):
    """What is wrong with an output on its own (empty: it opens and is whole)."""
    try:
        if path.suffix == ".h5":
            with h5py.File(path, "r") as f:
                lengths = {d.name: d.shape[0] for d in frame_datasets(f)}
                if len(set(lengths.values())) > 1:
                    return f"per-frame datasets of unequal length {lengths}"
                if "format" not in f.attrs:
                    return "no format attribute"
        elif path.suffix == ".json":
            json.loads(path.read_text())
        elif path.suffix == ".toml":
            tomllib.loads(path.read_text())
        elif path.suffix == ".csv":
            rows = list(csv.reader(path.read_text().splitlines()))
            if not path.read_text().endswith("\n") or any(len(row) != len(rows[0]) for row in rows):
                return "incomplete rows"
            [float(value) for row in rows[1:] for value in row]
        elif path.suffix == ".png":
            data = path.read_bytes()
            if not data.startswith(b"\x89PNG\r\n\x1a\n") or not data.endswith(b"IEND\xaeB`\x82"):
                return "not a whole PNG"
    except Exception as error:  # noqa: BLE001 — any failure to read is the finding
        return f"unreadable: {error}"
    return ""


def check_failed_run(label, out, result, names):
    """A run that met an I/O failure: exit 4, one clear line naming the file, nothing incomplete."""
    check(result.returncode == EXIT_IO_FAILURE,
          f"{label}: exit code {result.returncode}, expected {EXIT_IO_FAILURE}; stderr: {result.stderr.strip()[-400:]}")
    lines = result.stderr.strip().splitlines()
    check(len(lines) == 1 and lines[0].startswith("granule: I/O error: "),
          f"{label}: stderr is not one clear line: {result.stderr.strip()[-400:]!r}")
    check(any(name in result.stderr for name in names), f"{label}: the message names none of {names}: {result.stderr.strip()}")
    for path in sorted(out.glob("**/*")) if out.is_dir() else []:
        check(path.suffix != ".tmp", f"{label}: temporary {path.name} left behind")
        # A growing file's journal (a flush written whole but not yet applied) stays beside it.
        if path.is_file() and path.suffix not in (".partial", ".journal"):
            check(not problems_of(path), f"{label}: {path.name} under its final name: {problems_of(path)}")
            check(same_as_clean(path), f"{label}: {path.name} under its final name differs from the clean run's")


def same_as_clean(path):
    """Outputs are reproducible bit for bit, so a published file must equal the clean run's; only
    summary.json differs (wall time), in its values, not its keys, and checkpoint.h5 may be an
    earlier, complete checkpoint of the same run (it holds the wall time too)."""
    reference = clean / path.name
    if path.name == "summary.json":
        return json.loads(path.read_text()).keys() == json.loads(reference.read_text()).keys()
    if path.name == "checkpoint.h5":
        with h5py.File(path, "r") as a, h5py.File(reference, "r") as b:
            return a.attrs["format"] == b.attrs["format"] and set(a["engine"].keys()) == set(b["engine"].keys())
    return path.read_bytes() == reference.read_bytes()


# 1. A clean run, and the bytes it writes to each output (measured by the library, no budget).
clean = WORK / "clean"
result = run(clean)
check(result.returncode == 0, f"clean run: exit {result.returncode}: {result.stderr}")
for name in OUTPUTS:
    check((clean / name).is_file() and not problems_of(clean / name), f"clean run: {name} missing or broken")
written = {}
for index, name in enumerate(OUTPUTS + [""]):
    report = WORK / f"bytes_{index}"
    out = WORK / f"measure_{index}"  # directory names must not contain the file names matched
    measured = run(out, {"PATH": name, "REPORT": report} if name else {"REPORT": report})
    check(measured.returncode == 0, f"measuring {name}: exit {measured.returncode}: {measured.stderr}")
    written[name] = int(report.read_text())
print("bytes written by a clean run:", written)

# 2. The disk fills up in each output: at its first byte, in the middle, just before its end, and
# after its last byte (then only the sync or the rename before publication fails); EIO once.
# summary.json holds the wall time, so its length varies by a few bytes from run to run.
cases = []
for name in OUTPUTS:
    size = written[name]
    ends = {size - 1, size} if name != "summary.json" else set()
    for budget in sorted({0, size // 3, size // 2} | ends):
        cases.append((name, budget, "ENOSPC"))
cases.append(("snapshots.h5", written["snapshots.h5"] // 2, "EIO"))
# ... and anywhere in the run: 20 budgets spread over everything it writes.
cases += [("", written[""] * k // 20, "ENOSPC") for k in range(20)]
for index, (name, budget, error) in enumerate(cases):
    label = f"{name or 'any file'} full after {budget} bytes ({error})"
    out = WORK / f"full_{index}"
    fault = {"BUDGET": budget, "ERRNO": error}
    if name:
        fault["PATH"] = name
    result = run(out, fault)
    check_failed_run(label, out, result, [name] if name else OUTPUTS + [str(out)])
print(f"{len(cases)} runs with a disk that fills up")

# 3. --out is a regular file: a command-line mistake (exit 2), the file untouched.
regular = WORK / "regular_file"
regular.write_text("not a directory\n")
result = run(regular)
check(result.returncode == 2 and str(regular) in result.stderr, f"--out is a regular file: {result.returncode} {result.stderr}")
check(regular.read_text() == "not a directory\n", "--out is a regular file: the file was changed")

# 4. A directory that already holds a file (here a link to /dev/full where the snapshots would go)
# is refused before anything is written (exit 2), and left as it was.
device = WORK / "device_full"
device.mkdir()
(device / "snapshots.h5.partial").symlink_to("/dev/full")
result = run(device)
check(result.returncode == 2 and "--force" in result.stderr, f"directory in use: {result.returncode} {result.stderr}")
check(sorted(p.name for p in device.iterdir()) == ["snapshots.h5.partial"], "directory in use: it was changed")

# 5. stdout is /dev/full: the outputs are written, the lost log is an I/O failure.
with open("/dev/full", "w") as full:
    stdout_full = WORK / "stdout_full"
    result = run(stdout_full, stdout=full)
    check_failed_run("stdout is /dev/full", stdout_full, result, ["standard output", "write"])


# 6. A directory without write permission.  Root ignores permission bits: then the directory is
# made immutable (chattr +i) or mounted read-only, and the case is skipped if neither works.
def make_unwritable(directory):
    if os.geteuid() != 0:
        directory.chmod(0o555)
        return lambda: directory.chmod(0o755), ""
    if subprocess.run(["chattr", "+i", str(directory)], capture_output=True).returncode == 0:
        return lambda: subprocess.run(["chattr", "-i", str(directory)]), ""
    bind = subprocess.run(["mount", "--bind", str(directory), str(directory)], capture_output=True, text=True)
    if bind.returncode == 0:
        if subprocess.run(["mount", "-o", "remount,bind,ro", str(directory)], capture_output=True).returncode == 0:
            return lambda: subprocess.run(["umount", str(directory)]), ""
        subprocess.run(["umount", str(directory)])
    return None, f"chattr +i and a read-only bind mount both failed ({bind.stderr.strip()})"


locked = WORK / "locked"
locked.mkdir()
undo, reason = make_unwritable(locked)
if undo is None:
    print(f"SKIPPED: unwritable --out directory: {reason}")
else:
    try:
        check_failed_run("--out is an unwritable directory", locked, run(locked), [str(locked)])
        check_failed_run("--out is inside an unwritable directory", locked, run(locked / "run"), [str(locked)])
        check(not any(locked.iterdir()), "unwritable directory: something was written")
    finally:
        undo()


# 7. The analyses of a run fill the disk while writing their HDF5 file: `granule analyze spectra`
# (flushed frame by frame as spectra.h5.partial) and `granule analyze f1` (written after its CSV
# tables).  The clean outputs go beside the clean run's, as references; a failed analysis exits 4
# with one line naming its file, and publishes no spectra.h5 or f1.h5 unless it equals the clean one.
# The f1 fits need b at every angle (thesis eq. 5.29): 1200 samples on 3×3 cells left an angle
# with fewer than three positive bins in some realizations (1 seed in 11), so the velocities are
# taken about the global mean (1 cell), which fitted in all 11.
ANALYSES = {"spectra.h5": ["analyze", "spectra", str(clean / "snapshots.h5"), "--max-mode", "8"],
            "f1.h5": ["analyze", "f1", str(clean / "snapshots.h5"), "--cells", "1,1", "--density-window", "0+-1e9",
                      "--temperature-window", "0+-1e9", "--min-samples", "10", "--bootstrap", "2",
                      "--speed-bins", "16", "--angle-bins", "16"]}


def analyze(name, out, fault=None):
    """The analysis writing `name` into the directory `out`, under the fault library with `fault`."""
    out.mkdir(parents=True, exist_ok=True)
    env = dict(os.environ, LD_PRELOAD=LIBRARY, ASAN_OPTIONS="verify_asan_link_order=0")
    env.update({f"GRANULE_FAULT_{key}": str(value) for key, value in (fault or {}).items()})
    return subprocess.run([GRANULE, *ANALYSES[name], "--out", str(out / name)], capture_output=True, text=True,
                          env=env, timeout=60)


for name in ANALYSES:
    report = WORK / f"analysis_bytes_{name}"
    result = analyze(name, clean, {"PATH": name, "REPORT": report})
    check(result.returncode == 0 and (clean / name).is_file(), f"clean {name}: exit {result.returncode}: {result.stderr}")
    size = int(report.read_text())
    # In the middle, just before the end (the close fails), and after the last byte (the rename fails).
    for budget in (size // 2, size - 1, size):
        label = f"{name} full after {budget} of {size} bytes"
        out = WORK / f"analysis_{name}_{budget}"
        result = analyze(name, out, {"PATH": name, "BUDGET": budget, "ERRNO": "ENOSPC"})
        lines = result.stderr.strip().splitlines()
        check(result.returncode == EXIT_IO_FAILURE and len(lines) == 1 and lines[0].startswith("granule: I/O error: ")
              and name in lines[0], f"{label}: exit {result.returncode}, stderr {result.stderr.strip()[-400:]!r}")
        for path in out.iterdir():
            check(path.suffix in (".partial", ".journal") or path.read_bytes() == (clean / path.name).read_bytes(),
                  f"{label}: {path.name} under its final name differs from the clean analysis's")
        check(not (out / name).exists(), f"{label}: {name} published")
print(f"{3 * len(ANALYSES)} analyses with a disk that fills up")
finish()
