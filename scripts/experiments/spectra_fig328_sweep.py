#!/usr/bin/python3
"""Recipe for the data of thesis Fig 3.28: the dominant length scale of the density field of sheared
(Lees–Edwards) systems, over L, against L ν √(1−ẽ²)/σ, at ν = 0.05 and 0.10, N = 20000, L_x = L_y = 1,
U = 100, for several ẽ.  By (1.1) with l = L²/(2Nσ) and ν = πNσ²/4L², L0/L = (π/8) / (L ν √(1−ẽ²)/σ):
the measured scale should fall on a line through the origin against 1/x (a ν-dependent slope in the
thesis).

Usage (each run is N = 20000 to c = 200, i.e. 4·10^6 collisions, ~20–60 s here; 12 runs):
    /usr/bin/python3 scripts/experiments/spectra_fig328_sweep.py --granule build/release/granule --out /tmp/fig328
Options: --restitutions, --area-fractions, --until (c), --steady-from (c: frames averaged from here on),
--max-mode.  Writes <out>/fig328.csv (one row per run) and <out>/fig328.png.

The steady state depends on the initial temperature (thesis §3.1.1, Ch. 4): each run starts at the
temperature of (3.1) for its parameters, as the thesis recommends for the stripwise state.
"""
import argparse
import csv
import math
import subprocess
from pathlib import Path

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
parser.add_argument("--granule", default="build/release/granule")
parser.add_argument("--out", default="fig328")
parser.add_argument("--particles", type=int, default=20000)
parser.add_argument("--shear-velocity", type=float, default=100.0)
parser.add_argument("--restitutions", type=float, nargs="*", default=[0.5, 0.6, 0.7, 0.8, 0.9, 0.95])
parser.add_argument("--area-fractions", type=float, nargs="*", default=[0.05, 0.10])
parser.add_argument("--until", type=float, default=200.0, help="run length in collisions per particle")
parser.add_argument("--steady-from", type=float, default=100.0, help="average frames with c ≥ this")
parser.add_argument("--max-mode", type=int, default=64)
args = parser.parse_args()
out = Path(args.out)
out.mkdir(parents=True, exist_ok=True)

rows = []
for nu in args.area_fractions:
    for e in args.restitutions:
        name = out / f"nu{nu:g}_e{e:g}"
        sigma = math.sqrt(4 * nu / (math.pi * args.particles))
        gamma = args.shear_velocity
        t_steady = 0.080 * gamma ** 2 * sigma ** 2 / nu ** 2 * (1 / (1 - e * e) - 0.54)  # (3.1)
        if not (name / "snapshots.h5").exists():
            subprocess.run([args.granule, "run", "--out", str(name), "--set", f"system.particles={args.particles}",
                            "--set", f"system.area_fraction={nu}", "--set", f"system.restitution={e}",
                            "--set", "boundary.kind=lees-edwards", "--set", f"boundary.shear_velocity={gamma}",
                            "--set", f"initial.temperature={t_steady}", "--set", "initial.equilibrate=2",
                            "--set", f"run.until_collisions_per_particle={args.until}",
                            "--set", "output.snapshot_every_collisions_per_particle=10"], check=True)
        spectra = name / "spectra.h5"
        subprocess.run([args.granule, "analyze", "spectra", str(name / "snapshots.h5"), "--out", str(spectra),
                        "--max-mode", str(args.max_mode), "--subtract-shear", "--exclude-ky-axis"], check=True)
        with h5py.File(spectra) as f:
            steady = f["collisions_per_particle"][:] >= args.steady_from
            # Only frames whose dominant mode stands above the noise of uncorrelated positions
            # (docs/spectra.md, significance) say anything about a cluster length.
            significant = steady & (f["dominant/R/significant"][:] == 1)
            k = f["dominant/R/k"][:][significant]
            angle = f["dominant/R/angle_deg"][:][significant]
            length = 2 * math.pi / np.mean(k) if len(k) else math.nan  # 1/mean dominant |k| (§3.2.1)
            L = f.attrs["box"][0]
            x = L * nu * math.sqrt(1 - e * e) / f.attrs["diameter"]
            rows.append({"area_fraction": nu, "restitution": e, "x": x, "dominant_length_over_L": length / L,
                         "L0_over_L": f.attrs["L0"] / L, "mean_angle_deg": float(np.mean(angle)) if len(angle) else math.nan,
                         "frames": int(steady.sum()), "significant_frames": int(significant.sum())})
        print(rows[-1])

with open(out / "fig328.csv", "w", newline="") as handle:
    writer = csv.DictWriter(handle, fieldnames=list(rows[0]))
    writer.writeheader()
    writer.writerows(rows)

fig, ax = plt.subplots(figsize=(5.5, 4))
for nu, marker in zip(args.area_fractions, "^sod"):
    mine = [r for r in rows if r["area_fraction"] == nu]
    ax.plot([r["x"] for r in mine], [r["dominant_length_over_L"] for r in mine], marker, label=f"ν = {nu:g}")
x = np.linspace(min(r["x"] for r in rows), max(r["x"] for r in rows), 100)
ax.plot(x, math.pi / 8 / x, "k--", lw=0.8, label="L0/L = (π/8)/x  (eq 1.1)")
ax.set_xlabel("L ν √(1−e²) / σ")
ax.set_ylabel("dominant length / L")
ax.set_title(f"Fig 3.28 recipe: N = {args.particles}, U = {args.shear_velocity:g}", fontsize=10)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(out / "fig328.png", dpi=110)
print("wrote", out / "fig328.csv", out / "fig328.png")
