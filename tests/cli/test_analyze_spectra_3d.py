"""End-to-end: `granule analyze spectra` and `granule plot spectra` on small 3D runs (spheres), read back
with h5py: the power on the plane k_z = 0, the dominant mode over the whole 3D lattice and the
shell-averaged S(k) are recomputed independently with numpy from the snapshot's positions and velocities
(thesis (3.4), (3.5), (3.17) on the sheared 3D lattice k = l k1 + m k2 + n k3, k1 = 2π(1, −Δ/L_y, 0)/L_x,
k2 = 2π ŷ/L_y, k3 = 2π ẑ/L_z); L0 uses the sphere mean free path 1/(√2 π n σ²); 3D limits of --max-mode
exit 2 and write nothing; the plot draws the shell spectra and the file's dominant mode."""
import csv
import json
import math
from pathlib import Path

import h5py
import numpy as np

from harness import WORK, check, finish, granule

BOX = (1.0, 1.2, 0.8)
U = 20.0
M = 6


def simulate(name, *settings):
    result = granule("run", "--out", str(WORK / name), "--set", "system.dimension=3", "--set",
                     "system.particles=1200", "--set", "system.packing_fraction=0.05", "--set",
                     f"system.box=[{BOX[0]}, {BOX[1]}, {BOX[2]}]", "--set", "system.restitution=0.7", "--set",
                     "run.until_collisions_per_particle=4", "--set", "output.snapshot_every_collisions_per_particle=2",
                     *settings)
    check(result.returncode == 0, f"run {name} failed: {result.stderr}")
    return WORK / name / "snapshots.h5"


def lattice(offset):
    """(l, m, n) and k of all modes |l|, |m|, |n| <= M, in the file's tilt convention (Δ/L_y taken in
    [−L_x/2L_y, L_x/2L_y): the same set of k as any other representative)."""
    tilt = offset / BOX[1]
    period = BOX[0] / BOX[1]
    tilt -= period * math.floor(tilt / period + 0.5)
    l, m, n = np.meshgrid(*(np.arange(-M, M + 1),) * 3, indexing="ij")
    l, m, n = l.ravel(), m.ravel(), n.ravel()
    k = np.stack([2 * math.pi * l / BOX[0], 2 * math.pi * (m / BOX[1] - l * tilt / BOX[0]), 2 * math.pi * n / BOX[2]], 1)
    return l, m, n, k


def exact_power(positions, weights, k):
    """|(1/2π) Σ_j w_j e^{ik·r_j}|² for every row of k and every weight column, by direct sums."""
    out = np.zeros((len(k), weights.shape[1]))
    for start in range(0, len(k), 500):
        phase = np.exp(1j * positions @ k[start:start + 500].T)  # (N, modes)
        out[start:start + 500] = np.abs(phase.T @ weights / (2 * math.pi)) ** 2
    return out


snapshots = simulate("le", "--set", "boundary.kind=lees-edwards", "--set", f"boundary.shear_velocity={U}")
out = WORK / "le_spectra.h5"
result = granule("analyze", "spectra", str(snapshots), "--out", str(out), "--max-mode", M, "--frames", "1:",
                 "--subtract-shear", "--exclude-ky-axis")
check(result.returncode == 0, f"analyze failed: {result.stderr}")
with h5py.File(snapshots) as snap, h5py.File(out) as f:
    check(int(f.attrs["dimension"]) == 3 and len(f.attrs["box"]) == 3, "3D file: dimension and box")
    frames = f["frame_index"][:]
    check(list(frames) == list(range(1, snap["time"].shape[0])), f"frames 1: selected, got {frames}")
    check(f["R"].shape == (len(frames), 2 * M + 1, 2 * M + 1), f"plane map shape {f['R'].shape}")
    n_particles, sigma = int(snap.attrs["particles"]), float(snap.attrs["diameter"])
    density = n_particles / (BOX[0] * BOX[1] * BOX[2])
    l0 = 1 / (math.sqrt(2) * math.pi * density * sigma ** 2) / math.sqrt(1 - 0.7 ** 2)
    check(abs(f.attrs["L0"] - l0) < 1e-12 * l0, f"L0 = l/sqrt(1-e^2) with the sphere l: {f.attrs['L0']} vs {l0}")
    gamma = U / BOX[1]
    worst = 0.0
    for row, index in enumerate(frames):
        r, v = snap["positions"][index], snap["velocities"][index].copy()
        v[:, 0] -= gamma * (r[:, 1] - BOX[1] / 2)
        l, m, n, k = lattice(snap["shear_offset"][index])
        power = exact_power(r, np.column_stack([np.ones(len(r)), v]), k)  # R, Px', Py, Pz
        ideal_r = n_particles / (4 * math.pi ** 2)
        # The plane k_z = 0 as stored, indexed [m + M, l + M].
        plane = n == 0
        for column, name in ((0, "R"), (2, "Py"), (3, "Pz")):
            stored = f[name][row].ravel()
            expected = power[plane, column].reshape(2 * M + 1, 2 * M + 1).T.ravel()  # meshgrid is [l, m]
            level = ideal_r if name == "R" else np.sum(v[:, column - 1] ** 2) / (4 * math.pi ** 2)
            worst = max(worst, float(np.max(np.abs(stored - expected) / np.maximum(expected, level))))
        check(np.allclose(f["kx"][row].ravel(), k[plane, 0].reshape(2 * M + 1, 2 * M + 1).T.ravel(), atol=1e-12),
              "stored k_x of the plane")
        # Dominant mass mode over the whole 3D lattice, k = 0 excluded.
        origin = (l == 0) & (m == 0) & (n == 0)
        best = np.argmax(np.where(origin, -1, power[:, 0]))
        d = f["dominant/R"]
        stored_k = np.array([d["kx"][row], d["ky"][row], d["kz"][row]])
        check(np.allclose(np.abs(stored_k @ k[best]), np.dot(k[best], k[best]), rtol=1e-9),
              f"dominant R mode: file {stored_k}, numpy {k[best]}")
        check(abs(d["power_over_ideal_gas"][row] - power[best, 0] / ideal_r) < 1e-4 * power[best, 0] / ideal_r,
              "dominant power over the uncorrelated level")
        check(abs(d["length"][row] - 2 * math.pi / np.linalg.norm(k[best])) < 1e-9, "dominant length = 2π/|k|")
        check(0 < d["noise_p_value"][row] <= 1, "noise p-value in (0, 1]")
        # P_x' is left out exactly on the k_y axis (l = n = 0): NaN in the plane's column l = 0.
        px = f["Px"][row]
        check(np.all(np.isnan(px[:, M])) and not np.any(np.isnan(px[:, M + 1])), "P_x NaN exactly on the k_y axis")
        # Shell averages: modes with (b − ½)Δk ≤ |k| < (b + ½)Δk.
        shells = np.floor(np.linalg.norm(k, axis=1) / f.attrs["dk"] + 0.5)
        for b, centre in enumerate(f["shell_k"][:]):
            inside = shells == b + 1
            check(f["shell_modes"][row][b] == inside.sum(), f"shell {b}: mode count")
            expected = power[inside, 0].mean() / ideal_r
            check(abs(f["S_R"][row][b] - expected) < 1e-4 * expected, f"shell {b}: S_R {f['S_R'][row][b]} vs {expected}")
            check(abs(f["S_R_sd"][row][b] - math.sqrt(2 / inside.sum())) < 1e-12, f"shell {b}: band sqrt(2/c)")
    check(worst < 1e-4, f"fast method vs numpy exact sums on k_z = 0: worst relative error {worst:.2e}")
    print(f"3D fast vs numpy exact (power on k_z = 0, relative to max(power, ideal-gas level)): {worst:.2e}")

rows = list(csv.DictReader(open(WORK / "le_spectra_dominant.csv")))
check(len(rows) == 5 * len(frames), f"CSV has 5 fields per frame, got {len(rows)} rows")
check({r["field"] for r in rows} == {"R", "Px", "Py", "Pz", "P"}, "CSV fields")
check("kz" in rows[0] and "noise_p_value" in rows[0], "CSV has the 3D columns")

# Periodic run, exact method: the same numbers as the fast method to 1e-4 of the ideal-gas level.
periodic = simulate("free")
fast, exact = WORK / "fast.h5", WORK / "exact.h5"
for path, method in ((fast, "fast"), (exact, "exact")):
    result = granule("analyze", "spectra", str(periodic), "--out", str(path), "--max-mode", 5, "--frames", "-1",
                     "--method", method)
    check(result.returncode == 0, f"analyze --method {method} failed: {result.stderr}")
with h5py.File(fast) as a, h5py.File(exact) as b:
    level = a.attrs["particles"] / (4 * math.pi ** 2)
    check(np.max(np.abs(a["R"][0] - b["R"][0]) / np.maximum(b["R"][0], level)) < 1e-4, "fast = exact (R)")
    check(np.allclose(a["S_R"][0], b["S_R"][0], rtol=1e-4), "fast = exact (S_R)")
    check(a["dominant/R/k"][0] == b["dominant/R/k"][0], "fast and exact agree on the dominant mode")

# The plot: shell spectra with their band, the dominant mode of the file.
png = WORK / "spectra3d.png"
result = granule("plot", "spectra", out, "--out", png, "--data", png.with_suffix(".json"), "--frame", -1)
check(result.returncode == 0 and png.exists(), f"plot spectra of a 3D file failed: {result.stderr}")
if result.returncode == 0:
    data = json.loads(png.with_suffix(".json").read_text())
    with h5py.File(out) as f:
        check(np.allclose(data["shells"]["S_R"], f["S_R"][-1]), "plot draws S_R of the frame")
        check(np.allclose(data["maps"]["R"]["dominant_k"], [f["dominant/R/kx"][-1], f["dominant/R/ky"][-1]]),
              "plot marks the dominant mode")

# Bad input: the 3D limit of --max-mode, exit 2 and nothing written.
bad = WORK / "bad.h5"
result = granule("analyze", "spectra", str(periodic), "--out", str(bad), "--max-mode", 257)
check(result.returncode == 2 and "--max-mode" in result.stderr, f"--max-mode 257 in 3D: {result.returncode} {result.stderr}")
check(not bad.exists() and not Path(str(bad) + ".partial").exists(), "nothing written on bad input")

finish()
