"""`granule plot fields` on 2D runs: `--group instant` works with its own defaults (it failed: the
default list asked /instant for the collisional pressure, which exists only averaged), and the
time-averaged, smoothed maps do what docs/plots.md says, checked against independent results:
* averaging in the frame moving with the shear: stripes 1 + ½ cos(k·(x − u(y) t, y)) carried by the
  mean flow u(y) = γ (y − L_y/2), sampled at three times, average to the last frame's stripes (to the
  interpolation error) when each frame is advected by u(y) Δt; a plain average smears them;
* the Gaussian kernel of σ cells lowers the variance of white noise by 1/(4π σ²) (2D).
"""
import sys
import types
from pathlib import Path

import h5py
import numpy as np

from harness import WORK, check, finish, granule

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "python" / "granule_plots"))
import fields  # noqa: E402

# 1. A real Lees–Edwards run: the instantaneous maps with the defaults, and averaged smoothed maps.
run = WORK / "run"
r = granule("run", "--out", run, "--set", "system.particles=2000", "--set", "boundary.kind=lees-edwards", "--set",
            "boundary.shear_velocity=20", "--set", "run.until_collisions_per_particle=6", "--set",
            "output.snapshot_every_collisions_per_particle=1", "--set", "initial.equilibrate=1")
check(r.returncode == 0, f"run failed: {r.stderr}")
r = granule("plot", "fields", run, "--group", "instant", "--out", WORK / "instant.png")
check(r.returncode == 0 and (WORK / "instant.png").exists(), f"plot fields --group instant: {r.stderr}")
r = granule("plot", "fields", run, "--average-frames", 3, "--smooth", 1.5, "--out", WORK / "smooth.png")
check(r.returncode == 0 and (WORK / "smooth.png").exists(), f"plot fields --average-frames 3 --smooth 1.5: {r.stderr}")
r = granule("plot", "fields", run, "--average-frames", 99)
check(r.returncode != 0 and "--average-frames" in r.stderr, f"too many frames named: {r.stderr}")

# 2. Stripes carried by the shear, in a fields file written here.
n, gamma, times = 64, 10.0, [0.0, 0.01, 0.02]
x = (np.arange(n) + 0.5) / n
X, Y = np.meshgrid(x, x)
k = 2 * np.pi * np.array([3.0, 2.0])


def stripes(t):
    return 1.0 + 0.5 * np.cos(k[0] * (X - gamma * (Y - 0.5) * t) + k[1] * Y)


path = WORK / "stripes.h5"
with h5py.File(path, "w") as f:
    f.attrs.update(nx=n, ny=n, length_x=1.0, length_y=1.0, particles=1, restitution=0.8, boundary="lees-edwards",
                   shear_velocity=gamma, subtract_shear_profile=0)
    f["frames/t"] = np.array(times)
    f["frames/shear_velocity"] = np.full(3, gamma)
    f["frames/shear_offset"] = gamma * np.array(times)
    f["instant/density"] = np.stack([stripes(t) for t in times])
options = types.SimpleNamespace(average_frames=3, smooth=0.0)
with h5py.File(path) as f:
    averaged = fields.averaged_map(f, f["instant"], "density", 2, options)
    plain = f["instant/density"][:].mean(axis=0)
sheared_error = np.abs(averaged - stripes(times[-1])).max()
plain_error = np.abs(plain - stripes(times[-1])).max()
print(f"stripes: shear-frame average off by {sheared_error:.3f}, plain average by {plain_error:.3f} (amplitude 0.5)")
check(sheared_error < 0.03, f"shear-frame average keeps the stripes: {sheared_error:.3f}")
check(plain_error > 0.2, f"the plain average smears them (else the test cannot tell): {plain_error:.3f}")

# 3. The smoothing kernel on white noise (periodic file): variance × 1/(4π σ²).
noise = np.random.default_rng(7).normal(size=(1, 128, 128))
path = WORK / "noise.h5"
with h5py.File(path, "w") as f:
    f.attrs.update(nx=128, ny=128, length_x=1.0, length_y=1.0, particles=1, restitution=0.8, boundary="periodic")
    f["frames/t"] = np.array([0.0])
    f["instant/density"] = noise
sigma = 2.0
with h5py.File(path) as f:
    smoothed = fields.averaged_map(f, f["instant"], "density", 0, types.SimpleNamespace(average_frames=1, smooth=sigma))
ratio = smoothed.var() / noise.var() * 4 * np.pi * sigma ** 2
print(f"white noise: variance after smoothing × 4πσ² = {ratio:.3f} (1 expected)")
check(abs(ratio - 1) < 0.1, f"Gaussian kernel of σ = {sigma} cells: variance ratio × 4πσ² = {ratio:.3f}")
finish()
