"""End-to-end: `granule analyze spectra` on a small Lees–Edwards run and a periodic run, read back with
h5py; the power at a few modes is recomputed independently with numpy from the snapshot positions
and velocities (thesis (3.4), (3.5), (3.17) on the lattice (3.10)–(3.12)); bad input exits 2 and
writes nothing."""
import csv
import math
from pathlib import Path

import h5py
import numpy as np

from harness import WORK, check, finish, granule


def simulate(name, *settings):
    result = granule("run", "--out", str(WORK / name), "--set", "system.particles=1500", "--set",
                     "system.area_fraction=0.05", "--set", "system.restitution=0.7", "--set",
                     "run.until_collisions_per_particle=6", "--set",
                     "output.snapshot_every_collisions_per_particle=2", *settings)
    check(result.returncode == 0, f"run {name} failed: {result.stderr}")
    return WORK / name / "snapshots.h5"


def exact_transforms(positions, velocities, kx, ky, mean_flow):
    """ρ̃, p̃′_x, p̃_y at wavevectors (kx, ky) by direct sums, m = 1, prefactor 1/2π."""
    phase = np.exp(1j * (np.outer(kx, positions[:, 0]) + np.outer(ky, positions[:, 1])))
    rho = phase.sum(axis=1) / (2 * math.pi)
    px = (phase * (velocities[:, 0] - mean_flow)).sum(axis=1) / (2 * math.pi)
    py = (phase * velocities[:, 1]).sum(axis=1) / (2 * math.pi)
    return rho, px, py


# 1. Lees–Edwards, fast method, shear profile subtracted, k_y axis left out of P_x.
box = (1.0, 1.5)
U = 20.0
snapshots = simulate("le", "--set", f"system.box=[{box[0]}, {box[1]}]", "--set", "boundary.kind=lees-edwards",
                     "--set", f"boundary.shear_velocity={U}")
out = WORK / "le_spectra.h5"
result = granule("analyze", "spectra", str(snapshots), "--out", str(out), "--max-mode", "12", "--frames", "1:",
                 "--subtract-shear", "--exclude-ky-axis")
check(result.returncode == 0, f"analyze failed: {result.stderr}")
M = 12
with h5py.File(snapshots) as snap, h5py.File(out) as f:
    check(f.attrs["format"] == b"granule-spectra" or f.attrs["format"] == "granule-spectra", "format attribute")
    check(f.attrs["max_mode"] == M and f.attrs["subtract_shear_profile"] == 1, "parameters recorded")
    frames = f["frame_index"][:]
    check(list(frames) == list(range(1, snap["time"].shape[0])), f"frames 1: selected, got {frames}")
    check(f["R"].shape == (len(frames), 2 * M + 1, 2 * M + 1), f"map shape {f['R'].shape}")
    sigma, n = snap.attrs["diameter"], snap.attrs["particles"]
    l = box[0] * box[1] / (2 * n * sigma)
    check(abs(f.attrs["L0"] - l / math.sqrt(1 - 0.7 ** 2)) < 1e-12 * f.attrs["L0"], "L0 = l/sqrt(1-e^2)")
    gamma = U / box[1]
    worst = 0.0
    for row, index in enumerate(frames):
        check(abs(f["time"][row] - snap["time"][index]) == 0, "time of the frame recorded")
        offset = snap["shear_offset"][index]
        xy, v = snap["positions"][index], snap["velocities"][index]
        # The thesis's lattice with [γt] = Δ/L_y ∈ [0, L_x/L_y): k = l k1 + m' k2.  The file may label the
        # same vectors differently (m = m' + shift·l); compare the stored (kx, ky) against the lattice.
        tilt = offset / box[1]
        kx, ky = f["kx"][row].ravel(), f["ky"][row].ravel()
        l_index = np.rint(kx * box[0] / (2 * math.pi))
        m_thesis = (ky + 2 * math.pi * l_index * tilt / box[0]) * box[1] / (2 * math.pi)
        check(np.allclose(m_thesis, np.rint(m_thesis), atol=1e-8), "stored k lie on the sheared lattice (3.10)")
        rho, px, py = exact_transforms(xy, v, kx, ky, gamma * (xy[:, 1] - box[1] / 2))
        for name, value in (("R", np.abs(rho) ** 2), ("Py", np.abs(py) ** 2)):
            stored = f[name][row].ravel()
            scale = np.maximum(value, n / (4 * math.pi ** 2) * (1 if name == "R" else np.mean(v[:, 1] ** 2)))
            worst = max(worst, float(np.max(np.abs(stored - value) / scale)))
        stored_px = f["Px"][row]
        check(np.all(np.isnan(stored_px[:, M])) and not np.any(np.isnan(stored_px[:, M + 1])),
              "P_x is NaN exactly on the k_y axis (l = 0)")
        off_axis = l_index != 0
        check(np.allclose(stored_px.ravel()[off_axis], (np.abs(px) ** 2)[off_axis],
                          rtol=1e-4, atol=1e-4 * np.mean(np.abs(px) ** 2)), "P_x' (3.17) off the k_y axis")
        dominant = f["dominant/R"]
        k = math.hypot(dominant["kx"][row], dominant["ky"][row])
        check(0 <= dominant["angle_deg"][row] < 180, "angle in [0, 180)")
        check(abs(dominant["length"][row] - 2 * math.pi / k) < 1e-12, "dominant length = 2π/|k|")
    check(worst < 1e-4, f"fast method power vs numpy exact sums: worst relative error {worst:.2e}")
    print(f"fast vs numpy exact (power, relative to max(power, ideal-gas level)): {worst:.2e}")
    annulus_k = f["annulus_k"][:]
    check(np.allclose(np.diff(annulus_k), f.attrs["dk"]), "annulus bins spaced by dk")

# The significance of the dominant R mode, recomputed from the stored maps: s = power/(N/4π²), and the
# false-alarm probability of the largest of K = ((2M+1)² − 1)/2 exponentials (docs/spectra.md).
with h5py.File(out) as f:
    d = f["dominant/R"]
    level = f.attrs["particles"] / (4 * math.pi ** 2)
    independent = ((2 * M + 1) ** 2 - 1) / 2
    for row in range(len(frames)):
        s = d["power"][row] / level
        check(abs(d["power_over_ideal_gas"][row] - s) < 1e-9 * s, "power over the ideal-gas level")
        check(d["independent_modes"][row] == independent, f"K = {independent}, got {d['independent_modes'][row]}")
        p = -math.expm1(independent * math.log1p(-math.exp(-s)))
        check(abs(d["noise_p_value"][row] - p) < 1e-9 + 1e-9 * p, f"p = 1 - (1 - e^-s)^K: {d['noise_p_value'][row]} vs {p}")
        check(d["significant"][row] == (p < 0.05), "significant = p < 0.05")
        threshold = -math.log(-math.expm1(math.log1p(-0.05) / independent))
        check(abs(d["noise_threshold"][row] - threshold) < 1e-6 * threshold, "threshold where p = 0.05")
    check("P" in f["dominant"] and "noise_p_value" in f["dominant/P"], "P has its significance too")
    check(f["S_R"].shape == f["annulus_R"].shape, "2D files carry the annulus-averaged S_R")
    check(f.attrs["false_alarm"] == 0.05 and f.attrs["format_version"] == 2, "false-alarm level and version 2")
lines = [line for line in result.stdout.splitlines() if line.startswith("  R:")]
check(len(lines) == len(frames) and all("significant" in line for line in lines),
      f"console says per frame whether R's mode is significant: {result.stdout}")
check("compared with L0 = l/√(1−ẽ²)" in result.stdout, "console says what the length is compared with")
check("frames (false-alarm level 0.05)" in result.stdout, "closing count of significant frames")

rows = list(csv.DictReader(open(WORK / "le_spectra_dominant.csv")))
check(len(rows) == 4 * len(frames), f"CSV has 4 fields per frame, got {len(rows)} rows")
check({"noise_p_value", "significant", "noise_threshold"} <= set(rows[0]), "CSV has the significance columns")
check({r["field"] for r in rows} == {"R", "Px", "Py", "P"}, "CSV fields")

# 2. Periodic box, exact method: the same numbers as the fast method to 1e-4 of the ideal-gas level.
snapshots = simulate("free")
fast, exact = WORK / "fast.h5", WORK / "exact.h5"
for path, method in ((fast, "fast"), (exact, "exact")):
    result = granule("analyze", "spectra", str(snapshots), "--out", str(path), "--max-mode", "10", "--frames", "-1",
                     "--method", method)
    check(result.returncode == 0, f"analyze --method {method} failed: {result.stderr}")
with h5py.File(fast) as a, h5py.File(exact) as b:
    level = a.attrs["particles"] / (4 * math.pi ** 2)
    check(np.max(np.abs(a["R"][0] - b["R"][0]) / np.maximum(b["R"][0], level)) < 1e-4, "fast = exact (R)")
    check(a["annulus_R"].shape == b["annulus_R"].shape, "annulus shapes")
    ky = b["ky"][0]
    check(np.allclose(ky[1:] - ky[:-1], 2 * math.pi), "periodic lattice k_y = 2πq/L_y")

# 3. Bad input: exit code 2, no output.
for args, what in ((["--max-mode", "0"], "--max-mode"), (["--dk", "-1"], "--dk"), (["--method", "slow"], "--method"),
                   (["--frames", "99"], "--frames"), (["--subtract-shear"], "--subtract-shear"),
                   (["--false-alarm", "1.5"], "--false-alarm")):
    bad = WORK / "bad.h5"
    result = granule("analyze", "spectra", str(snapshots), "--out", str(bad), *args)
    check(result.returncode == 2, f"{args}: exit code {result.returncode}, expected 2")
    check(what in result.stderr, f"{args}: message names {what}: {result.stderr}")
    check(not bad.exists() and not Path(str(bad) + ".partial").exists() and not (WORK / "bad_dominant.csv").exists(),
          f"{args}: no output written")
result = granule("analyze", "spectra", str(WORK / "missing.h5"), "--out", str(WORK / "bad.h5"))
check(result.returncode == 2, "missing snapshot file exits 2")

finish()
