"""A run SIGKILLed again and again while it writes a snapshot and a fields frame at every collision
per particle (so that many kills land inside an HDF5 flush) resumes every time and ends with files
identical to the run never interrupted.  Before flushes were journaled (io/journaled_file_driver.hpp)
such kills left chunk indices pointing to nodes never written: "wrong B-tree signature" or "addr
overflow", and in a stress test of 80 kills most resumes failed."""
import random
import signal
import subprocess
import time

import h5py
import numpy as np

from harness import GRANULE, WORK, check, finish, granule

SYSTEM = ["--set", "system.particles=1500", "--set", "system.restitution=0.9", "--set", "system.tc_duration=1e-7",
          "--set", "run.until_collisions_per_particle=300", "--set", "output.snapshot_every_collisions_per_particle=0.25",
          "--set", "output.checkpoint_every_seconds=0.02"]


def datasets(path):
    out = {}
    with h5py.File(path, "r") as f:
        f.visititems(lambda name, obj: out.__setitem__(name, obj[()]) if isinstance(obj, h5py.Dataset) else None)
    return out


reference = WORK / "reference"
result = granule("run", "--out", reference, *SYSTEM)
check(result.returncode == 0, f"reference run: {result.stderr}")

rng = random.Random(4)
killed = WORK / "killed"
command = [GRANULE, "run", "--out", str(killed), *SYSTEM]
kills, failures = 0, []
for attempt in range(60):
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    time.sleep(rng.uniform(0.05, 0.4))
    process.send_signal(signal.SIGKILL)
    code = process.wait(timeout=120)
    if code == 0:
        break  # it finished before the signal arrived
    kills += 1
    if code != -signal.SIGKILL:  # it stopped by itself: the resume failed
        failures.append(f"attempt {attempt}: exit {code}: {process.stderr.read()[-300:]}")
    resumable = (killed / "checkpoint.h5").exists()
    command = [GRANULE, "run", "--resume", str(killed)] if resumable else [GRANULE, "run", "--force", "--out", str(killed), *SYSTEM]
check(not failures, f"every resume after a SIGKILL runs: {failures[:2]}")
check(kills >= 20, f"at least twenty kills: {kills}")
if code != 0:
    result = subprocess.run(command, capture_output=True, text=True, timeout=300)
    check(result.returncode == 0, f"the last resume finishes: {result.stderr[-600:]}")
    if result.returncode != 0:
        finish()
check(not list(killed.glob("*.journal*")), "no journal is left once the run has ended")
for name in ("snapshots.h5", "fields.h5"):
    a, b = datasets(reference / name), datasets(killed / name)
    differing = [k for k in a if k not in b or a[k].shape != b[k].shape or not np.array_equal(a[k], b[k], equal_nan=True)]
    check(a and not differing, f"{name} of the killed run equals the reference: differing {differing[:5]}")
finish()
