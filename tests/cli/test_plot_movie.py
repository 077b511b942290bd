"""End-to-end: `granule plot movie` draws every --stride-th snapshot (ffprobe counts the frames), prints
t and c in the top-left corner of each frame (ink there only with the caption), and when ffmpeg is
missing or fails it exits with code 4 leaving no movie, no `.partial` and no scratch frames."""
import json
import os
import subprocess

import matplotlib.image
import numpy as np

from harness import GRANULE, WORK, check, finish, granule


def probe(path):
    r = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                        "stream=width,height,nb_read_frames", "-of", "json", str(path)], capture_output=True, text=True)
    return json.loads(r.stdout)["streams"][0] if r.returncode == 0 else {}


def first_frame(movie):
    """The movie's first frame as RGB in [0, 1], decoded by ffmpeg."""
    png = movie.with_suffix(".first.png")
    subprocess.run(["ffmpeg", "-loglevel", "error", "-y", "-i", str(movie), "-frames:v", "1", str(png)], check=True)
    return matplotlib.image.imread(str(png))[:, :, :3]


def leftovers(movie):
    return [p.name for p in movie.parent.iterdir() if p.name.startswith(movie.name)]


# A free-cooling run with seven snapshots (c = 0, 1, …, 6).
run = WORK / "run"
r = granule("run", "--out", run, "--set", "system.particles=1000", "--set", "run.until_collisions_per_particle=6",
            "--set", "output.snapshot_every_collisions_per_particle=1")
check(r.returncode == 0, f"run failed: {r.stderr}")

# Every frame, every second and every third frame: 7, 4 and 3 frames.
for stride, frames in ((1, 7), (2, 4), (3, 3)):
    movie = WORK / f"stride{stride}.mp4"
    r = granule("plot", "movie", run, "--stride", stride, "--width", 320, "--no-arrows", "--out", movie)
    check(r.returncode == 0, f"--stride {stride}: {r.stderr}")
    stream = probe(movie)
    check(int(stream.get("nb_read_frames", -1)) == frames and stream.get("width") == 320,
          f"--stride {stride}: {stream}, expected {frames} frames 320 wide")
    check(leftovers(movie) == [movie.name], f"--stride {stride} left {leftovers(movie)}")

# The caption: dark text on a white panel in the top-left corner (disks are coloured, the arrows off).
r = granule("plot", "movie", run, "--width", 320, "--no-arrows", "--no-caption", "--out", WORK / "bare.mp4")
check(r.returncode == 0, f"--no-caption: {r.stderr}")
corner = (slice(0, 24), slice(0, 120))
ink = {name: int((first_frame(WORK / f"{name}.mp4")[corner].max(axis=2) < 0.35).sum()) for name in ("stride1", "bare")}
check(ink["stride1"] > 40 and ink["bare"] < 5, f"dark pixels in the top-left corner: {ink}")
print(f"caption ink: {ink}")

# ffmpeg missing (PATH without it) or failing (a stand-in that writes half a file and exits 1).
fake = WORK / "fake_bin"
fake.mkdir()
(fake / "ffmpeg").write_text('#!/bin/sh\nfor a; do last="$a"; done\necho half-written > "$last"\nexit 1\n')
(fake / "ffmpeg").chmod(0o755)
empty = WORK / "empty_bin"
empty.mkdir()
for name, path in (("missing", empty), ("failing", fake)):
    movie = WORK / f"{name}.mp4"
    r = subprocess.run([GRANULE, "plot", "movie", str(run), "--width", "160", "--out", str(movie)], capture_output=True,
                       text=True, timeout=300, env={**os.environ, "PATH": str(path)})
    check(r.returncode == 4 and "ffmpeg" in r.stderr, f"ffmpeg {name}: exit {r.returncode}, {r.stderr.strip()}")
    check(leftovers(movie) == [], f"ffmpeg {name} left {leftovers(movie)}")

finish()
