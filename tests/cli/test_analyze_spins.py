"""End-to-end: `granule analyze spins` on small sheared runs of rough disks and spheres, read back with
h5py; each frame's C_contact and pair counts are recomputed independently with numpy over every pair
and every Lees–Edwards image (thesis §1.4.2) from the snapshot positions and spins; `granule plot
spins` draws the file; a smooth run, bad options and a damaged spins.h5 exit 2 and write nothing."""
import json

import h5py
import numpy as np

from harness import WORK, check, finish, granule

ROUGH = ["--set", "system.tangential_restitution=-0.8", "--set", "system.restitution=0.6", "--set",
         "boundary.kind=lees-edwards", "--set", "boundary.shear_velocity=20", "--set", "run.until_collisions_per_particle=6", "--set", "output.snapshot_every_collisions_per_particle=2"]


def simulate(name, *settings):
    result = granule("run", "--out", str(WORK / name), *settings)
    check(result.returncode == 0, f"run {name} failed: {result.stderr}")
    return WORK / name


def brute_force(positions, spins, box, offset, sigma, shell=0.1, walls_y=False):
    """C_contact and the number of pairs within 3σ by every pair and every image iy ∈ {-1, 0, 1}."""
    spins = spins.reshape(len(spins), -1)
    fluctuation = spins - spins.mean(axis=0)
    variance = (fluctuation ** 2).sum(axis=1).mean()
    d = positions[None, :, :] - positions[:, None, :]
    best = np.full(d.shape[:2], np.inf)
    for iy in ([0] if walls_y else [-1, 0, 1]):
        shifted = d.copy()
        shifted[:, :, 1] += iy * box[1]
        shifted[:, :, 0] += iy * offset
        for axis in [0] + ([2] if d.shape[2] == 3 else []):
            shifted[:, :, axis] -= box[axis] * np.round(shifted[:, :, axis] / box[axis])
        best = np.minimum(best, np.sqrt((shifted ** 2).sum(axis=2)))
    upper = np.triu(np.ones_like(best, dtype=bool), 1)
    contact = upper & (best < (1 + shell) * sigma)
    products = fluctuation @ fluctuation.T / variance
    return products[contact].mean(), contact.sum(), (upper & (best < 3 * sigma)).sum()


# 1. Rough disks under Lees–Edwards shear: every frame recomputed.
disks = simulate("disks", "--set", "system.particles=800", "--set", "system.area_fraction=0.05", *ROUGH)
result = granule("analyze", "spins", str(disks), "--frames", "1:")
check(result.returncode == 0, f"analyze spins failed: {result.stderr}")
check("C_contact =" in result.stdout and "pairs in contact" in result.stdout and "standard error" in result.stdout,
      f"summary: {result.stdout}")
with h5py.File(disks / "snapshots.h5") as snap, h5py.File(disks / "spins.h5") as f:
    check(f.attrs["format"] in (b"granule-spins", "granule-spins"), "format attribute")
    sigma, box = float(snap.attrs["diameter"]), (1.0, 1.0)
    frames = f["frame_index"][:]
    check(list(frames) == list(range(1, snap["time"].shape[0])), f"frames 1: selected, got {frames}")
    for row, index in enumerate(frames):
        c, contact, within = brute_force(snap["positions"][index], snap["spins"][index], box, snap["shear_offset"][index],
                                         sigma)
        check(f["contact_pairs"][row] == contact, f"frame {index}: {f['contact_pairs'][row]} contact pairs, numpy {contact}")
        check(f["pairs"][row].sum() == within, f"frame {index}: {f['pairs'][row].sum()} pairs within 3σ, numpy {within}")
        check(abs(f["C_contact"][row] - c) < 1e-9, f"frame {index}: C_contact {f['C_contact'][row]}, numpy {c}")
        check(abs(f["mean_spin"][row][2] - snap["spins"][index].mean()) < 1e-12, "mean spin recorded")
    values = f["C_contact"][:]
    check(abs(f.attrs["C_contact"] - values.mean()) < 1e-12, "C_contact: the mean of the frames'")
    check(abs(f.attrs["C_contact_error"] - values.std(ddof=1) / np.sqrt(len(values))) < 1e-12, "error: their standard error")
    pairs = f["pairs"][:]
    check(np.array_equal(f["average/pairs"][:], pairs.sum(axis=0)), "average pairs: the frames' sum")
    check(np.all(f["pairs_flow"][:] + f["pairs_gradient"][:] == pairs), "2D: every pair lies along x or y")

# 2. The picture and its numbers.
picture = WORK / "spins.png"
result = granule("plot", "spins", str(disks), "--out", str(picture), "--data", str(WORK / "spins.json"))
check(result.returncode == 0 and picture.is_file(), f"plot spins failed: {result.stderr}")
drawn = json.loads((WORK / "spins.json").read_text())
check(len(drawn["correlation"]["C"]) == 20 and drawn["frames"] == len(frames), f"drawn: {list(drawn)}")

# 3. Rough spheres (ω a vector) under shear, and the options recorded.
spheres = simulate("spheres", "--set", "system.dimension=3", "--set", "system.particles=400", "--set",
                   "system.box=[1.0, 1.0, 1.0]", "--set", "system.packing_fraction=0.05",
                   *ROUGH)
check((spheres / "snapshots.h5").is_file(), "3D run wrote snapshots")
out = WORK / "spheres_spins.h5"
result = granule("analyze", "spins", str(spheres / "snapshots.h5"), "--out", str(out), "--bins", "8", "--max-distance", "2.5")
check(result.returncode == 0, f"analyze spins of spheres failed: {result.stderr}")
with h5py.File(spheres / "snapshots.h5") as snap, h5py.File(out) as f:
    check(f["C"].shape[1] == 8 and abs(f["r_edges"][-1] - 2.5) < 1e-12, "bins and distance recorded")
    index = f["frame_index"][-1]
    c, contact, _ = brute_force(snap["positions"][index], snap["spins"][index], (1.0, 1.0, 1.0), snap["shear_offset"][index],
                                float(snap.attrs["diameter"]))
    check(f["contact_pairs"][-1] == contact and (contact == 0 or abs(f["C_contact"][-1] - c) < 1e-9),
          f"3D: C_contact {f['C_contact'][-1]} of {f['contact_pairs'][-1]}, numpy {c} of {contact}")

# 4. Refusals: exit 2, a message that names what is wrong, nothing written.
smooth = simulate("smooth", "--set", "system.particles=300", "--set", "run.until_collisions_per_particle=1")
result = granule("analyze", "spins", str(smooth))
check(result.returncode == 2 and "smooth" in result.stderr and "tangential_restitution" in result.stderr,
      f"smooth run: {result.returncode} {result.stderr!r}")
check(not (smooth / "spins.h5").exists(), "a smooth run's refusal wrote spins.h5")
for options, words in ((["--max-distance", "1.05"], "--max-distance"), (["--contact-shell", "0"], "--contact-shell"),
                       (["--bins", "0"], "--bins"), (["--frames", "99"], "frame")):
    target = WORK / "refused.h5"
    result = granule("analyze", "spins", str(disks), "--out", str(target), *options)
    check(result.returncode == 2 and words in result.stderr, f"{options}: {result.returncode} {result.stderr!r}")
    check(not target.exists(), f"{options} wrote a file")
result = granule("analyze", "spins", str(WORK / "nowhere"))
check(result.returncode == 2 and "snapshots" in result.stderr, f"missing run: {result.stderr!r}")

# 5. A spins.h5 that lacks what its schema declares is refused by `granule plot` before the script runs.
damaged = WORK / "damaged" / "spins.h5"
damaged.parent.mkdir()
damaged.write_bytes((disks / "spins.h5").read_bytes())
with h5py.File(damaged, "r+") as f:
    del f["average/C_flow"]
result = granule("plot", "spins", str(damaged.parent), "--out", str(WORK / "damaged.png"))
check(result.returncode == 2 and "average/C_flow" in result.stderr, f"damaged file: {result.returncode} {result.stderr!r}")
check(not (WORK / "damaged.png").exists(), "a refused file was drawn")

finish()
