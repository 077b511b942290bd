"""End-to-end: every `granule plot` picture kind draws a PNG of the documented size from a real run
(read back with matplotlib's imread), the pictures carry the content that tells cases apart (ink of
the configuration equals the area fraction; a shaded map is light where the field is high), the
movie has one frame per snapshot (ffprobe), and bad input exits with code 2 writing nothing."""
import json
import subprocess

import h5py
import matplotlib.image
import numpy as np

from harness import WORK, check, finish, granule


def picture(path):
    """(height, width, RGB in [0, 1]) of a PNG, via matplotlib's independent PNG reader."""
    return matplotlib.image.imread(str(path))[:, :, :3]


# A free-cooling run in a 1 × 0.5 box: 2000 disks, ν = 0.05, three snapshots.
run = WORK / "run"
r = granule("run", "--out", run, "--set", "system.particles=2000", "--set", "system.box=[1.0, 0.5]",
            "--set", "run.until_collisions_per_particle=10", "--set", "output.snapshot_every_collisions_per_particle=5")
check(r.returncode == 0, f"run failed: {r.stderr}")
with h5py.File(run / "snapshots.h5") as f:
    frames = len(f["time"])

# config: 1000 px wide by default, the height follows the box (1 × 0.5 → 500 px).
r = granule("plot", "config", run)
check(r.returncode == 0, f"plot config failed: {r.stderr}")
image = picture(run / "configuration.png")
check(image.shape == (500, 1000, 3), f"configuration.png shape {image.shape}")
check(len(np.unique(image.reshape(-1, 3).round(2), axis=0)) > 50, "direction colouring has few colours")
# Disks to scale: with uniform grey disks and nothing else drawn, the ink covers ν of the picture.
r = granule("plot", "config", run, "--frame", 0, "--color", "none", "--no-arrows", "--no-legend", "--width", 2000,
            "--out", WORK / "ink.png")
check(r.returncode == 0, f"plot config --color none failed: {r.stderr}")
ink = np.mean((1.0 - picture(WORK / "ink.png")[:, :, 0]) / 0.85)
check(abs(ink - 0.05) < 0.0025, f"ink {ink:.4f} is not the area fraction 0.05")
# Lees–Edwards-style and field colourings run and keep the size.
for option in (["--color", "speed"], ["--color", "field", "--field", "temperature", "--cells", 8, 4], ["--relative"]):
    out = WORK / f"config_{option[-1]}.png"
    r = granule("plot", "config", run, "--width", 400, "--out", out, *option)
    check(r.returncode == 0 and picture(out).shape == (200, 400, 3), f"config {option}: {r.stderr}")

# timeseries (13.5 × 10.5 in) and phase (12 × 8 in) at 100 and 50 dpi.
for kind, (w, h) in {"timeseries": (13.5, 10.5), "phase": (12.0, 8.0)}.items():
    r = granule("plot", kind, run)
    check(r.returncode == 0, f"plot {kind} failed: {r.stderr}")
    check(picture(run / f"{kind}.png").shape == (round(h * 100), round(w * 100), 3), f"{kind}.png size")
    r = granule("plot", kind, run, "--dpi", 50, "--out", WORK / f"{kind}_50.png")
    check(r.returncode == 0 and picture(WORK / f"{kind}_50.png").shape == (round(h * 50), round(w * 50), 3),
          f"{kind} --dpi 50")

# fields and profiles from a fields file of the documented schema made here with h5py: a density
# that is high on the left half of the box (case A) or on the right half (case B).
def fields_file(path, left_high):
    nx, ny, k = 8, 6, 2
    x = (np.arange(nx) + 0.5) / nx
    high = (x < 0.5) if left_high else (x >= 0.5)
    density = np.broadcast_to(np.where(high, 3000.0, 1000.0), (k, ny, nx))
    with h5py.File(path, "w") as f:
        f.attrs.update(nx=nx, ny=ny, length_x=1.0, length_y=1.0, diameter=0.005, particles=2000, restitution=0.8,
                       boundary="lees-edwards", shear_velocity=10.0, subtract_shear_profile=0)
        for name, values in {"t": [1.0, 2.0], "c": [5.0, 10.0], "t_start": [0.0, 1.0], "c_start": [0.0, 5.0]}.items():
            f[f"frames/{name}"] = np.array(values)
        for group in ("instant", "average"):
            for name in ("count", "density", "velocity_x", "velocity_y", "temperature", "kinetic_xx", "kinetic_xy",
                         "kinetic_yy", "pressure_kinetic", "vorticity"):
                f[f"{group}/{name}"] = density if name == "density" else np.ones((k, ny, nx))
        for name in ("collisional_xx", "collisional_xy", "collisional_yy", "pressure_collisional", "total_xx",
                     "total_xy", "total_yy", "pressure_total"):
            f[f"average/{name}"] = np.ones((k, ny, nx))
        y = (np.arange(ny) + 0.5) / ny
        f["profiles/y"] = y
        for name in ("density", "velocity_x", "velocity_y", "temperature"):
            f[f"profiles/{name}"] = np.tile(10.0 * (y - 0.5), (k, 1))


grey = {}
for case, left_high in (("A", True), ("B", False)):
    folder = WORK / f"fields_{case}"
    folder.mkdir()
    fields_file(folder / "fields.h5", left_high)
    r = granule("plot", "fields", folder)
    check(r.returncode == 0, f"plot fields failed: {r.stderr}")
    check(picture(folder / "fields.png").shape == (900, 1000, 3), "fields.png: 2 × 2 panels of 5 × 4.5 in at 100 dpi")
    r = granule("plot", "fields", folder / "fields.h5", "--quantities", "density", "--group", "instant", "--frame", 0,
                "--out", folder / "density.png")
    check(r.returncode == 0, f"plot fields --quantities density failed: {r.stderr}")
    one = picture(folder / "density.png")
    check(one.shape == (450, 500, 3), f"one panel is 5 × 4.5 in: {one.shape}")
    grey[case] = one.mean(axis=2)
    r = granule("plot", "profiles", folder)
    check(r.returncode == 0 and picture(folder / "profiles.png").shape == (800, 1000, 3), f"profiles: {r.stderr}")
# In both maps the panel spans about 10 %–75 % of the width: sample the middle of each half.
row = 225
for case, bright, dark in (("A", 0.25, 0.55), ("B", 0.55, 0.25)):
    g = grey[case]
    lighter = g[row, int(bright * 500)] - g[row, int(dark * 500)]
    check(lighter > 0.5, f"case {case}: the high-density half is not lighter ({lighter:.2f})")

# movie: one frame per snapshot, even dimensions for H.264.
r = granule("plot", "movie", run, "--width", 301, "--fps", 4)
check(r.returncode == 0, f"plot movie failed: {r.stderr}")
probe = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                        "stream=width,height,nb_read_frames,codec_name", "-of", "json", str(run / "movie.mp4")],
                       capture_output=True, text=True)
stream = json.loads(probe.stdout)["streams"][0] if probe.returncode == 0 else {}
check(stream.get("codec_name") == "h264" and int(stream.get("nb_read_frames", -1)) == frames, f"movie stream {stream}")
check(stream.get("width") == 302 and stream.get("height") == 152, f"movie size {stream}")
check(not (run / "movie.mp4.frames").exists(), "movie scratch frames left behind")

# Bad input: exit code 2, a message naming the option, and no output.
bad = {
    "frame": (["config", run, "--frame", 99, "--out", WORK / "bad.png"], "--frame"),
    "color": (["config", run, "--color", "purple", "--out", WORK / "bad.png"], "--color"),
    "width": (["config", run, "--width", 5, "--out", WORK / "bad.png"], "--width"),
    "missing": (["config", WORK / "nowhere", "--out", WORK / "bad.png"], "does not exist"),
    "group": (["fields", WORK / "fields_A", "--group", "median", "--out", WORK / "bad.png"], "--group"),
    "quantity": (["fields", WORK / "fields_A", "--quantities", "entropy", "--out", WORK / "bad.png"], "--quantities"),
    "fields_frame": (["profiles", WORK / "fields_A", "--frame", 2, "--out", WORK / "bad.png"], "--frame"),
    "no_fields": (["fields", WORK / "ink.png", "--out", WORK / "bad.png"], "error"),
    "dpi": (["phase", run, "--dpi", 5000, "--out", WORK / "bad.png"], "--dpi"),
}
for name, (args, expected) in bad.items():
    r = granule("plot", *args)
    check(r.returncode == 2, f"{name}: exit code {r.returncode} ({r.stderr.strip()})")
    check(expected in r.stderr, f"{name}: message lacks '{expected}': {r.stderr.strip()}")
    check(not (WORK / "bad.png").exists(), f"{name}: output written")

finish()
