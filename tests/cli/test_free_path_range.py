"""Free paths of a sheared run are all kept (README, `collisions.max_length`): lab-frame paths
carry the mean flow, and a range of 10 mean free paths fixed in advance dropped 17–35 % of them.  The
default range now widens; checked on a Lees–Edwards run (U = 100 in a unit box, as System III) and on
free cooling: every path recorded (summary.json and collisions.h5: binned counts = paths, overflow
0, dropped_fraction 0), and in the sheared run more than 1 % of the paths lie beyond the starting
range (so a fixed starting range would lose them: the test can tell).  A range given explicitly stays
fixed, and what it drops is reported."""
import json

import h5py
import numpy as np

from harness import WORK, check, finish, granule


def run(name, *settings):
    result = granule("run", "--out", WORK / name, "--set", "system.particles=2000", "--set",
                     "system.restitution=0.8", "--set", "collisions.free_paths=true", "--set",
                     "run.until_collisions_per_particle=20", "--set", "output.snapshot_every_collisions_per_particle=0",
                     "--set", "initial.equilibrate=1", *settings)
    check(result.returncode == 0, f"{name}: run failed: {result.stderr}")
    summary = json.load(open(WORK / name / "summary.json"))["measurements"]["free_paths"]
    with h5py.File(WORK / name / "collisions.h5") as f:
        g = f["free_paths"]
        counts, overflow = g["total/counts"][:], g["total/overflow"][:]
        edges, start = g["length_edges"][:], float(g.attrs["initial_max_length"])
    return summary, counts, overflow, edges, start, result.stdout


for name, settings in (("sheared", ["--set", "boundary.kind=lees-edwards", "--set", "boundary.shear_velocity=100"]),
                       ("cooling", [])):
    summary, counts, overflow, edges, start, _ = run(name, *settings)
    paths = summary["paths"]
    check(paths > 10000, f"{name}: paths recorded: {paths}")
    check(counts.sum() == paths and overflow.sum() == 0, f"{name}: binned {counts.sum()} of {paths}, overflow {overflow.sum()}")
    check(summary["dropped_fraction"] == 0.0, f"{name}: dropped fraction {summary['dropped_fraction']}")
    beyond = counts[np.searchsorted(edges, start, side="left"):].sum() / paths if edges[-1] > start else 0.0
    print(f"{name}: {paths:.0f} paths, range {start:.4g} -> {edges[-1]:.4g} ({summary['histogram_range_doublings']} "
          f"doublings), {100 * beyond:.1f} % beyond the starting range")
    if name == "sheared":
        check(beyond > 0.01, f"sheared: {beyond:.3f} of the paths beyond the starting range")

# A range given explicitly is kept: the drop is reported instead.
summary, counts, overflow, edges, start, _ = run("fixed", "--set", "boundary.kind=lees-edwards", "--set",
                                                 "boundary.shear_velocity=100", "--set", "collisions.max_length=0.01")
check(abs(edges[-1] - 0.01) < 1e-12 and summary["histogram_range_doublings"] == 0, "a given range stays fixed")
check(abs(summary["dropped_fraction"] - overflow.sum() / summary["paths"]) < 1e-12 and summary["dropped_fraction"] > 0.01,
      f"the fixed range's drop is reported: {summary['dropped_fraction']}")
print(f"fixed range 0.01: dropped fraction {summary['dropped_fraction']:.3f}")
finish()
