#!/usr/bin/python3
"""Thesis §2.2 experiment (Figs 2.8–2.10): mass and momentum spectra of a freely cooling gas.

Usage (System I of the thesis: N = 40000, ν = 0.05, ẽ = 0.98; ~2 min run, ~10 s analysis):
    granule run --out sys1 --set system.particles=40000 --set system.area_fraction=0.05 \
        --set system.restitution=0.98 --set initial.equilibrate=5 \
        --set run.until_collisions_per_particle=600 --set output.snapshot_every_collisions_per_particle=25
    granule analyze spectra sys1/snapshots.h5 --max-mode 32 --out sys1_spectra.h5
    /usr/bin/python3 scripts/experiments/spectra_free_cooling.py sys1_spectra.h5 --out sys1 [--at 50 150 400 550]

Writes <out>_annulus.png (R(k) and P(k) at the chosen c, as Figs 2.8–2.9), <out>_modes.png (the power
per mode in the rings k = 2π/L and 4π/L over c, in units of the mean power per mode of that frame) and
prints the table behind the second figure: does the momentum mode at k = 2π/L rise before the mass
mode at twice the wavenumber?
"""
import argparse
import math

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
parser.add_argument("spectra", help="output of granule analyze spectra")
parser.add_argument("--out", default="spectra", help="prefix of the figures")
parser.add_argument("--at", type=float, nargs="*", default=[50, 150, 400, 550], help="c of the annulus plots")
args = parser.parse_args()

with h5py.File(args.spectra) as f:
    c = f["collisions_per_particle"][:]
    k = f["annulus_k"][:]
    modes = f["annulus_modes"][:]
    ring = {name: f["annulus_" + name][:] for name in ("R", "P")}
    # Mean power per mode over all computed modes but k = 0: the frame's equipartition level.
    level = {}
    for name in ("R", "P"):
        maps = f[name][:]
        side = maps.shape[1]
        maps[:, side // 2, side // 2] = np.nan
        level[name] = np.nanmean(maps.reshape(len(c), -1), axis=1)
    dominant = {name: (f[f"dominant/{name}/k"][:], f[f"dominant/{name}/angle_deg"][:]) for name in ("R", "P")}
    n, e, L0 = f.attrs["particles"], f.attrs["restitution"], f.attrs["L0"]
    box = f.attrs["box"]

# Figs 2.8–2.9: the annulus sums at the chosen times.
chosen = [int(np.argmin(np.abs(c - target))) for target in args.at]
fig, axes = plt.subplots(2, len(chosen), figsize=(3.2 * len(chosen), 5.5), squeeze=False)
for column, i in enumerate(chosen):
    for row, name in enumerate(("R", "P")):
        ax = axes[row][column]
        ax.plot(k, ring[name][i], "k.-", lw=0.8, ms=3)
        ax.plot(k, modes[i] * level[name][i], color="0.6", lw=0.8, label="equipartition")
        ax.set_title(f"{name}(k), c = {c[i]:.0f}", fontsize=9)
        ax.set_xlabel("k")
axes[0][0].legend(fontsize=7)
fig.suptitle(f"N = {n}, e = {e}: annulus sums (thesis Figs 2.8-2.9)", fontsize=10)
fig.tight_layout()
fig.savefig(f"{args.out}_annulus.png", dpi=110)

# The ring-1 momentum and ring-2 mass power per mode, relative to the frame's mean per mode.
lowest = 2 * math.pi / max(box)
b1, b2 = int(np.argmin(np.abs(k - lowest))), int(np.argmin(np.abs(k - 2 * lowest)))
p1 = ring["P"][:, b1] / modes[:, b1] / level["P"]
r1 = ring["R"][:, b1] / modes[:, b1] / level["R"]
r2 = ring["R"][:, b2] / modes[:, b2] / level["R"]
fig, ax = plt.subplots(figsize=(6, 4))
ax.semilogy(c, p1, "o-", label=f"P, k = {k[b1]:.3g} (2π/L)")
ax.semilogy(c, r1, "s-", label=f"R, k = {k[b1]:.3g}")
ax.semilogy(c, r2, "^-", label=f"R, k = {k[b2]:.3g} (4π/L)")
ax.axhline(1, color="0.6", lw=0.8)
ax.set_xlabel("c (collisions per particle)")
ax.set_ylabel("power per mode / mean power per mode")
ax.set_title(f"N = {n}, e = {e}: lowest modes (thesis §2.2)", fontsize=10)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(f"{args.out}_modes.png", dpi=110)

print(f"L0 = {L0:.4g}; ring k = {k[b1]:.4g} and {k[b2]:.4g}")
print("    c   P(2π/L)  R(2π/L)  R(4π/L)   dominant P: 2π/k, angle   dominant R: 2π/k, angle")
for i in range(len(c)):
    print(f"{c[i]:6.0f} {p1[i]:8.2f} {r1[i]:8.2f} {r2[i]:8.2f}   {2 * math.pi / dominant['P'][0][i]:10.4f} "
          f"{dominant['P'][1][i]:6.1f}   {2 * math.pi / dominant['R'][0][i]:10.4f} {dominant['R'][1][i]:6.1f}")
for name, series in (("P(2π/L)", p1), ("R(4π/L)", r2)):
    above = np.nonzero(series > 10)[0]
    print(f"first c with {name} > 10× the mean per mode: {c[above[0]] if len(above) else 'never'}")
