"""A run resumed with an output cadence it did not have (`--set` on `--resume`) writes at the new
cadence, counted from the run's origin: snapshots, samples and fields frames every 2 collisions
per disk from c = 10 to 20 after a first part that wrote only its initial and final states (the
checkpoint's old triggers, "never", were taken over before and nothing was written)."""
import csv

import h5py
import numpy as np

from harness import WORK, check, finish, granule

out = WORK / "run"
first = granule("run", "--out", out, "--set", "system.particles=800", "--set", "run.until_collisions_per_particle=10",
                "--set", "output.every_collisions_per_particle=5")
check(first.returncode == 0, f"first part: {first.stderr}")
with h5py.File(out / "snapshots.h5") as f:
    frames_before = f["positions"].shape[0]
check(frames_before == 2, f"first part wrote {frames_before} snapshot frames, expected the initial and final ones")

second = granule("run", "--resume", out, "--set", "run.until_collisions_per_particle=20",
                 "--set", "output.snapshot_every_collisions_per_particle=2", "--set", "output.every_collisions_per_particle=2")
check(second.returncode == 0, f"resumed part: {second.stderr}")
with h5py.File(out / "snapshots.h5") as f:
    c = np.asarray(f["collisions_per_particle"][()])
# Triggers at c = 12, 14, ..., 20 (20 is also the final state), each within one collision of 2k.
new = c[c > 10.0 + 1e-9]
check(len(new) == 5, f"resumed part wrote snapshots at c = {new.tolist()}, expected 12, 14, 16, 18, 20")
check(len(new) == 5 and np.all(np.abs(new - np.array([12.0, 14.0, 16.0, 18.0, 20.0])) <= 2.0 / 800), f"snapshot c = {new.tolist()}")

rows = [float(r["c"]) for r in csv.DictReader(open(out / "timeseries.csv"))]
later = [x for x in rows if x > 10.0 + 1e-9]
check(len(later) == 5, f"time series rows after the resume at c = {later}, expected every 2")
finish()
