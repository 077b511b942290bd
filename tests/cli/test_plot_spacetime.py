"""End-to-end: `granule plot spacetime` from a small Lees–Edwards run.  The arrays written beside the
picture equal the streamwise profiles recomputed here from the snapshot file with numpy (rows of the
full width: ρ = count / row area, V_x the row mean, T = ½(var v_x + var v_y), to round-off), with
velocities relative to u(y) = γ(t)(y − L_y/2) under --relative using the per-frame U(t) of the file;
from fields.h5 they equal its stored profiles exactly (instant) or the row means of the averaged maps
(average), and the instant fields agree with the snapshot binning on ρ and V_x, which do not depend
on how a row is cut into cells.  Bad input exits with code 2 writing nothing."""
import shutil

import h5py
import matplotlib.image
import numpy as np

from harness import WORK, check, finish, granule

ROUND_OFF = 1e-12


def close(a, b):
    """Equal to round-off, relative to the largest magnitude of the pair."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and np.max(np.abs(a - b), initial=0.0) <= ROUND_OFF * max(np.max(np.abs(b)), 1.0)


def binned_profiles(snapshots, rows, relative=False, shear_velocity=None):
    """(density, V_x, T) of every frame, (frames, rows), straight from the positions and velocities."""
    with h5py.File(snapshots) as f:
        lx, ly = f.attrs["box"]
        u_nominal = float(f.attrs["shear_velocity"])
        out = {name: [] for name in ("density", "velocity_x", "temperature")}
        for k in range(len(f["time"])):
            (x, y), (vx, vy) = f["positions"][k].T, f["velocities"][k].T
            if relative:
                u = shear_velocity[k] if shear_velocity is not None else u_nominal
                vx = vx - u / ly * (y - 0.5 * ly)
            row = np.clip((y / ly * rows).astype(int), 0, rows - 1)
            density, mean_vx, temperature = np.zeros(rows), np.zeros(rows), np.zeros(rows)
            for r in range(rows):
                inside = row == r
                density[r] = inside.sum() / (lx * ly / rows)
                if inside.any():
                    mean_vx[r] = vx[inside].mean()
                    temperature[r] = 0.5 * (np.var(vx[inside]) + np.var(vy[inside]))
            for name, values in zip(out, (density, mean_vx, temperature)):
                out[name].append(values)
    return {name: np.array(values) for name, values in out.items()}


def arrays(path):
    with h5py.File(path) as f:
        attrs = {k: v.decode() if isinstance(v, bytes) else v for k, v in f.attrs.items()}
        return {name: f[name][:] for name in ("t", "c", "y", "density", "velocity_x", "temperature")}, attrs, \
            ({name: f[f"protocol/{name}"][:] for name in ("t", "shear_velocity", "shear_offset")} if "protocol" in f else None)


# A small Lees–Edwards run: 800 disks, ẽ = 0.8, U = 20, a snapshot (and a fields frame) every c = 1.
run = WORK / "run"
r = granule("run", "--out", run, "--set", "system.particles=800", "--set", "system.restitution=0.8",
            "--set", "boundary.kind=lees-edwards", "--set", "boundary.shear_velocity=20",
            "--set", "run.until_collisions_per_particle=6", "--set", "output.snapshot_every_collisions_per_particle=1")
check(r.returncode == 0, f"run failed: {r.stderr}")
with h5py.File(run / "snapshots.h5") as f:
    times, cs, frames = f["time"][:], f["collisions_per_particle"][:], len(f["time"])
check(frames == 7, f"{frames} snapshots, expected 7")

# From the snapshots, 12 rows: the arrays are the numpy binning of every frame.
r = granule("plot", "spacetime", run, "--from", "snapshots", "--rows", 12)
check(r.returncode == 0, f"plot spacetime --from snapshots failed: {r.stderr}")
check(matplotlib.image.imread(str(run / "spacetime.png")).shape[:2] == (900, 1000), "spacetime.png is 10 × 9 in at 100 dpi")
got, attrs, protocol = arrays(run / "spacetime.h5")
expected = binned_profiles(run / "snapshots.h5", 12)
check(np.array_equal(got["t"], times) and np.array_equal(got["c"], cs), "frame times and c are the snapshots'")
check(close(got["y"], (np.arange(12) + 0.5) / 12), f"row centres {got['y']}")
for name in expected:
    check(close(got[name], expected[name]), f"snapshots: {name} differs from the numpy binning by "
          f"{np.max(np.abs(got[name] - expected[name])):.3g}")
check(got["density"].sum(axis=1).round(9).tolist() == [800 * 12.0] * frames, "rows hold every disk")
with h5py.File(run / "snapshots.h5") as f:
    stored_u = f["shear_velocity"][:frames]
check(attrs["source"] == "snapshots" and protocol is not None and np.array_equal(protocol["shear_velocity"], stored_u),
      "the per-frame U(t) of the snapshot file is kept")
print(f"snapshot rows: largest |ΔT| {np.max(np.abs(got['temperature'] - expected['temperature'])):.3g} "
      f"of T up to {expected['temperature'].max():.3g}")

# A protocol U(t) stored per frame (as the shear protocols write it): kept in the arrays, and
# --relative takes velocities relative to u(y) = U(t)/L_y (y − L_y/2) frame by frame.
ramp = run.with_name("ramp")
ramp.mkdir()
shutil.copy(run / "snapshots.h5", ramp / "snapshots.h5")
u_of_t = 20.0 * (1.0 - np.exp(-times / max(times[-1], 1e-300) * 3.0))
with h5py.File(ramp / "snapshots.h5", "a") as f:
    del f["shear_velocity"]  # replaced by a made-up ramp
    f["shear_velocity"] = u_of_t
    offsets = f["shear_offset"][:]
r = granule("plot", "spacetime", ramp, "--rows", 10, "--relative", "--data", ramp / "arrays.h5")
check(r.returncode == 0, f"plot spacetime --relative failed: {r.stderr}")
got, attrs, protocol = arrays(ramp / "arrays.h5")
expected = binned_profiles(ramp / "snapshots.h5", 10, relative=True, shear_velocity=u_of_t)
for name in expected:
    check(close(got[name], expected[name]), f"--relative: {name} differs from the numpy binning")
check(protocol is not None and np.array_equal(protocol["shear_velocity"], u_of_t) and np.array_equal(protocol["t"], times)
      and np.array_equal(protocol["shear_offset"], offsets), "protocol U(t), Δ(t) and t kept from the snapshot file")
check(int(attrs["relative"]) == 1 and (ramp / "spacetime.png").exists(), "--relative recorded, picture beside the input")

# From fields.h5 (the default when the run has one): the stored instantaneous profiles, exactly.
r = granule("plot", "spacetime", run, "--out", WORK / "fields.png")
check(r.returncode == 0, f"plot spacetime (fields) failed: {r.stderr}")
got, attrs, _ = arrays(WORK / "fields.h5")
with h5py.File(run / "fields.h5") as f:
    nx, ny = int(f.attrs["nx"]), int(f.attrs["ny"])
    stored = {name: f[f"profiles/{name}"][:] for name in ("y", "density", "velocity_x", "temperature")}
    field_t = f["frames/t"][:]
    average = {name: f[f"average/{name}"][:] for name in ("density", "velocity_x", "temperature")}
check(attrs["source"] == "fields/instant", f"source {attrs['source']}")
for name in stored:
    check(np.array_equal(got[name], stored[name]), f"fields/instant: {name} is not the stored profile")
# The same rows cut into nx cells or binned whole: ρ and V_x agree (T does not: the cells' own
# temperatures leave out the spread of their mean velocities within a row, so T_row ≥ T_cells).
if np.array_equal(field_t, times):
    whole = binned_profiles(run / "snapshots.h5", ny)
    check(close(got["density"], whole["density"]) and close(got["velocity_x"], whole["velocity_x"]),
          "fields/instant: ρ and V_x differ from the whole-row binning of the snapshots")
    check(np.all(whole["temperature"] >= got["temperature"] * (1.0 - ROUND_OFF)), "a whole row is colder than its cells")
else:
    check(False, f"fields frames at {field_t}, snapshots at {times}")
# The averaged group: row mean of ρ, mass-weighted V_x and T.
r = granule("plot", "spacetime", run / "fields.h5", "--group", "average", "--out", WORK / "average.png")
check(r.returncode == 0, f"plot spacetime --group average failed: {r.stderr}")
got, attrs, _ = arrays(WORK / "average.h5")
rho = average["density"]
weights = rho.sum(axis=2)
check(close(got["density"], weights / nx), "fields/average: ρ(y) is not the row mean")
for name in ("velocity_x", "temperature"):
    check(close(got[name], np.where(weights > 0, (rho * average[name]).sum(axis=2) / np.where(weights > 0, weights, 1), 0)),
          f"fields/average: {name} is not the mass-weighted row mean")

# Bad input: exit code 2, a message naming the option, and nothing written.
bad = {
    "rows": (["--from", "snapshots", "--rows", 0], "--rows"),
    "rows_fields": (["--from", "fields", "--rows", 8], "--rows"),
    "group": (["--group", "median"], "--group"),
    "from": (["--from", "timeseries"], "--from"),
    "dpi": (["--dpi", 5], "--dpi"),
}
for name, (args, expected_text) in bad.items():
    r = granule("plot", "spacetime", run, *args, "--out", WORK / "bad.png")
    check(r.returncode == 2 and expected_text in r.stderr, f"{name}: exit {r.returncode}, {r.stderr.strip()}")
r = granule("plot", "spacetime", run / "spacetime.png", "--out", WORK / "bad.png")
check(r.returncode == 2 and "HDF5" in r.stderr, f"a PNG as input: exit {r.returncode}, {r.stderr.strip()}")
check(not any(WORK.glob("bad*")), "bad input wrote something")

finish()
