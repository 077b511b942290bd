"""Obstacles through the real `granule run`: a flow past a cylinder stopped half-way and resumed from its
checkpoint ends with the same snapshots and time series as the run never stopped; the snapshot file
records the obstacles (dataset obstacles); the time series carries the drag and lift on each, and
the drag on the obstacles equals the momentum gravity puts into the flow less what the walls take
(steady state, averaged); the picture is drawn; exports write the obstacles beside the particles; bad obstacle input exits 2 naming the entry and
writes nothing; a snapshot whose grains lie inside an obstacle is refused."""
import csv

import h5py
import numpy as np

from harness import WORK, check, finish, granule

FLOW = ["--set", "system.particles=600", "--set", "system.diameter=0.02", "--set", "system.box=[2.0, 1.0]",
        "--set", "system.restitution=0.95", "--set", "system.gravity=[0.2, 0]", "--set", 'boundary.kind="walls"',
        "--set", 'boundary.wall_axes=["y"]', "--set", "boundary.wall_tangential_restitution=0.8",
        "--set", "initial.temperature=0.1", "--set", "output.every_time=0.5", "--set", "output.snapshot_every_time=2",
        "--set", "obstacles=[{ centre = [0.6, 0.5], diameter = 0.25, restitution = 0.9 }, "
                 "{ centre = [1.5, 0.2], diameter = 0.1, tangential_restitution = 0.5 }]"]


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


whole = WORK / "whole"
result = granule("run", "--out", whole, *FLOW, "--set", "run.until_time=8")
check(result.returncode == 0, f"whole run: {result.stderr}")
check("2 fixed obstacles" in result.stdout, f"the run describes its obstacles: {result.stdout}")
half = WORK / "half"
result = granule("run", "--out", half, *FLOW, "--set", "run.until_time=4")
check(result.returncode == 0, f"first half: {result.stderr}")
result = granule("run", "--resume", half, "--set", "run.until_time=8")
check(result.returncode == 0, f"resumed half: {result.stderr}")
with h5py.File(whole / "snapshots.h5") as a, h5py.File(half / "snapshots.h5") as b:
    check(np.array_equal(a["positions"][()], b["positions"][()]), "a resumed run's snapshots are the uninterrupted run's")
    obstacles = a["obstacles"][()]
    check(obstacles.shape == (2, 6) and obstacles[0, 3] == 0.25 and obstacles[1, 5] == 0.5,
          f"the snapshot file records the obstacles: {obstacles}")
series = rows(whole / "timeseries.csv")
check(series == rows(half / "timeseries.csv"), "a resumed run's time series is the uninterrupted run's")
for column in ("obstacles_drag", "obstacle0_drag", "obstacle0_lift", "obstacle1_collisions"):
    check(column in series[0], f"timeseries.csv has {column}")
# Momentum balance of the flow (per unit time, averaged over the second half): gravity's N m g_x equals
# the obstacles' drag plus the walls' shear stress times their length, up to the change of the flow's
# momentum (small once it is steady).
late = [r for r in series if float(r["t"]) > 4.0]
drag = np.mean([float(r["obstacles_drag"]) for r in late])
walls = np.mean([(float(r["wall_y0_shear_stress"]) + float(r["wall_y1_shear_stress"])) * 2.0 for r in late])  # × L_x
push = 600 * 0.2
print(f"drag {drag:.4g}, wall friction {walls:.4g}, gravity's push {push:.4g}")
check(drag > 0.0 and abs(drag + walls - push) < 0.1 * push,
      f"drag {drag} and wall friction {walls} balance gravity's push {push} within the flow's acceleration (10 %)")
check((whole / "configuration.png").exists(), "the picture is drawn")
for fmt, name in (("xyz", "obstacles.xyz"), ("vtk", "obstacles.vtp")):
    result = granule("plot", "export", whole, "--format", fmt)
    check(result.returncode == 0 and (whole / name).exists(), f"export --format {fmt} writes {name}: {result.stderr}")
lines = (whole / "obstacles.xyz").read_text().splitlines()
check(lines[0] == "2" and [float(v) for v in lines[3].split()[1:]] == [1.5, 0.2, 0.0, 0.0, 0.0, 0.0, 0.05],
      f"obstacles.xyz lists the obstacles with their radii: {lines}")

bad = WORK / "bad"
result = granule("run", "--out", bad, "--set", "system.particles=50",
                 "--set", "obstacles=[{ centre = [0.5, 9e9], diameter = 0.1 }]")
check(result.returncode == 2 and "obstacles[0] has its centre at y = 9000000000" in result.stderr,
      f"an obstacle outside the box is refused by name: {result.returncode} {result.stderr}")
check(not bad.exists(), "and nothing is written")

# A run continued from the flow's last frame with an obstacle put where grains are is refused.
moved = WORK / "moved"
result = granule("run", "--out", moved, "--set", f'initial.from="{whole}"', "--set", "run.until_time=1",
                 "--set", "system.particles=600", "--set", "system.diameter=0.02", "--set", "system.box=[2.0, 1.0]",
                 "--set", 'boundary.kind="walls"', "--set", 'boundary.wall_axes=["y"]',
                 "--set", "obstacles=[{ centre = [1.0, 0.5], diameter = 0.9 }]")
check(result.returncode == 2 and "inside obstacle 0" in result.stderr,
      f"grains inside an obstacle are refused: {result.returncode} {result.stderr[-400:]}")
finish()
