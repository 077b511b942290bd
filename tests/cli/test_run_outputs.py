"""End-to-end: `granule run` writes the documented outputs, read back by independent readers
(h5py, csv, json), and rejects bad input with exit code 2 and no output left behind."""
import csv
import json
import math
import subprocess

import h5py
import numpy as np

from harness import GRANULE, WORK, check, finish


def run(*args):
    return subprocess.run([GRANULE, "run", *args], capture_output=True, text=True, timeout=300)


config = WORK / "le.toml"
config.write_text("""seed = 4
[system]
particles = 1500
area_fraction = 0.1
box = [1.0, 1.5]
restitution = 0.8
[boundary]
kind = "lees-edwards"
shear_velocity = 20.0
[initial]
temperature = 1.0
equilibrate = 2
[run]
until_collisions_per_particle = 6
[output]
every_collisions_per_particle = 0.5
snapshot_every_collisions_per_particle = 2
""")
out = WORK / "le"
result = run(str(config), "--out", str(out))
check(result.returncode == 0, f"run failed: {result.stderr}")

# timeseries.csv: the documented columns, c on the requested grid, physical values.
rows = list(csv.DictReader(open(out / "timeseries.csv")))
for column in "t,c,kinetic_energy,temperature,flatness,pressure_kinetic,pressure_collisional,collision_rate".split(","):
    check(column in rows[0], f"timeseries.csv lacks {column}")
cs = [float(r["c"]) for r in rows]
check(abs(cs[0]) < 1e-12 and abs(cs[-1] - 6.0) < 1e-3 and len(rows) == 13, f"unexpected c grid {cs}")
check(all(float(r["temperature"]) > 0 for r in rows), "non-positive temperature")

summary = json.load(open(out / "summary.json"))
for key in ["particles", "diameter", "area_fraction", "box", "restitution", "boundary", "shear_velocity", "seed",
            "collisions", "events", "wall_seconds", "collisions_per_second", "t", "c", "version"]:
    check(key in summary, f"summary.json lacks {key}")
check(summary["collisions"] == 9000 and summary["boundary"] == "lees-edwards", f"summary {summary}")
sigma = math.sqrt(4 * 0.1 * 1.5 / (math.pi * 1500))
check(abs(summary["diameter"] / sigma - 1) < 1e-12, "diameter does not follow from the area fraction")
check("steady_shear" in summary, "Lees-Edwards summary lacks the (3.1)/(3.2) comparison")

with h5py.File(out / "snapshots.h5", "r") as f:
    check(f.attrs["format"] == b"granule-snapshots" or f.attrs["format"] == "granule-snapshots", "format attribute")
    check(f["positions"].shape == (4, 1500, 2), f"positions shape {f['positions'].shape}")
    check(abs(f.attrs["diameter"] - sigma) < 1e-15, "diameter attribute")
    xy, v, t = f["positions"][-1], f["velocities"][-1], f["time"][-1]
    offset = f["shear_offset"][-1]
    check(np.all((xy[:, 0] >= 0) & (xy[:, 0] < 1.0) & (xy[:, 1] >= 0) & (xy[:, 1] < 1.5)), "positions outside box")
    check(abs(t - summary["t"]) < 1e-12, "final snapshot time differs from the summary")
    # No overlaps, checked with the thesis's image rule (images above shifted by the offset).
    d = xy[:, None, :] - xy[None, :, :]
    best = np.inf
    for iy in (-1, 0, 1):
        dx = d[..., 0] + iy * offset
        dx -= np.round(dx)
        dy = d[..., 1] + iy * 1.5
        r = np.sqrt(dx * dx + dy * dy)
        np.fill_diagonal(r, np.inf)
        best = min(best, r.min())
    check(best > sigma * (1 - 1e-9), f"overlap: min distance {best / sigma} sigma")

# config.toml repeats the run: the same final state bit for bit.
again = run(str(out / "config.toml"), "--out", str(WORK / "again"))
check(again.returncode == 0, f"repeat failed: {again.stderr}")
with h5py.File(out / "snapshots.h5") as a, h5py.File(WORK / "again" / "snapshots.h5") as b:
    check(np.array_equal(a["positions"][-1], b["positions"][-1]), "resolved config.toml does not repeat the run")

# A run stopped at c = 4 and resumed to c = 6 ends in the same state as the uninterrupted run
# (snapshots every 2 in both, so both synchronise at c = 4), with the time series continued.
short = WORK / "short"
r = run(str(config), "--out", str(short), "--set", "run.until_collisions_per_particle=4")
check(r.returncode == 0, f"short run failed: {r.stderr}")
r = subprocess.run([GRANULE, "run", "--resume", str(short), "--set", "run.until_collisions_per_particle=6"],
                   capture_output=True, text=True, timeout=300)
check(r.returncode == 0, f"resume failed: {r.stderr}")
with h5py.File(out / "snapshots.h5") as a, h5py.File(short / "snapshots.h5") as b:
    check(b["positions"].shape[0] == 4, f"resumed file has {b['positions'].shape[0]} frames")
    check(np.array_equal(a["positions"][-1], b["positions"][-1]) and np.array_equal(a["velocities"][-1], b["velocities"][-1]),
          "resumed run differs from the uninterrupted one")
    check(a["time"][-1] == b["time"][-1], "resumed run ends at another time")
resumed_rows = list(csv.DictReader(open(short / "timeseries.csv")))
check([r["c"] for r in resumed_rows] == [r["c"] for r in rows], "resumed time series does not continue the original")

# Bad input: exit code 2, a message naming the key and the range, and nothing written.
bad_cases = {
    "malformed": ("[system\nparticles = 3", "malformed TOML"),
    "unknown": ("[system]\nparticle = 3", "system.particle"),
    "n": ("[system]\nparticles = 0", "system.particles"),
    "packing": ("[system]\nparticles = 100\narea_fraction = 0.95", "system.area_fraction"),
    "restitution": ("[system]\nrestitution = 1.2", "system.restitution"),
    "zero_e": ("[system]\nrestitution = 0", "(0, 1]"),
    "box": ("[system]\nparticles = 4\narea_fraction = 0.6", "too small"),
    "shear": ("[boundary]\nshear_velocity = 3", "boundary.shear_velocity"),
}
for name, (text, expected) in bad_cases.items():
    path = WORK / f"bad_{name}.toml"
    path.write_text(text)
    target = WORK / f"bad_{name}"
    r = run(str(path), "--out", str(target))
    check(r.returncode == 2, f"{name}: exit code {r.returncode}")
    check(expected in r.stderr, f"{name}: message lacks '{expected}': {r.stderr.strip()}")
    check(not target.exists(), f"{name}: output directory was created")
r = run("--set", "system.restitution=-1", "--out", str(WORK / "bad_set"))
check(r.returncode == 2 and "system.restitution" in r.stderr and not (WORK / "bad_set").exists(), "bad --set accepted")

finish()
