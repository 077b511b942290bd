"""`granule run --resume` trusts nothing it reads: each damage or edit of a run directory below is
refused with exit 2 and a message naming what is wrong, within a time limit, and the run directory
stays resumable once the damage is undone.  Edits of checkpoint.h5 are made with h5py, once as they
are (the dataset's digest no longer matches) and once with the digests recomputed, as a hostile
user would (`granule_file_fuzz reseal`): then the configuration, engine and schedule checks must
refuse them.  A run killed in its first second can be resumed (its first checkpoint is written
before its first event).  Prints the table of cases."""
import shutil
import signal
import subprocess
import sys
import time

import h5py
import numpy as np

from harness import GRANULE, WORK, check, finish, granule

FUZZER = sys.argv[3]
SYSTEM = ["--set", "system.particles=400", "--set", "boundary.kind=lees-edwards", "--set", "boundary.shear_velocity=20",
          "--set", "system.restitution=0.9", "--set", "system.tc_duration=1e-7",
          "--set", "output.snapshot_every_collisions_per_particle=2"]

base = WORK / "base"
result = granule("run", "--out", base, *SYSTEM, "--set", "run.until_collisions_per_particle=6")
check(result.returncode == 0, f"base run: {result.stderr}")


def edit_dataset(path, name, change):
    with h5py.File(path, "r+") as f:
        values = f[name][()]
        f[name][...] = change(np.array(values))


def flip_bits_in(path, name, count, seed):
    """Flips bits inside the stored bytes of one dataset (contiguous: its offset is known)."""
    with h5py.File(path, "r") as f:
        offset, size = f[name].id.get_offset(), f[name].id.get_storage_size()
    rng = np.random.default_rng(seed)
    with open(path, "r+b") as f:
        for position in rng.integers(offset, offset + size, count):
            f.seek(int(position))
            byte = f.read(1)[0]
            f.seek(int(position))
            f.write(bytes([byte ^ (1 << int(rng.integers(0, 8)))]))


def edit_config(path, old, new):
    text = path.read_text()
    check(old in text, f"config.toml has no line {old!r}")
    path.write_text(text.replace(old, new))


def at(index, value):
    def change(values):
        values = values.copy()
        values.flat[index] = value
        return values
    return change


def no_partner(values):
    """The first particle with a collision candidate loses it."""
    values = values.copy()
    values[np.flatnonzero(values >= 0)[0]] = -1
    return values


CASES = [
    # (name, edit of the run directory, digests resealed, words the refusal must contain)
    ("config.toml: restitution edited", lambda d: edit_config(d / "config.toml", "restitution = 0.9", "restitution = 0.7"),
     False, "system.restitution"),
    ("config.toml: particles edited", lambda d: edit_config(d / "config.toml", "particles = 400", "particles = 401"),
     False, "system.particles"),
    ("engine/restitution edited", lambda d: edit_dataset(d / "checkpoint.h5", "engine/restitution", at(0, 0.5)),
     False, "engine/restitution"),
    ("engine/restitution edited, digest resealed", lambda d: edit_dataset(d / "checkpoint.h5", "engine/restitution", at(0, 0.5)),
     True, "restitution"),
    ("engine/collisions = -5", lambda d: edit_dataset(d / "checkpoint.h5", "engine/collisions", at(0, -5)), False, "digest"),
    ("engine/collisions = -5, digest resealed", lambda d: edit_dataset(d / "checkpoint.h5", "engine/collisions", at(0, -5)),
     True, "collisions"),
    ("engine/clock_base = NaN, digest resealed", lambda d: edit_dataset(d / "checkpoint.h5", "engine/clock_base", at(0, np.nan)),
     True, "clock_base"),
    # The clock moved back: the time series then holds rows after the checkpoint's time.
    ("engine/clock_base moved back by 10, digest resealed",
     lambda d: edit_dataset(d / "checkpoint.h5", "engine/clock_base", lambda v: v - 10.0), True, "run/samples"),
    ("engine/t_now = inf, digest resealed", lambda d: edit_dataset(d / "checkpoint.h5", "engine/t_now", at(0, np.inf)),
     True, "t_now"),
    ("engine/event_partner of a particle = -1", lambda d: edit_dataset(d / "checkpoint.h5", "engine/event_partner", no_partner),
     False, "digest"),
    ("engine/event_partner of a particle = -1, digest resealed",
     lambda d: edit_dataset(d / "checkpoint.h5", "engine/event_partner", no_partner), True, "partner"),
    ("engine/x[3] moved onto a neighbour, digest resealed",
     lambda d: edit_dataset(d / "checkpoint.h5", "engine/x", lambda v: np.where(np.arange(v.size) == 3, v[4], v)),
     True, "invariant"),
    ("run/samples/t[1] = NaN", lambda d: edit_dataset(d / "checkpoint.h5", "run/samples/t", at(1, np.nan)), False, "digest"),
    ("run/samples/t[1] = NaN, digest resealed", lambda d: edit_dataset(d / "checkpoint.h5", "run/samples/t", at(1, np.nan)),
     True, "run/samples"),
    ("run/sampling/next_time = NaN, digest resealed",
     lambda d: edit_dataset(d / "checkpoint.h5", "run/sampling/next_time", at(0, np.nan)), True, "run/sampling"),
    ("run/snapshot_frames = -1, digest resealed",
     lambda d: edit_dataset(d / "checkpoint.h5", "run/snapshot_frames", at(0, -1)), True, "snapshot_frames"),
    ("run/config removed", lambda d: h5py.File(d / "checkpoint.h5", "r+").__delitem__("run/config"), False, "run/config"),
    ("10 bits flipped in engine/vx", lambda d: flip_bits_in(d / "checkpoint.h5", "engine/vx", 10, 1), False, "engine/vx"),
    ("10 bits flipped in engine/queue_time", lambda d: flip_bits_in(d / "checkpoint.h5", "engine/queue_time", 10, 2), False,
     "engine/queue_time"),
    ("checkpoint.h5 cut in half", lambda d: open(d / "checkpoint.h5", "r+b").truncate((d / "checkpoint.h5").stat().st_size // 2),
     False, "checkpoint.h5"),
]

rows = []
for index, (name, edit, reseal, words) in enumerate(CASES):
    run = WORK / f"case_{index}"
    shutil.copytree(base, run)
    edit(run)
    if reseal:
        resealed = subprocess.run([FUZZER, "reseal", run / "checkpoint.h5"], capture_output=True, text=True)
        check(resealed.returncode == 0, f"{name}: reseal failed: {resealed.stderr}")
    started = time.monotonic()
    try:
        result = granule("run", "--resume", run, "--set", "run.until_collisions_per_particle=8")
        code, message = result.returncode, result.stderr.strip().splitlines()
    except subprocess.TimeoutExpired:
        code, message = "timeout", ["no exit within 300 s"]
    seconds = time.monotonic() - started
    text = " ".join(message)
    refused = code == 2 and words in text
    rows.append((name, code, f"{seconds:.1f}", (message[0] if message else "")[:110]))
    check(refused, f"{name}: expected exit 2 naming {words!r}, got {code}: {text[-400:]}")

# The original directory is untouched and resumes; so does a run killed in its first second.
result = granule("run", "--resume", base, "--set", "run.until_collisions_per_particle=8")
check(result.returncode == 0, f"the undamaged run does not resume: {result.stderr}")
early = WORK / "killed_early"
process = subprocess.Popen([GRANULE, "run", "--out", early, *SYSTEM, "--set", "system.particles=20000",
                            "--set", "run.until_collisions_per_particle=50"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
time.sleep(1.0)
process.send_signal(signal.SIGKILL)
process.wait()
check((early / "checkpoint.h5").exists(), "a run killed after 1 s left no checkpoint")
result = granule("run", "--resume", early, "--set", "run.until_collisions_per_particle=0.5")
check(result.returncode == 0, f"a run killed after 1 s does not resume: {result.stderr[-400:]}")
rows.append(("SIGKILL 1 s after the start, then --resume", result.returncode, "", "resumed"))

width = max(len(r[0]) for r in rows)
print(f"{'case':{width}}  exit  seconds  message")
for name, code, seconds, message in rows:
    print(f"{name:{width}}  {str(code):4}  {seconds:>7}  {message}")
finish()
