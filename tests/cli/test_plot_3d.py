"""End-to-end: the pictures and exports of a 3D run (thesis Appendix C, Figs C.1-C.3).

The isosurface code against analytic densities: a sphere's area and enclosed volume (second-order
accurate: within 1 % at 8 cells per radius), a slab's planes exactly; Gaussian smoothing across the
Lees-Edwards images leaves a linear shear profile linear and multiplies a sheared-periodic wave by
one factor everywhere.  Then `granule plot fields` and `granule plot config` on a synthetic 3D run
(files in the 3D layout written here with h5py) write PNGs of the requested size, options of the
other dimension are refused (exit 2, nothing written), and a 3D fields.h5 exports to a .vti that
VTK reads back exactly.  (Exports and `analyze fields` from 3D snapshot files need the 3D snapshot
reader and are tested with it.)"""
import math
import sys
import time
from pathlib import Path

import h5py
import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

from harness import WORK, check, finish, granule

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "python" / "granule_plots"))
from _isosurface import area_and_volume, isosurface, smooth  # noqa: E402


def cell_centres(n, box):
    axes = [(np.arange(k) + 0.5) * length / k for k, length in zip(n, box)]
    z, y, x = np.meshgrid(axes[2], axes[1], axes[0], indexing="ij")
    return x, y, z


# A sphere of radius R as the level set of a Gaussian blob, 8 cells per radius.
box = (1.0, 1.0, 1.0)
x, y, z = cell_centres((32, 32, 32), box)
radius, width = 0.25, 0.15
blob = np.exp(-((x - 0.5) ** 2 + (y - 0.45) ** 2 + (z - 0.52) ** 2) / (2 * width ** 2))
vertices, triangles, values = isosurface(blob, x, box, math.exp(-radius ** 2 / (2 * width ** 2)))
area, volume = area_and_volume(vertices, triangles)
area_error, volume_error = area / (4 * math.pi * radius ** 2) - 1, volume / (4 / 3 * math.pi * radius ** 3) - 1
print(f"sphere, 8 cells per radius: {len(triangles)} triangles, area error {area_error:+.2e}, volume error {volume_error:+.2e}")
check(abs(area_error) < 0.01 and abs(volume_error) < 0.01, f"sphere area error {area_error}, volume error {volume_error}")
check(np.max(np.abs(values - vertices[:, 0])) < 1e-6, "the colour field x is not interpolated at the vertices")

# A slab: ρ = 1 + 0.8 cos(2π y / L_y) = 1 at y = L_y/4 and 3L_y/4: two planes across the box.
box = (1.0, 2.0, 1.0)
x, y, z = cell_centres((16, 16, 16), box)
vertices, triangles, _ = isosurface(1 + 0.8 * np.cos(2 * math.pi * y / box[1]), y, box, 1.0)
area, _ = area_and_volume(vertices, triangles)
check(abs(area - 2 * box[0] * box[2]) < 1e-9, f"slab area {area}, expected {2 * box[0] * box[2]}")
heights = np.minimum(np.abs(vertices[:, 1] - 0.5), np.abs(vertices[:, 1] - 1.5))
check(heights.max() < 1e-6, f"slab planes off y = 0.5, 1.5 by up to {heights.max()}")

# Lees-Edwards images: V_x = γ (y − L_y/2) continues across the top as the bottom + U, U = γ L_y,
# so smoothing leaves it linear (plain wrapping would pull the top and bottom rows together).
box, cells = (1.0, 1.0, 1.0), (16, 16, 16)
x, y, z = cell_centres(cells, box)
gamma = 3.0
profile = gamma * (y - 0.5)
smoothed = smooth(profile, 2.0, np.ones_like(y), cells_offset=3.0, image_velocity=gamma * box[1])
check(np.max(np.abs(smoothed - profile)) < 1e-9, f"smoothing bent the shear profile by {np.max(np.abs(smoothed - profile))}")
# cos(2π (x − Δ y / L_y) / L_x) is periodic across the images offset by Δ (3 cells here): any
# symmetric smoothing multiplies it by one factor in every cell.
wave = np.cos(2 * math.pi * (x - (3.0 / 16) * y / box[1]) / box[0])
ratio = smooth(wave, 1.5, cells_offset=3.0)[np.abs(wave) > 0.3] / wave[np.abs(wave) > 0.3]
check(np.ptp(ratio) < 1e-9 and 0.0 < ratio.mean() < 1.0, f"smoothing across the images is not one factor: {ratio.min()} … {ratio.max()}")
wrong = smooth(wave, 1.5, cells_offset=0.0)[np.abs(wave) > 0.3] / wave[np.abs(wave) > 0.3]
check(np.ptp(wrong) > 1e-3, "the image offset makes no difference: the test cannot fail")


def fixed(text):
    """A fixed-length string attribute, as the C++ writers store them."""
    return np.bytes_(text)


def write_run(run, particles, box, shear_velocity, cells, frames=3, seed=5):
    """snapshots.h5 and fields.h5 of a synthetic sheared 3D run: a dense sheet across y = L_y/2 (every
    dataset and attribute of the schema, since granule reads them as it reads its own files)."""
    rng = np.random.default_rng(seed)
    run.mkdir(parents=True)
    with h5py.File(run / "snapshots.h5", "w") as f:
        f.attrs.update({"format": fixed("granule-snapshots"), "granule_version": fixed("test"), "dimension": 3,
                        "particles": particles, "diameter": 0.03, "box": np.array(box), "restitution": 0.8,
                        "tc_duration": 0.0, "boundary": fixed("lees-edwards"), "shear_velocity": shear_velocity,
                        "seed": np.uint64(1), "packing_fraction": 0.1})
        positions = rng.random((frames, particles, 3)) * np.array(box)
        velocities = 0.1 * rng.standard_normal((frames, particles, 3))
        velocities[..., 0] += shear_velocity / box[1] * (positions[..., 1] - box[1] / 2)
        # Per-frame datasets grow along their first axis, as the run writes them.
        def frames_of(name, values):
            f.create_dataset(name, data=values, maxshape=(None, *values.shape[1:]))
        frames_of("positions", positions)
        frames_of("velocities", velocities)
        for name in ("time", "collisions_per_particle", "shear_offset", "shear_velocity", "strain", "strain_reference",
                     "strain_at_reference"):
            frames_of(name, np.arange(frames, dtype=float) * (-1.0 if name == "strain_reference" else 1.0))
        for name in ("collisions", "events"):
            frames_of(name, 100 * np.arange(frames, dtype=np.int64))
        f["diameters"] = 0.01 + 0.02 * rng.random(particles)
        f["masses"] = (f["diameters"][()] / 0.02) ** 3
    x, y, z = cell_centres(cells, box)
    with h5py.File(run / "fields.h5", "w") as f:
        f.attrs.update({"format": fixed("granule-fields"), "source": fixed("run"), "boundary": fixed("lees-edwards"),
                        "nx": cells[0], "ny": cells[1], "length_x": box[0], "length_y": box[1], "dimension": 3,
                        "nz": cells[2], "length_z": box[2], "diameter": 0.02, "particles": particles, "restitution": 0.8,
                        "shear_velocity": shear_velocity, "subtract_shear_profile": 0})
        sheet = np.exp(-((y - box[1] / 2) ** 2) / 0.02) * (1 + 0.3 * np.cos(2 * math.pi * x / box[0]))
        for group in ("instant", "average"):
            f[f"{group}/density"] = np.array([1 + 2 * sheet + 0.05 * rng.standard_normal(sheet.shape) for _ in range(frames)])
            f[f"{group}/velocity_x"] = np.array([shear_velocity / box[1] * (y - box[1] / 2)] * frames)
        for name, values in (("t", np.arange(frames)), ("c", 5.0 * np.arange(frames)), ("t_start", np.zeros(frames)),
                             ("c_start", np.zeros(frames)), ("shear_offset", 0.1 * np.arange(frames)),
                             ("shear_velocity", np.full(frames, shear_velocity))):
            f[f"frames/{name}"] = np.asarray(values, dtype=float)


def png_size(path):
    header = Path(path).read_bytes()[:24]
    return int.from_bytes(header[16:20], "big"), int.from_bytes(header[20:24], "big")


def drawn(path):
    """The picture has content: more than one colour."""
    import matplotlib.image

    image = matplotlib.image.imread(str(path))
    return image[..., :3].std() > 0.01


run = WORK / "run3d"
write_run(run, 20000, (2.0, 2.0, 1.0), 2.0, (20, 20, 10))

r = granule("plot", "fields", run, "--size", 640, 480, "--average-frames", 2, "--level", 1.5, "--smooth", 1)
check(r.returncode == 0, f"plot fields (3D) failed: {r.stderr}")
check((run / "fields.png").exists() and png_size(run / "fields.png") == (640, 480), "fields.png is not 640 × 480")
check((run / "fields.png").exists() and drawn(run / "fields.png"), "fields.png is blank")

start = time.monotonic()
r = granule("plot", "config", run, "--width", 800, "--frame", 1)
seconds = time.monotonic() - start
print(f"plot config of 20000 spheres: {seconds:.1f} s")
check(r.returncode == 0, f"plot config (3D) failed: {r.stderr}")
check((run / "configuration.png").exists() and png_size(run / "configuration.png") == (800, 600), "configuration.png is not 800 × 600")
check((run / "configuration.png").exists() and drawn(run / "configuration.png"), "configuration.png is blank")
r = granule("plot", "config", run, "--width", 400, "--color", "speed", "--perspective", "--view", 10, -80, "--out", WORK / "p.png")
check(r.returncode == 0 and png_size(WORK / "p.png") == (400, 300), f"perspective picture: {r.stderr}")

for arguments, says in ((["config", run, "--cells", 4, 4], "--cells"), (["config", run, "--color", "direction"], "--color"),
                        (["fields", run, "--quantities", "density", "temperature"], "--quantities"),
                        (["fields", run, "--level", -1], "--level"), (["fields", run, "--average-frames", 9], "--average-frames"),
                        (["movie", run], "2D")):
    out = WORK / "refused.png"
    r = granule("plot", *arguments, "--out", out)
    check(r.returncode == 2 and says in r.stderr and not out.exists(), f"{arguments}: exit {r.returncode}, {r.stderr}")

# A 3D fields.h5 to ParaView: an nx × ny × nz image whose cell data are the file's maps.
r = granule("plot", "export", run, "--format", "vtk", "--what", "fields", "--frame", 1, "--out", WORK / "fields3d.vti")
check(r.returncode == 0, f"export of 3D fields failed: {r.stderr}")
reader = vtk.vtkXMLImageDataReader()
reader.SetFileName(str(WORK / "fields3d.vti"))
reader.Update()
image = reader.GetOutput()
check(image.GetDimensions() == (21, 21, 11), f"vti dimensions {image.GetDimensions()}")
check(np.allclose(image.GetSpacing(), (0.1, 0.1, 0.1)), f"vti spacing {image.GetSpacing()}")
with h5py.File(run / "fields.h5") as f:
    expected = f["average/density"][1]
exported = image.GetCellData().GetArray("average_density")
check(exported is not None and np.array_equal(vtk_to_numpy(exported).reshape(10, 20, 20), expected),
      "the exported density differs from the file's map")

# A 2D run refuses the options of 3D pictures.
flat = WORK / "run2d"
r = granule("run", "--out", flat, "--set", "system.particles=300", "--set", "run.until_collisions_per_particle=1")
check(r.returncode == 0, f"2D run failed: {r.stderr}")
for arguments, says in ((["config", flat, "--perspective"], "--perspective"), (["fields", flat, "--level", 2], "--level")):
    out = WORK / "refused2d.png"
    r = granule("plot", *arguments, "--out", out)
    check(r.returncode == 2 and says in r.stderr and not out.exists(), f"{arguments}: exit {r.returncode}, {r.stderr}")

finish()
