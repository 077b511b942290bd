"""The shear protocols and initial states of thesis Chapter 4 from the command line: U(t) and Δ(t)
stored per snapshot frame and in the time series agree with the protocol's formulas (written here
independently); config.toml repeats the run; a run under a protocol killed and resumed ends with
the same files; the static start has no shear profile; T_i may be given relative to T₀ of (4.5);
initial.from starts a run from another run's frame; bad protocol settings exit 2 naming the key."""
import csv
import math
import signal
import subprocess
import time

import h5py
import numpy as np

from harness import GRANULE, WORK, check, finish, granule

U0, TAU, AMPLITUDE, PERIOD, START, CYCLES, TOLERANCE = 10.0, 0.02, 3.0, 0.02, 0.03, 3.0, 1e-3
PROTOCOL = ["--set", "boundary.kind=lees-edwards", "--set", f"boundary.shear_velocity={U0}",
            "--set", f"boundary.shear_ramp_time={TAU}",
            "--set", f"boundary.shear_oscillation={{amplitude={AMPLITUDE}, period={PERIOD}, start={START}, cycles={CYCLES}}}"]
SYSTEM = ["--set", "system.particles=1000", "--set", "system.area_fraction=0.1", "--set", "system.restitution=0.8",
          "--set", "system.tc_duration=1e-6", "--set", "initial.equilibrate=1", "--set", "run.until_collisions_per_particle=30",
          "--set", "output.every_collisions_per_particle=0.5", "--set", "output.snapshot_every_collisions_per_particle=2"]


def u_exact(t):
    """U(t) = U0 (1 − e^{−t/τ}) + A sin(2π (t − t_s)/P) for t_s ≤ t ≤ t_s + nP."""
    u = U0 * (1.0 - math.exp(-t / TAU))
    if START <= t <= START + CYCLES * PERIOD:
        u += AMPLITUDE * math.sin(2.0 * math.pi * (t - START) / PERIOD)
    return u


def integral_exact(t):
    """∫₀ᵗ U dt′ of u_exact."""
    total = U0 * (t - TAU * (1.0 - math.exp(-t / TAU)))
    end = min(t, START + CYCLES * PERIOD)
    if end > START:
        k = 2.0 * math.pi / PERIOD
        total += AMPLITUDE / k * (1.0 - math.cos(k * (end - START)))
    return total


def datasets(path):
    out = {}
    with h5py.File(path, "r") as f:
        f.visititems(lambda name, obj: out.__setitem__(name, obj[()]) if isinstance(obj, h5py.Dataset) else None)
    return out


def same_h5(a, b):
    da, db = datasets(a), datasets(b)
    return sorted(k for k in da if k not in db or da[k].shape != db[k].shape or not np.array_equal(da[k], db[k]))


scale = U0 + AMPLITUDE
run = WORK / "ramp_kick"
r = granule("run", "--out", run, *SYSTEM, *PROTOCOL)
check(r.returncode == 0, f"protocol run failed: {r.stderr}")

with h5py.File(run / "snapshots.h5") as f:
    t, u, offset = f["time"][:], f["shear_velocity"][:], f["shear_offset"][:]
worst_u = max(abs(u[k] - u_exact(t[k])) for k in range(len(t)))
# |U_engine − U| ≤ tolerance·scale at every instant, so Δ can drift from ∫U by at most that times t.
worst_offset = max(abs(math.remainder(offset[k] - offset[0] - integral_exact(t[k]), 1.0)) / (TOLERANCE * scale * t[k] + 1e-12)
                   for k in range(1, len(t)))
print(f"{len(t)} frames to t = {t[-1]:.4g}: max |U − U(t)| = {worst_u:.3g} (tolerance {TOLERANCE * scale:.3g}); "
      f"max Δ error / (tol·scale·t) = {worst_offset:.3g}")
check(len(t) >= 10 and t[-1] > START + CYCLES * PERIOD, f"the run covers the protocol ({len(t)} frames to t = {t[-1]})")
check(worst_u <= TOLERANCE * scale * (1 + 1e-9), f"snapshot U(t) off the protocol by {worst_u}")
check(worst_offset <= 1.0, f"snapshot Δ(t) off ∫U by {worst_offset} of its bound")
with open(run / "timeseries.csv") as f:
    rows = list(csv.DictReader(f))
worst_row = max(abs(float(row["shear_velocity"]) - u_exact(float(row["t"]))) for row in rows)
check(worst_row <= TOLERANCE * scale * (1 + 1e-9), f"time-series shear_velocity off the protocol by {worst_row}")
config = (run / "config.toml").read_text()
check("shear_ramp_time = 0.02" in config and "shear_oscillation = { amplitude = 3" in config and "shear_tolerance" in config,
      "config.toml keeps the protocol")

# config.toml repeats the run, bit for bit.
again = WORK / "again"
r = granule("run", str(run / "config.toml"), "--out", again)
check(r.returncode == 0 and same_h5(run / "snapshots.h5", again / "snapshots.h5") == [],
      f"config.toml does not repeat the run: {r.stderr[-300:]}")

# Killed (SIGTERM) and SIGKILLed under the protocol, resumed each time: the same files as the run never interrupted.
killed = WORK / "killed"
command = [GRANULE, "run", "--out", str(killed), *SYSTEM, *PROTOCOL, "--set", "output.checkpoint_every_seconds=0.05"]
interruptions = 0

def next_command():
    """Resume when a checkpoint exists; a run killed before its first one starts again."""
    if (killed / "checkpoint.h5").exists():
        return [GRANULE, "run", "--resume", str(killed)]
    return [*command, "--force"]


for attempt, sig in enumerate([signal.SIGTERM, signal.SIGKILL, signal.SIGTERM]):
    config = killed / "config.toml"
    stamp = config.stat().st_mtime_ns if config.exists() else None
    process = subprocess.Popen(next_command(), stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    # Signal handlers are installed before config.toml is (re)written.
    deadline = time.monotonic() + 60
    while (not config.exists() or config.stat().st_mtime_ns == stamp) and process.poll() is None \
            and time.monotonic() < deadline:
        time.sleep(0.01)
    time.sleep(0.05 + 0.05 * attempt)
    process.send_signal(sig)
    code = process.wait(timeout=120)
    if code == 0:
        break
    interruptions += 1
r = subprocess.run(next_command(), capture_output=True, text=True, timeout=300)
check(r.returncode == 0, f"resume failed: {r.stderr[-300:]}")
differing = same_h5(run / "snapshots.h5", killed / "snapshots.h5")
check(differing == [], f"resumed run differs in {differing[:5]}")
check((run / "timeseries.csv").read_text() == (killed / "timeseries.csv").read_text(), "resumed time series differs")
print(f"{interruptions} interruptions, resumed run identical: {differing == []}")
check(interruptions >= 1, "the run was interrupted at least once")

# A static start (§4.3): no shear profile in the first frame; the default start has one.
def first_frame_slope(directory):
    with h5py.File(directory / "snapshots.h5") as f:
        positions, velocities = f["positions"][0], f["velocities"][0]
    return np.polyfit(positions[:, 1], velocities[:, 0], 1)[0]


static, sheared = WORK / "static", WORK / "sheared"
for directory, extra in ((static, ["--set", "initial.shear_profile=false"]), (sheared, [])):
    r = granule("run", "--out", directory, *SYSTEM[:8], "--set", "run.until_collisions_per_particle=1",
                "--set", "boundary.kind=lees-edwards", "--set", "boundary.shear_velocity=10", "--set", "initial.equilibrate=0",
                *extra)
    check(r.returncode == 0, f"{directory.name} start failed: {r.stderr[-300:]}")
slopes = first_frame_slope(static), first_frame_slope(sheared)
print(f"dV_x/dy of the first frame: static start {slopes[0]:.3g}, sheared start {slopes[1]:.3g} (γ = 10)")
check(abs(slopes[0]) < 0.5 and abs(slopes[1] - 10.0) < 0.5, f"initial profiles {slopes}")

# T_i relative to T₀ = l²γ²/(π ε) of (4.5), l = πσ/(8ν).
r = granule("run", "--out", WORK / "hot", *SYSTEM[:8], "--set", "boundary.kind=lees-edwards",
            "--set", "boundary.shear_velocity=10", "--set", "initial.temperature_over_steady=10",
            "--set", "run.until_collisions_per_particle=0.5")
check(r.returncode == 0, f"hot start failed: {r.stderr[-300:]}")
sigma = math.sqrt(4 * 0.1 / (math.pi * 1000))
t0 = (math.pi * sigma / (8 * 0.1)) ** 2 * 10.0 ** 2 / (math.pi * (1 - 0.8 ** 2))
written = float([line for line in (WORK / "hot" / "config.toml").read_text().splitlines() if line.startswith("temperature =")][0].split("=")[1])
check(abs(written / (10 * t0) - 1) < 1e-12, f"T_i = {written}, 10 T₀ = {10 * t0}")

# initial.from: frame 3 of the protocol run, continued with another restitution and constant U.
branch = WORK / "branch"
r = granule("run", "--out", branch, *SYSTEM[:6], "--set", "system.restitution=0.5", "--set", "boundary.kind=lees-edwards",
            "--set", "boundary.shear_velocity=4", "--set", f"initial.from=\"{run}\"", "--set", "initial.frame=3",
            "--set", "run.until_collisions_per_particle=1")
check(r.returncode == 0, f"initial.from failed: {r.stderr[-300:]}")
with h5py.File(run / "snapshots.h5") as a, h5py.File(branch / "snapshots.h5") as b:
    check(np.array_equal(a["positions"][3], b["positions"][0]) and np.array_equal(a["velocities"][3], b["velocities"][0]),
          "the branch starts from frame 3 exactly")
    check(b["shear_velocity"][0] == 4.0 and b["time"][0] == 0.0, "the branch runs its own protocol from t = 0")

# Bad settings: exit 2, nothing written, the key named.
bad = {
    "decreasing schedule": (["--set", "boundary.kind=lees-edwards", "--set", "boundary.shear_schedule=[[0, 1], [2, 3], [1, 4]]"],
                            "boundary.shear_schedule"),
    "ramp without U0": (["--set", "boundary.kind=lees-edwards", "--set", "boundary.shear_ramp_time=1"], "boundary.shear_ramp_time"),
    "oscillation without period": (["--set", "boundary.kind=lees-edwards", "--set", "boundary.shear_velocity=1",
                                    "--set", "boundary.shear_oscillation={amplitude=1}"], "period"),
    "unknown oscillation key": (["--set", "boundary.kind=lees-edwards", "--set", "boundary.shear_velocity=1",
                                 "--set", "boundary.shear_oscillation={amplitude=1, period=1, phase=2}"], "boundary.shear_oscillation.phase"),
    "protocol in a periodic box": (["--set", "boundary.shear_ramp_time=1"], "lees-edwards"),
    "schedule and U0": ([WORK / "both_u.toml"], "boundary.shear_schedule"),
    "T_i twice": ([WORK / "both_t.toml"], "initial.temperature"),
    "T0 of an elastic gas": (["--set", "boundary.kind=lees-edwards", "--set", "boundary.shear_velocity=1",
                              "--set", "system.restitution=1", "--set", "initial.temperature_over_steady=3"], "restitution < 1"),
    "missing source": (["--set", "initial.from=\"/nonexistent\""], "initial.from"),
    "another system": (["--set", "system.particles=999", "--set", f"initial.from=\"{run}\""], "must match"),
    "tolerance": (["--set", "boundary.kind=lees-edwards", "--set", "boundary.shear_velocity=1",
                   "--set", "boundary.shear_tolerance=0.5"], "boundary.shear_tolerance"),
}
# Two ways of saying one thing in one file are refused (a --set replaces the other way instead).
(WORK / "both_u.toml").write_text('[boundary]\nkind = "lees-edwards"\nshear_velocity = 1\nshear_schedule = [[0, 1]]\n')
(WORK / "both_t.toml").write_text('[boundary]\nkind = "lees-edwards"\nshear_velocity = 1\n'
                                  '[initial]\ntemperature = 2\ntemperature_over_steady = 3\n')
for name, (settings, fragment) in bad.items():
    out = WORK / ("bad_" + name.replace(" ", "_"))
    r = granule("run", "--out", out, *settings)
    check(r.returncode == 2 and fragment in r.stderr and not out.exists(),
          f"{name}: exit {r.returncode}, stderr {r.stderr.strip()[-200:]!r}")

finish()
