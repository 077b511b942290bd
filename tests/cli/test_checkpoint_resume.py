"""A run killed at random moments (SIGKILL, SIGINT, SIGTERM) and resumed each time from its checkpoint
ends with files identical, dataset by dataset and byte by byte, to the run that was never
interrupted; the trajectory does not depend on output cadence; --resume refuses physics changes;
an output directory in use is refused without --force."""
import csv
import json
import random
import signal
import subprocess
import time

import h5py
import numpy as np

from harness import GRANULE, WORK, check, finish, granule

SYSTEM = ["--set", "system.particles=1500", "--set", "boundary.kind=lees-edwards", "--set", "boundary.shear_velocity=50",
          "--set", "system.restitution=0.9", "--set", "system.tc_duration=1e-7", "--set", "collisions.free_paths=true",
          "--set", "run.until_collisions_per_particle=400"]
OUTPUTS = ["--set", "output.snapshot_every_collisions_per_particle=10", "--set", "output.checkpoint_every_seconds=0.05"]


def datasets(path):
    out = {}
    with h5py.File(path, "r") as f:
        f.visititems(lambda name, obj: out.__setitem__(name, obj[()]) if isinstance(obj, h5py.Dataset) else None)
    return out


def same_h5(a, b, prefix=""):
    da, db = datasets(a), datasets(b)
    keys = [k for k in da if k.startswith(prefix)]
    differing = [k for k in keys if k not in db or da[k].shape != db[k].shape or not np.array_equal(da[k], db[k], equal_nan=True)]
    return len(keys) > 0 and not differing, differing[:5]


reference = WORK / "reference"
result = granule("run", "--out", reference, *SYSTEM, *OUTPUTS)
check(result.returncode == 0, f"reference run: {result.stderr}")

# Kill the same run again and again at random moments; resume after each kill.
rng = random.Random(12)
killed = WORK / "killed"
kills = {"SIGKILL": 0, "SIGINT": 0, "SIGTERM": 0}
command = [GRANULE, "run", "--out", str(killed), *SYSTEM, *OUTPUTS]
for attempt in range(16):
    config = killed / "config.toml"
    stamp = config.stat().st_mtime_ns if config.exists() else None
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    # Not before the process has installed its handlers: it does so before it (re)writes
    # config.toml, which takes long on a loaded machine or under the sanitizers.
    deadline = time.monotonic() + 60
    while (not config.exists() or config.stat().st_mtime_ns == stamp) and process.poll() is None \
            and time.monotonic() < deadline:
        time.sleep(0.01)
    time.sleep(rng.uniform(0.05, 0.35))
    name = rng.choice(list(kills))
    process.send_signal(getattr(signal, name))
    code = process.wait(timeout=120)
    if code == 0:
        break  # it finished before the signal arrived
    kills[name] += 1
    expected = {"SIGKILL": -signal.SIGKILL, "SIGINT": 130, "SIGTERM": 143}[name]
    check(code == expected, f"{name}: exit {code}, expected {expected}: {process.stderr.read()[-300:]}")
    if name != "SIGKILL" and code == expected:
        # A run the signal stopped says so; one the signal met in its final writes (exit 128 + signal
        # all the same) has reached its end and says that.
        stop = json.loads((killed / "summary.json").read_text())["stop_reason"]
        check(stop in ("interrupted", "collisions reached"), f"an interrupted run says so in summary.json (says {stop!r})")
    if not (killed / "checkpoint.h5").exists():
        command = [GRANULE, "run", "--force", "--out", str(killed), *SYSTEM, *OUTPUTS]  # killed before its first checkpoint
    else:
        command = [GRANULE, "run", "--resume", str(killed)]
if code != 0:  # the last interruption: let it finish now
    result = subprocess.run(command, capture_output=True, text=True, timeout=300)
    check(result.returncode == 0, f"the last resume finishes: exit {result.returncode}: {result.stderr[-600:]}")
    if result.returncode != 0:
        finish()
print(f"kills: {kills}")
check(sum(kills.values()) >= 5, f"at least five interruptions: {kills}")
for name in ("snapshots.h5", "fields.h5", "collisions.h5"):
    same, differing = same_h5(reference / name, killed / name)
    check(same, f"{name} of the interrupted run equals the reference: differing {differing}")
check((reference / "timeseries.csv").read_bytes() == (killed / "timeseries.csv").read_bytes(), "time series identical")
same, differing = same_h5(reference / "checkpoint.h5", killed / "checkpoint.h5", "engine/")
check(same, f"final engine state identical: {differing}")
rows = list(csv.DictReader(open(killed / "timeseries.csv")))
check(len(rows) == 801, f"one row per 0.5 c from 0 to 400: {len(rows)}")

# Another output cadence (and no fields), same trajectory.
cadence = WORK / "cadence"
result = granule("run", "--out", cadence, *SYSTEM, "--set", "output.snapshot_every_collisions_per_particle=3",
                 "--set", "output.every_collisions_per_particle=0.1", "--set", "fields.enabled=false")
check(result.returncode == 0, f"cadence run: {result.stderr}")
same, differing = same_h5(reference / "checkpoint.h5", cadence / "checkpoint.h5", "engine/")
check(same, f"the engine state at c = 400 does not depend on output cadence: {differing}")

# Extending a finished run equals running longer at once.
longer = WORK / "longer"
result = granule("run", "--out", longer, *SYSTEM, *OUTPUTS, "--set", "run.until_collisions_per_particle=430")
check(result.returncode == 0, f"longer run: {result.stderr}")
result = granule("run", "--resume", reference, "--set", "run.until_collisions_per_particle=430")
check(result.returncode == 0, f"extension: {result.stderr}")
for name in ("snapshots.h5", "fields.h5", "collisions.h5"):
    same, differing = same_h5(longer / name, reference / name)
    check(same, f"{name} of the extended run equals the longer run: {differing}")

# A checkpoint of another format version (an older engine's bookkeeping) is refused with what to do,
# and nothing is written.
older = WORK / "older"
result = granule("run", "--out", older, *SYSTEM, "--set", "run.until_collisions_per_particle=5")
check(result.returncode == 0, f"short run: {result.stderr}")
with h5py.File(older / "checkpoint.h5", "r+") as f:
    f.attrs["format_version"] = np.int32(1)
before = {p.name: p.read_bytes() for p in older.iterdir() if p.is_file()}
result = granule("run", "--resume", older, "--set", "run.until_collisions_per_particle=10")
check(result.returncode != 0 and "format version 1" in result.stderr and "--from-frame" in result.stderr,
      f"an older checkpoint is refused with advice: exit {result.returncode}: {result.stderr[-400:]}")
check(before == {p.name: p.read_bytes() for p in older.iterdir() if p.is_file()}, "the refused resume wrote nothing")

# A resumed run keeps its physics; a directory in use is not overwritten silently.
result = granule("run", "--resume", reference, "--set", "system.restitution=0.5")
check(result.returncode == 2 and "system.restitution" in result.stderr, f"physics change refused: {result.stderr}")
result = granule("run", "--out", reference, *SYSTEM)
check(result.returncode == 2 and "--force" in result.stderr, f"directory in use refused: {result.stderr}")
(WORK / "a_file").write_text("x")
result = granule("run", "--out", WORK / "a_file", *SYSTEM)
check(result.returncode == 2 and "not a directory" in result.stderr, f"--out is a file: {result.stderr}")
result = granule("run", "--out", reference, "--force", "--set", "system.particles=300", "--set", "run.until_collisions_per_particle=1")
check(result.returncode == 0, f"--force: {result.stderr}")

# An inelastic collapse (no TC model, ẽ = 0.1 at ν = 0.4): exit 3 with advice that works as printed —
# continue from an earlier frame with the TC model; the later outputs are set aside, not lost.
# Within 60 collisions per disk about half the seeds collapse (16 of 30, with two builds); within
# 200 every one of 20 did.
collapsed = WORK / "collapsed"
result = granule("run", "--out", collapsed, "--set", "system.particles=400", "--set", "system.area_fraction=0.4",
                 "--set", "system.restitution=0.1", "--set", "system.tc_duration=0", "--set", "initial.equilibrate=2",
                 "--set", "run.until_collisions_per_particle=200", "--set", "output.snapshot_every_collisions_per_particle=1")
check(result.returncode == 3, f"collapse: exit {result.returncode}: {result.stderr[-300:]}")
advice = [line.strip() for line in result.stderr.splitlines() if line.strip().startswith("granule run --resume")]
check(len(advice) == 1 and "--from-frame" in advice[0] and "system.tc_duration=" in advice[0], f"advice: {result.stderr}")
if advice:
    frame = int(advice[0].split("--from-frame")[1].split()[0])
    with h5py.File(collapsed / "snapshots.h5") as f:
        before = f["positions"][: frame + 1]
    rows_before = (collapsed / "timeseries.csv").read_text().splitlines()
    result = granule(*advice[0].split()[1:])
    check(result.returncode == 0, f"the advised continuation runs: {result.stderr[-300:]}")
    aside = collapsed / f"set_aside_after_frame_{frame}"
    check((aside / "snapshots.h5").exists() and (aside / "summary.json").exists(), "the collapsed run's outputs are set aside")
    with h5py.File(collapsed / "snapshots.h5") as f:
        check(np.array_equal(f["positions"][: frame + 1], before), "frames up to K kept")
        check(f["time"].shape[0] > frame + 1, "the continuation adds frames")
    rows_after = (collapsed / "timeseries.csv").read_text().splitlines()
    kept = [row for row in rows_before if row in rows_after]
    check(len(kept) >= 2 and rows_after[: len(kept)] == kept, "time-series rows up to frame K kept")
    summary = json.loads((collapsed / "summary.json").read_text())
    check(summary["stop_reason"] == "collisions reached" and summary["tc_duration"] > 0, f"continued with TC: {summary}")

finish()
