"""3D and polydisperse runs from the command line: the snapshot file has the documented layout
(positions (S, N, d), per-particle diameters and masses, the packing fraction); no two particles
overlap in any frame (brute force with σ_ij = (σ_i + σ_j)/2, minimum images); elastic runs keep
the energy and every run the momentum; config.toml repeats the run bit for bit; a run stopped
and resumed writes the same files; 2D-only keys are refused in 3D (exit 2, naming the key)."""
import subprocess

import h5py
import numpy as np

from harness import WORK, check, finish, granule

SPHERES = ["--set", "system.dimension=3", "--set", "system.box=[1.0, 1.2, 0.8]", "--set", "system.particles=1500",
           "--set", "system.packing_fraction=0.15", "--set", "output.every_collisions_per_particle=1",
           "--set", "output.snapshot_every_collisions_per_particle=4", "--set", "run.until_collisions_per_particle=16"]
MIXTURE = ["--set", 'system.diameters={distribution="bidisperse", ratio=1.6, fraction=0.4}']
SHEAR = ["--set", "boundary.kind=lees-edwards", "--set", "boundary.shear_velocity=5", "--set", "system.restitution=0.9"]


def read(run):
    with h5py.File(run / "snapshots.h5") as f:
        return {"dimension": int(f.attrs["dimension"]), "box": np.array(f.attrs["box"]), "phi": float(f.attrs["packing_fraction"]),
                "positions": f["positions"][:], "velocities": f["velocities"][:], "offset": f["shear_offset"][:],
                "diameters": f["diameters"][:] if "diameters" in f else None, "masses": f["masses"][:] if "masses" in f else None,
                "diameter": float(f.attrs["diameter"])}


def min_gap_ratio(r, box, sigma, offset):
    """Smallest |r_ij| / σ_ij over all pairs and the images across y (Lees–Edwards offset), x and z."""
    d = r[None, :, :] - r[:, None, :]
    worst = np.inf
    for iy in (-1, 0, 1):
        shifted = d.copy()
        shifted[..., 1] += iy * box[1]
        shifted[..., 0] += iy * offset
        shifted[..., 0] -= box[0] * np.round(shifted[..., 0] / box[0])
        if len(box) == 3:
            shifted[..., 2] -= box[2] * np.round(shifted[..., 2] / box[2])
        dist = np.sqrt((shifted ** 2).sum(-1)) / sigma
        np.fill_diagonal(dist, np.inf)
        worst = min(worst, dist.min())
    return worst


def check_run(name, extra, elastic):
    run = WORK / name
    result = granule("run", "--out", str(run), *SPHERES, *extra, *(["--set", "system.restitution=1"] if elastic else []))
    check(result.returncode == 0, f"{name}: run exits 0 ({result.stderr.strip()[-200:]})")
    s = read(run)
    n = 1500
    check(s["dimension"] == 3 and s["positions"].shape[1:] == (n, 3) and s["velocities"].shape[1:] == (n, 3),
          f"{name}: positions and velocities are (S, N, 3): {s['positions'].shape}")
    check(np.allclose(s["box"], [1.0, 1.2, 0.8]), f"{name}: box attribute {s['box']}")
    sizes = s["diameters"] if s["diameters"] is not None else np.full(n, s["diameter"])
    masses = s["masses"] if s["masses"] is not None else np.ones(n)
    phi = np.pi / 6 * np.sum(sizes ** 3) / (1.0 * 1.2 * 0.8)
    check(abs(phi / 0.15 - 1) < 1e-12 and abs(s["phi"] / 0.15 - 1) < 1e-12, f"{name}: packing fraction {phi}, attribute {s['phi']}")
    if "bidisperse" in " ".join(extra):
        large = np.isclose(sizes, sizes.max())
        check(large.sum() == 600, f"{name}: 40 % large spheres ({large.sum()})")
        check(np.allclose(masses[large] / masses[~large][0], 1.6 ** 3), f"{name}: masses ∝ σ³")
        check(s["diameter"] == sizes.max(), f"{name}: the diameter attribute is the largest diameter")
    sigma = 0.5 * (sizes[:, None] + sizes[None, :])
    box = s["box"]
    gaps = [min_gap_ratio(s["positions"][k], box, sigma, s["offset"][k]) for k in range(len(s["positions"]))]
    check(min(gaps) > 1 - 1e-9, f"{name}: no overlaps in {len(gaps)} frames (min |r|/σ_ij = {min(gaps):.12f})")
    p = (masses[None, :, None] * s["velocities"]).sum(axis=1)
    energy = 0.5 * (masses[None, :, None] * s["velocities"] ** 2).sum(axis=(1, 2))
    if "lees-edwards" not in " ".join(extra):
        check(np.abs(p).max() < 1e-9 * np.sqrt(energy[0] * masses.sum()), f"{name}: momentum conserved ({np.abs(p).max():.2e})")
    if elastic:
        check(np.abs(energy / energy[0] - 1).max() < 1e-12, f"{name}: energy conserved ({np.abs(energy / energy[0] - 1).max():.2e})")
    # config.toml repeats the run exactly.
    again = WORK / (name + "_again")
    result = granule("run", str(run / "config.toml"), "--out", str(again))
    check(result.returncode == 0, f"{name}: config.toml runs")
    check(np.array_equal(read(again)["positions"], s["positions"]), f"{name}: config.toml repeats the run bit for bit")
    return run, s


def check_resume(name, extra):
    """Stopped at c = 8 and resumed to c = 16: the same snapshots as a run straight to 16."""
    straight, s = check_run(name, extra, elastic=False)
    run = WORK / (name + "_resumed")
    result = granule("run", "--out", str(run), *SPHERES, *extra, "--set", "run.until_collisions_per_particle=8")
    check(result.returncode == 0, f"{name}: first part runs")
    result = granule("run", "--resume", str(run), "--set", "run.until_collisions_per_particle=16")
    check(result.returncode == 0, f"{name}: resume runs ({result.stderr.strip()[-200:]})")
    r = read(run)
    check(r["positions"].shape == s["positions"].shape and np.array_equal(r["positions"], s["positions"])
          and np.array_equal(r["velocities"], s["velocities"]), f"{name}: resumed run equals the straight run bit for bit")
    rows = [(WORK / d / "timeseries.csv").read_text() for d in (name, name + "_resumed")]
    check(rows[0] == rows[1], f"{name}: resumed time series identical")


check_run("spheres_elastic", [], elastic=True)
check_run("mixture3d_elastic", MIXTURE, elastic=True)
check_resume("spheres_sheared", SHEAR)
check_resume("mixture3d_sheared", [*MIXTURE, *SHEAR])

for key, value, needle in [("engine.cells", "[4, 4]", "engine.cells"),
                           ("system.area_fraction", "0.1", "system.area_fraction")]:
    result = granule("run", "--out", str(WORK / "refused"), "--force", *SPHERES, "--set", f"{key}={value}")
    check(result.returncode == 2 and needle in result.stderr, f"3D run refuses {key} (exit {result.returncode}: {result.stderr.strip()[:160]})")
    check(not (WORK / "refused" / "snapshots.h5").exists(), f"nothing written when {key} is refused")

result = granule("analyze", "f1", str(WORK / "spheres_elastic" / "snapshots.h5"), "--density-window", "1500+-1000",
                 "--temperature-window", "1+-1", "--out", str(WORK / "f1.h5"))
check(result.returncode == 2 and "2D runs only" in result.stderr and not (WORK / "f1.h5").exists(),
      f"analyze f1 refuses a 3D run (exit {result.returncode}: {result.stderr.strip()[:160]})")

finish()
