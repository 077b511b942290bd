"""End-to-end: the fields and collision statistics of a run (fields.h5, collisions.h5, CSV tables)
read back with h5py/csv and checked against each other and against `granule analyze fields` on the
run's own snapshots; bad measurement settings are rejected with exit code 2 and no output."""
import csv
import json

import h5py
import numpy as np

from harness import WORK, check, finish, granule


N = 1500
out = WORK / "run"
result = granule("run", "--out", str(out), "--set", f"system.particles={N}", "--set", "system.restitution=0.9",
                 "--set", "boundary.kind=\"lees-edwards\"", "--set", "boundary.shear_velocity=10",
                 "--set", "initial.equilibrate=2", "--set", "run.until_collisions_per_particle=8",
                 "--set", "output.snapshot_every_collisions_per_particle=2", "--set", "fields.cells=[6, 8]",
                 "--set", "diagnostics.cells=[6, 8]",
                 "--set", "collisions.density_windows=[[0, 1500], [1500, 1e9]]",
                 "--set", "collisions.from_collisions_per_particle=1", "--set", "collisions.free_paths=true")
check(result.returncode == 0, f"run failed: {result.stderr}")

with h5py.File(out / "fields.h5") as f, h5py.File(out / "snapshots.h5") as snaps:
    check(f.attrs["format"] == b"granule-fields", "fields.h5 format attribute")
    check((f.attrs["nx"], f.attrs["ny"]) == (6, 8), "fields grid")
    c = f["frames/c"][:]
    check(np.allclose(c, [0, 2, 4, 6, 8]), f"fields frames go with the snapshots: {c}")
    check(f["instant/density"].shape == (5, 8, 6), f"field shape {f['instant/density'].shape}")
    for k in range(5):
        check(np.isclose(f["instant/count"][k].sum(), N), f"frame {k}: cell counts sum to N")
    # Interval averages: the collisional stress is positive-definite in trace, the total is kinetic + collisional.
    pc = f["average/pressure_collisional"][1:]
    check((pc >= 0).all() and pc.sum() > 0, "collisional pressure non-negative and present")
    total = f["average/total_xy"][1:]
    check(np.allclose(total, f["average/kinetic_xy"][1:] + f["average/collisional_xy"][1:]), "total stress (1.7)")
    check(f["average/collisional_xy"][1:].sum() < 0, "collisional shear stress is negative for positive shear")
    prof = f["profiles/velocity_x"][-1]
    y = f["profiles/y"][:]
    slope = np.polyfit(y, prof, 1)[0]
    check(abs(slope / 10.0 - 1.0) < 0.25, f"V_x(y) slope {slope} against γ = 10")
    instant_density = f["instant/density"][:]
    instant_temperature = f["instant/temperature"][:]

    # Heat flux (docs/macrostructure.md): q^(k) of each cell recomputed here from the snapshots,
    # q = q^(k) + q^(c), and the profiles are row means.
    area = f.attrs["length_x"] * f.attrs["length_y"] / 48
    for k in (1, 4):
        xy, v = snaps["positions"][k], snaps["velocities"][k]
        ix = np.minimum((xy[:, 0] / f.attrs["length_x"] * 6).astype(int), 5)
        iy = np.minimum((xy[:, 1] / f.attrs["length_y"] * 8).astype(int), 7)
        q = np.zeros((8, 6, 2))
        for cy in range(8):
            for cx in range(6):
                vc = v[(ix == cx) & (iy == cy)]
                c_pec = vc - vc.mean(axis=0)
                q[cy, cx] = (0.5 * (c_pec ** 2).sum(axis=1)[:, None] * c_pec).sum(axis=0) / area
        check(np.allclose(f["instant/heat_flux_kinetic_x"][k], q[:, :, 0], rtol=1e-8, atol=1e-9), f"frame {k}: q^(k)_x")
        check(np.allclose(f["instant/heat_flux_kinetic_y"][k], q[:, :, 1], rtol=1e-8, atol=1e-9), f"frame {k}: q^(k)_y")
        check(np.allclose(f["profiles/heat_flux_kinetic_y"][k], q[:, :, 1].mean(axis=1), rtol=1e-8, atol=1e-9),
              f"frame {k}: q^(k)_y(y) profile")
    for axis in ("x", "y"):
        qc = f[f"average/heat_flux_collisional_{axis}"][1:]
        check(np.abs(qc).sum() > 0, f"collisional heat flux {axis} present")
        check(np.allclose(f[f"average/heat_flux_total_{axis}"][1:], f[f"average/heat_flux_kinetic_{axis}"][1:] + qc),
              f"total heat flux {axis}")
        check(np.allclose(f[f"profiles/average_heat_flux_total_{axis}"][1:], f[f"average/heat_flux_total_{axis}"][1:].mean(axis=2)),
              f"average total heat flux profile {axis}")
    last_xy, last_v, last_offset = snaps["positions"][-1], snaps["velocities"][-1], snaps["shear_offset"][-1]
    lx, ly, sigma = f.attrs["length_x"], f.attrs["length_y"], f.attrs["diameter"]

# The flow measures of the last sample (timeseries.csv and summary.json, at the last snapshot),
# recomputed from the snapshot: 8 rows, band L_y/5, clusters at 1.1 σ by brute force with Δ.
counts = np.bincount(np.minimum((last_xy[:, 1] / ly * 8).astype(int), 7), minlength=8)
row_vx = np.bincount(np.minimum((last_xy[:, 1] / ly * 8).astype(int), 7), weights=last_v[:, 0], minlength=8) / counts
centres = (np.arange(8) + 0.5) * ly / 8
ys = np.sort(last_xy[:, 1])
band = max(((ys - y0) % ly < ly / 5).sum() for y0 in ys) / N
dx = last_xy[:, 0][None, :] - last_xy[:, 0][:, None]
dy = last_xy[:, 1][None, :] - last_xy[:, 1][:, None]
linked = np.zeros((N, N), bool)
for image in (-1, 0, 1):
    sx = dx + image * last_offset
    sx -= lx * np.round(sx / lx)
    linked |= np.hypot(sx, dy + image * ly) < 1.1 * sigma
labels = np.arange(N)
while True:
    relaxed = np.where(linked, labels[None, :], N).min(axis=1)
    relaxed = np.minimum(relaxed, labels)
    if (relaxed == labels).all():
        break
    labels = relaxed
expected = {"density_contrast": (counts.max() - counts.min()) / counts.mean(),
            "density_rms_deviation": np.sqrt(((counts / counts.mean() - 1) ** 2).mean()),
            "densest_band_mass_fraction": band,
            "velocity_profile_deviation": np.sqrt(((row_vx - 10.0 * (centres - ly / 2) / ly) ** 2).mean()) / 10.0,
            "largest_cluster_mass_fraction": np.bincount(labels).max() / N}
last_row = list(csv.DictReader(open(out / "timeseries.csv")))[-1]
flow = json.load(open(out / "summary.json"))["flow_classification"]
check(abs(flow["c"] - 8.0) < 1e-9 and abs(float(last_row["c"]) - 8.0) < 1e-9, "last sample at the last snapshot")
for name, value in expected.items():
    check(abs(float(last_row[name]) - value) < 1e-9 * max(1.0, abs(value)), f"timeseries {name}: {last_row[name]} vs {value}")
    check(abs(flow[name] - value) < 1e-9 * max(1.0, abs(value)), f"summary {name}: {flow[name]} vs {value}")
print("flow measures at c = 8 (N = 1500, U = 10, ẽ = 0.9):", {k: round(float(v), 4) for k, v in expected.items()})

# The same fields from the snapshots, computed afterwards, equal the ones measured during the run.
result = granule("analyze", "fields", str(out / "snapshots.h5"), "--cells", "6,8", "--out", str(WORK / "fs.h5"))
check(result.returncode == 0, f"analyze fields failed: {result.stderr}")
with h5py.File(WORK / "fs.h5") as f:
    check(np.allclose(f["instant/density"][:], instant_density, rtol=0, atol=1e-9), "analyze fields: density")
    check(np.allclose(f["instant/temperature"][:], instant_temperature, rtol=1e-9, atol=1e-12), "analyze fields: T")
    check(list(f["average/configurations"][:]) == [1, 2, 3, 4, 5], "running average over frames")
    check("collisional_xx" not in f["average"], "no collisional stress without collisions")

with h5py.File(out / "collisions.h5") as f:
    check(f.attrs["format"] == b"granule-collisions", "collisions.h5 format")
    check(abs(f.attrs["from_c"] - 1.0) < 1e-9, "measurement window start recorded")
    b = f["impact_parameters"]
    windows = b["windows/collisions"][:]
    check(len(windows) == 7 and (windows == N).all(), f"impact windows of N collisions: {windows}")
    total = b["total/counts"][:]
    check(total.sum() == 7 * N, f"every collision of the 7 windows counted once: {total.sum()}")
    split = b["density_window_0/counts"][:].sum() + b["density_window_1/counts"][:].sum()
    check(split == total.sum(), "two complementary density windows split the collisions")
    p = f["free_paths/total"]
    check(p.attrs["paths"] > 10 * N, "free paths recorded")
    check(p["counts"].shape == (100, 72), "free path histogram shape")
    check(abs(p.attrs["l0_matched"] - 2 * p.attrs["mean_length"]) < 1e-12, "matched l0 is twice the mean path")

rows = list(csv.DictReader(open(out / "free_paths.csv")))
check(len(rows) == 100 and "P_matched_eq_3_36" in rows[0], "free_paths.csv")
rows = list(csv.DictReader(open(out / "impact_parameters.csv")))
check(len(rows) == 50 and "beta_rho1" in rows[0], "impact_parameters.csv")
summary = json.load(open(out / "summary.json"))
check("free_paths" in summary["measurements"], "summary.json carries the measurement figures")

# Collision statistics after the fact: continuing the run from its snapshot at c = 2 follows the same
# physical state (with new round-off, so a statistically equivalent trajectory, not the same bits):
# its impact parameters must be drawn from the distribution a run measuring from c = 2 recorded
# (a two-sample chi-square test), over the same window.
common = ["--set", "system.particles=2000", "--set", "system.restitution=0.8", "--set", "run.until_collisions_per_particle=4",
          "--set", "output.snapshot_every_collisions_per_particle=2"]
result = granule("run", "--out", str(WORK / "plain"), *common)
check(result.returncode == 0, f"plain run failed: {result.stderr}")
result = granule("run", "--out", str(WORK / "from2"), *common, "--set", "collisions.from_collisions_per_particle=2")
check(result.returncode == 0, f"run measuring from c = 2 failed: {result.stderr}")
result = granule("analyze", "collisions", str(WORK / "plain"), "--frame", "1", "--collisions-per-particle", "2",
                 "--out", str(WORK / "replay"))
check(result.returncode == 0, f"analyze collisions failed: {result.stderr}")
with h5py.File(WORK / "replay" / "collisions.h5") as a, h5py.File(WORK / "from2" / "collisions.h5") as b:
    replayed, recorded = a["impact_parameters/total/counts"][:], b["impact_parameters/total/counts"][:]
    both = replayed + recorded
    used = both > 0
    chi2 = float((((replayed - recorded) ** 2)[used] / both[used]).sum())
    dof = int(used.sum()) - 1
    # chi-square with dof degrees of freedom: the 0.1% critical value is below dof + 4.3 sqrt(2 dof)
    check(recorded.sum() == 4000 and replayed.sum() == 4000, "replay and run count the same window")
    check(chi2 < dof + 4.3 * np.sqrt(2 * dof), f"replayed impact parameters follow the run's: chi2 {chi2:.1f}, {dof} dof")
    check(abs(a.attrs["from_c"] - 2.0) < 1e-12 and abs(a.attrs["to_c"] - 4.0) < 1e-12, "replay window recorded")
check((WORK / "replay" / "fields.h5").exists(), "replay writes fields with the collisional stress")
result = granule("analyze", "collisions", str(WORK / "plain"), "--frame", "7")
check(result.returncode == 2 and "--frame" in result.stderr, f"bad frame: {result.stderr}")

# Windows that collect nothing give empty statistics, not a failure.
empty = WORK / "empty_windows"
result = granule("run", "--out", empty, "--set", "system.particles=500", "--set", "run.until_collisions_per_particle=2",
                 "--set", "collisions.free_paths=true", "--set", "collisions.density_windows=[[1e9, 2e9]]",
                 "--set", "collisions.speed_windows=[[1e6, 2e6]]")
check(result.returncode == 0, f"empty windows: {result.stderr[-300:]}")
with h5py.File(empty / "collisions.h5") as f:
    check(f["free_paths/density_window_0"].attrs["paths"] == 0, "an empty density window is written with 0 paths")

# Bad input: clear error naming the key, exit code 2, nothing written.
bad = WORK / "bad"
result = granule("run", "--out", str(bad), "--set", "collisions.density_windows=[[2, 1]]")
check(result.returncode == 2 and "collisions.density_windows" in result.stderr, f"bad window: {result.stderr}")
check(not bad.exists(), "nothing written for a bad config")
result = granule("run", "--out", str(bad), "--set", "fields.enabled=3")
check(result.returncode == 2 and "fields.enabled" in result.stderr, f"bad boolean: {result.stderr}")
result = granule("analyze", "fields", str(out / "snapshots.h5"), "--cells", "0,3", "--out", str(WORK / "x.h5"))
check(result.returncode == 2 and "--cells" in result.stderr and not (WORK / "x.h5").exists(), "bad --cells")

finish()
