"""End-to-end: `granule plot f1` draws the f1.h5 of `granule analyze f1` (on a small Lees–Edwards run,
four ρ × T windows) as a PNG of the documented size (read back with matplotlib's imread), and the
numbers it draws (the --data sidecar) are checked against the file and against independent results:
the sine-series curves b⁽ⁱ⁾(θ) are the Appendix B table evaluated here from its documented formula
(which also reproduces the file's b_series and f** profile), h(v, 2π) = 2πφ (5.18), the
Jenkins–Richman coefficients are those of the Gaussian with the measured ⟨v′v′⟩ (5.32)-(5.34), and
the per-window means, stresses and ratio equal the file and windows.csv.  --window selects the window
(negative from the end); bad input exits with code 2 naming the option, writing neither the PNG nor
the sidecar."""
import csv
import json
import math

import h5py
import matplotlib.image
import numpy as np

from harness import WORK, check, finish, granule

CELLS = 10


def series(table, theta):
    """b⁽ⁱ⁾(θ) = b₀⁽ⁱ⁾ + Σⱼ b₂ⱼ⁽ⁱ⁾ sin 2j(θ + ε₂ⱼ), written out term by term as docs/f1.md reads the table."""
    return np.array([[table[0, 1 + i] + sum(table[j, 1 + i] * math.sin(2 * j * (t + table[j, 0])) for j in range(1, 7))
                      for i in range(3)] for t in theta])


def median_cell_temperature(snapshots):
    """Median over the 10 × 10 cells of the last frame of T = ½⟨(v − V_cell)²⟩ (1.3): to centre the T windows."""
    with h5py.File(snapshots) as f:
        (lx, ly), xy, v = f.attrs["box"], f["positions"][-1], f["velocities"][-1]
    cell = np.minimum((xy[:, 0] / lx * CELLS).astype(int), CELLS - 1) + CELLS * np.minimum(
        (xy[:, 1] / ly * CELLS).astype(int), CELLS - 1)
    count = np.maximum(np.bincount(cell, minlength=CELLS ** 2), 1)
    mean = np.stack([np.bincount(cell, v[:, a], CELLS ** 2) / count for a in (0, 1)], axis=1)
    return float(np.median(0.5 * np.bincount(cell, ((v - mean[cell]) ** 2).sum(axis=1), CELLS ** 2) / count))


# 1. A small sheared run (3000 disks, ẽ = 0.8, U = 20, c = 8) and its f1 analysis in 2 × 2 windows:
# ρ of 20–30 and 30–40 disks per cell, T below and above the median cell temperature.
run = WORK / "run"
r = granule("run", "--out", run, *(a for s in ("system.particles=3000", "system.restitution=0.8",
                                               "boundary.kind=lees-edwards", "boundary.shear_velocity=20",
                                               "run.until_collisions_per_particle=8", "initial.equilibrate=1",
                                               "output.snapshot_every_collisions_per_particle=1") for a in ("--set", s)))
check(r.returncode == 0, f"run failed: {r.stderr}")
t = median_cell_temperature(run / "snapshots.h5")
cell_area = 1.0 / CELLS ** 2
f1 = run / "f1.h5"
r = granule("analyze", "f1", run / "snapshots.h5", "--out", f1, "--cells", f"{CELLS},{CELLS}", "--from-frame", 2,
            "--density-window", f"{25 / cell_area}±{5 / cell_area}", "--density-window", f"{35 / cell_area}±{5 / cell_area}",
            "--temperature-window", f"{0.6 * t}±{0.4 * t}", "--temperature-window", f"{1.4 * t}±{0.4 * t}",
            "--bootstrap", 4, "--min-samples", 1000, "--speed-bins", 32, "--angle-bins", 32)
check(r.returncode == 0, f"analyze f1 failed: {r.stderr}")

# 2. The default: f1.png beside f1.h5 in the run directory, window 0, 3 rows of 4 panels of 4 × 3.6 in.
r = granule("plot", "f1", run)
check(r.returncode == 0, f"plot f1 RUN failed: {r.stderr}")
if r.returncode == 0:
    shape = matplotlib.image.imread(str(run / "f1.png")).shape
    check(shape[:2] == (1080, 1600), f"f1.png: 1600 × 1080 px at 100 dpi, got {shape}")

with h5py.File(f1) as f, open(f1.with_name("f1_windows.csv")) as handle:
    names = sorted(f["windows"])
    csv_rows = list(csv.DictReader(handle))
    check(len(names) >= 2, f"several windows analysed: {names}")
    for window in (0, -1):
        out = WORK / f"window{window}.png"
        r = granule("plot", "f1", f1, "--window", window, "--out", out, "--data", out.with_suffix(".json"), "--dpi", 50)
        check(r.returncode == 0, f"plot f1 --window {window} failed: {r.stderr}")
        if r.returncode != 0:
            continue
        check(matplotlib.image.imread(str(out)).shape[:2] == (540, 800), "f1.png at 50 dpi")
        data = json.loads(out.with_suffix(".json").read_text())
        g = f["windows"][names[window]]
        label = f"--window {window}"
        check(data["group"] == names[window], f"{label}: drew {data['group']}, not {names[window]}")
        s, table = g.attrs["speed_scale"], g["table"][:]
        check(abs(s - math.sqrt(2 * g.attrs["temperature"])) < 1e-12 * s, f"{label}: speed scale √(2T)")

        # (A) h at θ = nπ/4, and h(v, 2π) = 2π φ (5.18).
        curves = data["once"]["h_at_n_pi_over_4"]
        check(np.allclose([c["theta"] for c in curves], np.arange(1, 9) * math.pi / 4, rtol=0, atol=1e-12),
              f"{label}: h drawn at θ = nπ/4")
        check(np.allclose(curves[-1]["h"], 2 * math.pi * g["phi"][:], rtol=0, atol=1e-12), f"{label}: h(v, 2π) ≠ 2πφ")
        check(np.array_equal(data["once"]["J_fit"], g["J_fit"][:]), f"{label}: J fit drawn")

        # (E) The drawn series is the table, evaluated here; the table also reproduces the file's b_series.
        theta = np.array(data["coefficients"]["series_theta"])
        unit = np.array([1, s, s * s])
        check(np.allclose(data["coefficients"]["series"], series(table, theta) * unit, rtol=1e-12, atol=1e-12),
              f"{label}: drawn b⁽ⁱ⁾(θ) curves differ from the Appendix B table")
        check(np.allclose(g["b_series"][:], series(table, g["theta"][:]), rtol=1e-10, atol=1e-10),
              f"{label}: table does not reproduce the file's b_series")
        check(np.allclose(data["coefficients"]["b"], g["b"][:] * unit, rtol=1e-12), f"{label}: (5.27) points")
        # f** = exp(−b⁽⁰⁾ − b⁽¹⁾v − b⁽²⁾v²) from the table at the profile angle = the file's profile.
        b = series(table, [g.attrs["profile_angle"]])[0]
        v = g["profile_speeds"][:]
        check(np.allclose(np.exp(-(b[0] + b[1] * v + b[2] * v * v)), g["f_twice_vs_speed"][:], rtol=1e-9),
              f"{label}: the table does not give the file's f** profile")
        check(np.allclose(data["twice"]["neglog_f_twice"], -np.log(g["f_twice_vs_speed"][:]), rtol=1e-12),
              f"{label}: −log f** at the profile angle")

        # Jenkins–Richman (5.32)-(5.34): the Gaussian with the measured K = ⟨v′v′⟩ (stress_direct):
        # −log f = log(2π√det K) + ½ vᵀK⁻¹v, so 2T b⁽²⁾(θ) = s² (K_yy cos² − 2K_xy cos sin + K_xx sin²)/2 det K.
        kxx, kxy, kyy = g["stress_direct"][:]
        det = kxx * kyy - kxy * kxy
        c, n = np.cos(theta), np.sin(theta)
        jr = data["coefficients"]["jenkins_richman"]
        check(abs(jr["b0"] - math.log(2 * math.pi * math.sqrt(det))) < 1e-9, f"{label}: Jenkins–Richman b⁽⁰⁾")
        check(np.allclose(jr["twoT_b2"], s * s * (kyy * c * c - 2 * kxy * c * n + kxx * n * n) / (2 * det), rtol=1e-9),
              f"{label}: Jenkins–Richman b⁽²⁾(θ)")
        check(np.array_equal(data["profiles"]["angle"]["jr"], g["f_jr_vs_angle"][:]), f"{label}: Fig 5.11 curve")

        # Row 3: every window, equal to the file and to windows.csv.
        check([w["name"] for w in data["windows"]] == names, f"{label}: row 3 draws every window")
        for w, name, row in zip(data["windows"], names, csv_rows):
            h = f["windows"][name]
            ws, wt = h.attrs["speed_scale"], h["table"][:]
            check(np.allclose(w["means"], wt[0, 1:] * [1, ws, ws * ws], rtol=1e-12), f"{name}: means ≠ table")
            check(np.allclose(w["means"], [float(row[k]) for k in ("b0_0", "sqrt2T_b1_0", "twoT_b2_0")], rtol=1e-8),
                  f"{name}: means ≠ windows.csv")
            check(np.array_equal(w["phases"], wt[1:, 0]), f"{name}: phases ≠ table")
            for kind in ("direct", "once", "twice"):
                stress = h[f"stress_{kind}"][:]
                check(abs(w["trace"][kind] - stress[0] - stress[2]) < 1e-12 * stress[0], f"{name}: Tr τ {kind}")
                check(abs(w["trace"][kind] - float(row[f"trace_{kind}"])) < 1e-8 * stress[0], f"{name}: csv trace {kind}")
            check(abs(w["ratio"] - wt[0, 2] ** 2 / wt[0, 3]) < 1e-9 * abs(w["ratio"]) + 1e-15,
                  f"{name}: ratio ≠ (b₀⁽¹⁾)²/b₀⁽²⁾ of the table")
            check(w["T"] == h.attrs["temperature"], f"{name}: T")
            # Robust bars: the 16th-84th percentiles of the replicates the file keeps (converged ones),
            # which the sd of the same replicates must match for this well-behaved spread within 2x.
            replicates = h["bootstrap_ratio"][:]
            check(len(replicates) == h.attrs["bootstrap_converged_replicates"], f"{name}: replicates kept")
            low, high = np.percentile(replicates, [16, 84])
            check(np.allclose(w["ratio_interval"], [low, high], rtol=1e-12), f"{name}: ratio interval = percentiles")
            check(np.std(replicates, ddof=1) == 0 or abs(np.std(replicates, ddof=1) / h.attrs["ratio_error"] - 1) < 1e-9,
                  f"{name}: the file's error is the sd of the kept replicates")
        check(set(data["clipped_bars"]) == {"means", "phases", "stress", "ratio"}, f"{label}: clipped bars counted")

# 3. Bad input: exit code 2, a message naming the option, and neither the PNG nor the sidecar.
bad_png, bad_json = WORK / "bad.png", WORK / "bad.json"
bad = {
    "window range": ([f1, "--window", 99], "--window"),
    "window text": ([f1, "--window", "first"], "--window"),
    "dpi": ([f1, "--dpi", 5], "--dpi"),
    "not f1": ([run / "snapshots.h5"], "granule-f1"),
    "no f1.h5": ([WORK], "f1.h5"),
}
for name, (args, expected) in bad.items():
    r = granule("plot", "f1", *args, "--out", bad_png, "--data", bad_json)
    check(r.returncode == 2, f"{name}: exit code {r.returncode} ({r.stderr.strip()})")
    check(expected in r.stderr, f"{name}: message lacks '{expected}': {r.stderr.strip()}")
    check(not bad_png.exists() and not bad_json.exists(), f"{name}: output written")
    check(not any(WORK.glob("bad.*.partial")), f"{name}: partial output left")

finish()
