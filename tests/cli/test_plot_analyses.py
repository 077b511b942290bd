"""End-to-end: `granule plot collisions` and `granule plot spectra` draw PNGs of the documented size
(read back with matplotlib's imread) from real files of `granule run` and `granule analyze spectra`,
and the numbers they draw (the --data sidecar) are checked against independent results: the impact
parameters of an elastic gas are uniform (isotropy, a chi-square test) while a file with grazing
collisions is drawn peaked at b = σ; the isotropic free paths of an elastic gas follow α/2π and the
sheared ones do not; the curves of (3.24) drawn by Python equal the C++ fit at the bin edges and the
exact values erf(√(l/l̄)) and ½ at α = π; the spectra panels show the frame asked for, the level
N/4π² per mode of uncorrelated positions and the file's dominant mode.  Bad input exits with code 2
naming the option, writing neither the PNG nor the sidecar."""
import json
import math

import h5py
import matplotlib.image
import numpy as np

from harness import WORK, check, finish, granule


def picture(path):
    """(height, width, RGB in [0, 1]) of a PNG, via matplotlib's independent PNG reader."""
    return matplotlib.image.imread(str(path))[:, :, :3]


def plot(kind, source, out, *options):
    """Runs `granule plot KIND`, returns (PNG shape, sidecar) or (None, None) on failure."""
    r = granule("plot", kind, source, "--out", out, "--data", out.with_suffix(".json"), *options)
    check(r.returncode == 0, f"plot {kind} {source} failed: {r.stderr}")
    if r.returncode != 0:
        return None, None
    return picture(out).shape, json.loads(out.with_suffix(".json").read_text())


def run(name, *settings):
    r = granule("run", "--out", WORK / name, "--set", "system.particles=1500", "--set", "collisions.free_paths=true",
                *(a for s in settings for a in ("--set", s)))
    check(r.returncode == 0, f"run {name} failed: {r.stderr}")
    return WORK / name


# 1. An elastic periodic gas: 1500 disks (ν = 0.05, box 1 × 1, mean density 1500), 8 collisions each.
elastic = run("elastic", "system.restitution=1.0", "run.until_collisions_per_particle=8",
              "collisions.density_windows=[[0,1500],[1500,1e9]]")
shape, data = plot("collisions", elastic, WORK / "elastic.png")
check(shape == (900, 1500, 3), f"collisions.png: two rows of three 5 × 4.5 in panels, got {shape}")
with h5py.File(elastic / "collisions.h5") as f:
    impacts, paths = data["impact_parameters"], data["free_paths"]
    check(set(impacts["curves"]) == {"total", "density_window_0", "density_window_1", "last_window"},
          f"β curves drawn: {sorted(impacts['curves'])}")
    # β drawn = the file's counts normalised to unit integral over [0, 1] (3.20).
    counts = f["impact_parameters/total/counts"][:]
    bins = len(counts)
    beta = np.array(impacts["curves"]["total"]["beta"])
    check(np.allclose(beta, counts / counts.sum() * bins, rtol=1e-12), "β(b/σ) is not the normalised histogram")
    last = f["impact_parameters/windows/counts"][-1]
    check(np.allclose(impacts["curves"]["last_window"]["beta"], last / last.sum() * bins, rtol=1e-12), "last window β")
    # Elastic hard disks in equilibrium collide with uniform b/σ: chi-square with bins − 1 degrees of
    # freedom, allowed 5 standard deviations above its mean.
    expected = counts.sum() / bins
    chi2 = ((counts - expected) ** 2 / expected).sum()
    check(chi2 < bins - 1 + 5 * math.sqrt(2 * (bins - 1)), f"elastic β is not flat: χ² = {chi2:.1f} for {bins - 1} dof")
    excess = np.array(impacts["curves"]["total"]["cumulative_minus_uniform"])
    check(excess[0] == 0 and abs(excess[-1]) < 1e-12, "B(b) − b/σ must vanish at b = 0 and b = σ")
    check(abs(np.abs(excess).max() - f["impact_parameters/total"].attrs["ks_uniform"]) < 1e-12, "B − b/σ max = ks_uniform")

    # Free paths: the Python (3.24) curves against the C++ fit at the angle edges, and exact values.
    g = f["free_paths/total"]
    alpha = np.array(paths["angular"]["model_alpha"])
    model = np.array(paths["angular"]["model"])
    edges = f["free_paths/angle_edges"][1:]
    check(np.allclose(np.interp(edges, alpha, model), g["angular_fit"][:], atol=2e-3),
          "drawn angular factor of (3.24) differs from the file's fit")
    radial = {round(r["alpha"] / math.pi, 6): r for r in paths["radial"]}
    check(set(radial) == {0.5, 1.0, 2.0}, f"fixed angles of panel (E): {sorted(radial)}")
    lbar = g.attrs["lbar"]
    exact = [math.erf(math.sqrt(l / lbar)) for l in radial[2.0]["model_l"]]
    check(np.allclose(radial[2.0]["model"], exact, atol=1e-12), "L(l, 2π) curve is not erf(√(l/l̄))")
    check(np.allclose(radial[1.0]["model"], 0.5 * np.array(exact), atol=1e-9), "(3.24) at α = π is not ½ erf(√(l/l̄))")
    check(np.allclose(radial[2.0]["measured"], g["length_cumulative"][:], atol=1e-12), "L(l, 2π) points")
    # Isotropy: the measured angular part is α/2π within the Kolmogorov bound (1.95/√n, 0.1 %).
    angular = np.array(paths["angular"]["measured"])
    bound = 1.95 / math.sqrt(g.attrs["paths"])
    check(np.abs(angular - edges / (2 * math.pi)).max() < bound, "elastic free paths are not isotropic")
    # 𝒫(l) drawn is a probability density: ∫ 𝒫 dl + overflow fraction = 1.
    width = f["free_paths/length_edges"][1] - f["free_paths/length_edges"][0]
    mass = np.sum(paths["magnitude"]["measured"]) * width + g["overflow"][:].sum() / g.attrs["paths"]
    check(abs(mass - 1) < 1e-9, f"𝒫(l) does not integrate to 1: {mass}")

# 2. A sheared inelastic run (Lees–Edwards, U = 20): free paths along the flow, and snapshots for spectra.
sheared = run("sheared", "system.restitution=0.7", "system.box=[1.0, 1.5]", "boundary.kind=lees-edwards",
              "boundary.shear_velocity=20", "run.until_collisions_per_particle=6",
              "output.snapshot_every_collisions_per_particle=2", "collisions.density_windows=[[0,1000],[1000,1e9]]",
              "collisions.speed_windows=[[0,1],[1,1e9]]")
r = granule("plot", "collisions", sheared)
check(r.returncode == 0 and picture(sheared / "collisions.png").shape == (900, 1500, 3), f"default output: {r.stderr}")
for window in ("density_window_1", "speed_window_1"):
    shape, data = plot("collisions", sheared / "collisions.h5", WORK / f"sheared_{window}.png", "--window", window)
    with h5py.File(sheared / "collisions.h5") as f:
        g = f["free_paths/" + window]
        check(data["free_paths"]["window"] == window and data["free_paths"]["alpha0"] == g.attrs["alpha0"],
              f"--window {window}: not the group drawn")
        check(np.allclose(data["free_paths"]["angular"]["measured"], g["angular_cumulative"][:]), f"{window} points")
        deviation = np.abs(np.array(data["free_paths"]["angular"]["measured"])
                           - f["free_paths/angle_edges"][1:] / (2 * math.pi)).max()
        # Shear aligns the paths with the flow (thesis §3.2.3): far beyond the isotropic bound of section 1.
        check(deviation > 5 * 1.95 / math.sqrt(g.attrs["paths"]),
              f"sheared free paths look isotropic ({window}: max |L − α/2π| = {deviation:.3f})")

# 3. A file of the documented schema made here, impact parameters only, with grazing collisions
# (β ∝ 1/√(1 − (b/σ)²), as a clustered free-cooling gas, thesis Fig 2.16B): one row of panels, peaked.
bins = 50
edges = np.linspace(0, 1, bins + 1)
cdf = 1 - np.sqrt(1 - edges ** 2)  # a distribution with density b/√(1 − b²), growing to b = σ
grazing = np.round(2e5 * np.diff(cdf))
beta = grazing / grazing.sum() * bins
excess = np.cumsum(grazing) / grazing.sum() - edges[1:]
with h5py.File(WORK / "grazing.h5", "w") as f:
    f.attrs.update(format="granule-collisions", format_version=1, particles=40000, restitution=0.6, boundary="periodic",
                   diameter=0.001, shear_velocity=0.0, length_x=1.0, length_y=1.0, from_c=90.0, to_c=100.0, from_t=1.0,
                   to_t=2.0, density_cells_nx=40, density_cells_ny=40)
    g = f.create_group("impact_parameters")
    g.attrs["window_collisions"] = 40000
    g["bin_edges"] = edges
    f["impact_parameters/total/counts"] = grazing
    f["impact_parameters/total/density"] = beta
    f["impact_parameters/total/cumulative_minus_uniform"] = excess
    f["impact_parameters/total"].attrs.update(samples=grazing.sum(), ks_uniform=np.abs(excess).max())
    f["impact_parameters/windows/t_start"] = np.array([1.0, 1.5])
    f["impact_parameters/windows/t_end"] = np.array([1.5, 2.0])
    f["impact_parameters/windows/collisions"] = np.array([1e5, 1e5])
    f["impact_parameters/windows/counts"] = np.array([grazing / 2, grazing / 2])
shape, data = plot("collisions", WORK / "grazing.h5", WORK / "grazing.png")
check(shape == (450, 1500, 3), f"impact parameters only: one row of panels, got {shape}")
if data:
    drawn = np.array(data["impact_parameters"]["curves"]["total"]["beta"])
    check(np.argmax(drawn) == bins - 1 and drawn[-1] > 5 * drawn[0], "grazing collisions are not drawn peaked at b = σ")
    check("free_paths" not in data, "no free-path panels without free paths")

# 4. Spectra of the sheared run's snapshots (4 frames), M = 12.
spectra = sheared / "spectra.h5"
r = granule("analyze", "spectra", sheared / "snapshots.h5", "--out", spectra, "--max-mode", 12, "--subtract-shear")
check(r.returncode == 0, f"analyze spectra failed: {r.stderr}")
r = granule("plot", "spectra", sheared, "--dpi", 50)
check(r.returncode == 0 and picture(sheared / "spectra.png").shape == (450, 750, 3), f"spectra.png at 50 dpi: {r.stderr}")
grey = {}
with h5py.File(spectra) as f:
    n = f.attrs["particles"]
    for frame in (1, -1):
        out = WORK / f"spectra_{frame}.png"
        shape, data = plot("spectra", spectra, out, "--frame", frame)
        check(shape == (900, 1500, 3), f"spectra.png: two rows of three 5 × 4.5 in panels, got {shape}")
        grey[frame] = picture(out).mean(axis=2)
        k = frame % len(f["time"])
        check(data["frame"] == k and data["t"] == f["time"][k] and data["frame_index"] == f["frame_index"][k],
              f"--frame {frame}: drew frame {data['frame']}")
        check(np.array_equal(data["annulus"]["R"], f["annulus_R"][k]), "annulus R(k) of the frame")
        check(np.allclose(data["annulus"]["uncorrelated_R"], f["annulus_modes"][k] * n / (4 * math.pi ** 2), rtol=1e-12),
              "uncorrelated level is not N/4π² per mode")
        for name in ("R", "Px", "Py"):
            check(np.allclose(data["maps"][name]["dominant_k"], [f[f"dominant/{name}/kx"][k], f[f"dominant/{name}/ky"][k]]),
                  f"dominant mode of {name} marked elsewhere")
        check(np.allclose(data["dominant"]["R"], f["dominant/R/length"][:]), "dominant length series")
    check(np.abs(grey[1] - grey[-1]).mean() > 1e-3, "frames 1 and -1 drew the same picture")

# Bad input: exit code 2, a message naming the option, and neither the PNG nor the sidecar.
bad_png, bad_json = WORK / "bad.png", WORK / "bad.json"
bad = {
    "window": (["collisions", sheared, "--window", "density_window_7"], "--window"),
    "window_without_paths": (["collisions", WORK / "grazing.h5", "--window", "speed_window_0"], "--window"),
    "dpi": (["collisions", elastic, "--dpi", 5], "--dpi"),
    "not_collisions": (["collisions", spectra], "granule-collisions"),
    "missing": (["collisions", WORK / "nowhere"], "does not exist"),
    "no_spectra": (["spectra", elastic], "spectra.h5"),
    "frame": (["spectra", spectra, "--frame", 4], "--frame"),
    "not_spectra": (["spectra", elastic / "collisions.h5"], "granule-spectra"),
}
for name, (args, expected) in bad.items():
    r = granule("plot", *args, "--out", bad_png, "--data", bad_json)
    check(r.returncode == 2, f"{name}: exit code {r.returncode} ({r.stderr.strip()})")
    check(expected in r.stderr, f"{name}: message lacks '{expected}': {r.stderr.strip()}")
    check(not bad_png.exists() and not bad_json.exists(), f"{name}: output written")
    check(not any(WORK.glob("bad.*.partial")), f"{name}: partial output left")

finish()
