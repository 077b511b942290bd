"""granule sweep: a 2×2×2 sweep of tiny runs gives the same results.csv locally (--jobs 2), under
mpirun -n 2 (--mpi) and as three array tasks gathered by --collect, and every point equals a plain
`granule run` of its config.toml bit for bit; a second call skips finished points, an interrupted
point resumes from its checkpoint (and still equals the plain run), a failing point is recorded
with its error without stopping the others, bad specs are refused with nothing written, and
`granule plot sweep` draws a swept quantity with the kinetic-theory curves."""
import csv
import json
import os
import shutil
import signal
import subprocess
import time

import h5py
import numpy as np

from harness import GRANULE, WORK, check, finish, granule

# Tiny Lees–Edwards runs: 200 disks, 3 collisions per disk after a one-collision pre-run.
BASE = """
seed = 7
[system]
particles = 200
area_fraction = 0.1
restitution = 0.8
[boundary]
kind = "lees-edwards"
shear_velocity = 2.0
[initial]
equilibrate = 1
[run]
until_collisions_per_particle = 3
[output]
every_collisions_per_particle = 0.5
"""
SPEC = BASE + """
[sweep]
system.restitution = [0.7, 0.9]
"boundary.shear_velocity" = [1.0, 2.5]
seeds = 2
"""
TIMING = {"point_seconds", "summary.wall_seconds", "summary.collisions_per_second"}
MPI_ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def write(name, text):
    path = WORK / name
    path.write_text(text)
    return path


def rows(directory):
    with open(directory / "results.csv", newline="") as f:
        return list(csv.DictReader(f))


def without_timing(table):
    return [{k: v for k, v in row.items() if k not in TIMING} for row in table]


def timed(command, env=None):
    """The finished process and its wall time in seconds."""
    start = time.monotonic()
    result = subprocess.run(list(map(str, command)), capture_output=True, text=True, timeout=300, env=env)
    return result, time.monotonic() - start


def final_state(run_dir):
    with h5py.File(run_dir / "snapshots.h5", "r") as f:
        return {name: f[name][-1] for name in ("positions", "velocities", "time", "shear_offset")}


def same_run(a, b):
    """The same final state bit for bit, and the same summary apart from timing and what the last
    invocation alone did (a resumed run's pre-run happened in the first)."""
    sa, sb = final_state(a), final_state(b)
    if any(not np.array_equal(sa[k], sb[k]) for k in sa):
        return False
    ja, jb = (json.loads((d / "summary.json").read_text()) for d in (a, b))
    for j in (ja, jb):
        for key in ("wall_seconds", "collisions_per_second", "prerun_collisions_this_invocation"):
            j.pop(key)
    return ja == jb


spec = write("sweep.toml", SPEC)
timings = {}

# --- locally, two processes at once ------------------------------------------------------------
local = WORK / "local"
result, timings["local --jobs 2"] = timed([GRANULE, "sweep", spec, "--out", local, "--jobs", "2"])
check(result.returncode == 0, f"local sweep: exit {result.returncode}: {result.stderr[-800:]}")
reference = rows(local) if (local / "results.csv").exists() else []
check(len(reference) == 8, f"8 points in results.csv, got {len(reference)}")
check(all(r["status"] == "finished" for r in reference), "every point finished")
check(sum(" finished in " in line for line in result.stdout.splitlines()) == 8, f"one line per point:\n{result.stdout}")
names = [r["point"] for r in reference]
check("shear_velocity=1__restitution=0.7__seed=7" in names, f"readable point names: {names[:3]}")
check(len(set(names)) == 8 and all((local / "runs" / n / "config.toml").exists() for n in names),
      "each point has its own run directory with its resolved config")
check(reference and {"system.restitution", "boundary.shear_velocity", "seed", "summary.t",
                     "summary.steady_shear.temperature_measured"} <= set(reference[0]), "parameter and summary columns")

# Every point is the plain run of its own config.toml, bit for bit.
for name in names:
    plain = WORK / "plain" / name
    ran = granule("run", local / "runs" / name / "config.toml", "--out", plain)
    check(ran.returncode == 0 and same_run(local / "runs" / name, plain), f"{name} equals a plain granule run of its config")

# --- a second call skips what is done ------------------------------------------------------------
result = granule("sweep", spec, "--out", local, "--jobs", "2")
check(result.returncode == 0 and result.stdout.count("skipped (finished before)") == 8,
      f"the restart skips all 8 points: {result.stdout[-500:]}")
check(rows(local) == reference, "a restart leaves results.csv as it was")

# --- under MPI ---------------------------------------------------------------------------------
probe = granule("sweep", spec, "--out", WORK / "probe", "--mpi")
if "built without MPI" in probe.stderr or shutil.which("mpirun") is None:
    check(probe.returncode == 2 and not (WORK / "probe").exists(), "without MPI, --mpi is refused clearly")
    print("SKIPPED: the MPI sweep (granule built without MPI or no mpirun)")
else:
    shutil.rmtree(WORK / "probe", ignore_errors=True)
    mpi = WORK / "mpi"
    result, timings["mpirun -n 2 --mpi"] = timed(["mpirun", "--oversubscribe", "-n", "2", GRANULE, "sweep", spec, "--out",
                                                  mpi, "--mpi"], env=MPI_ENV)
    check(result.returncode == 0, f"MPI sweep: exit {result.returncode}: {result.stderr[-800:]}")
    check((mpi / "results.csv").exists() and without_timing(rows(mpi)) == without_timing(reference),
          "MPI results.csv equals the local one")

# --- as array tasks, gathered afterwards ---------------------------------------------------------
array = WORK / "array"
start = time.monotonic()
for task in range(3):
    result = granule("sweep", spec, "--out", array, "--array-task", task, "--array-count", "3")
    check(result.returncode == 0 and "--collect" in result.stdout, f"array task {task}: {result.stderr[-500:]}")
check(not (array / "results.csv").exists(), "array tasks leave results.csv to --collect")
collected = granule("sweep", array, "--collect")
timings["3 array tasks + collect"] = time.monotonic() - start
check(collected.returncode == 0 and "8 finished" in collected.stdout, f"collect: {collected.stdout}{collected.stderr}")
check((array / "results.csv").exists() and without_timing(rows(array)) == without_timing(reference),
      "collected results.csv equals the local one")
env = dict(os.environ, SLURM_ARRAY_TASK_ID="3", SLURM_ARRAY_TASK_MIN="1", SLURM_ARRAY_TASK_COUNT="4")
slurm = subprocess.run([GRANULE, "sweep", spec, "--out", WORK / "slurm"], capture_output=True, text=True, env=env, timeout=300)
check(slurm.returncode == 0 and slurm.stdout.count(" finished in ") == 2 and "task 2 of 4" in slurm.stdout,
      f"SLURM's array variables choose the task: {slurm.stdout}")

# --- an interrupted point resumes from its checkpoint --------------------------------------------
long_spec = write("long.toml", BASE.replace("particles = 200", "particles = 3000").replace(
    "until_collisions_per_particle = 3", "until_collisions_per_particle = 400") + "[sweep]\nseeds = [11]\n")
long_dir = WORK / "long"
# In a session of its own, signalled as a whole, as a terminal's Ctrl-C or a batch system's time
# limit signals a job: the running point gets the signal once and checkpoints.
process = subprocess.Popen([GRANULE, "sweep", long_spec, "--out", long_dir], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                           text=True, start_new_session=True)
log = long_dir / "points" / "seed=11.log"
# The run writes its config.toml once its signal handlers are in place, then runs for seconds.
started = long_dir / "runs" / "seed=11" / "config.toml"
deadline = time.monotonic() + 60
while not started.exists() and process.poll() is None and time.monotonic() < deadline:
    time.sleep(0.02)
time.sleep(0.3)
os.killpg(process.pid, signal.SIGTERM)
out, err = process.communicate(timeout=120)
check(process.returncode == 143, f"an interrupted sweep exits 143: {process.returncode}: {err[-300:]}")
interrupted = rows(long_dir)[0]
check(interrupted["status"] == "interrupted", f"the point is recorded as interrupted: {interrupted['status']}")
result = granule("sweep", long_spec, "--out", long_dir)
check(result.returncode == 0 and "resuming" in log.read_text(), f"the restart resumes it: {result.stdout[-300:]}")
plain = WORK / "plain_long"
granule("run", long_dir / "runs" / "seed=11" / "config.toml", "--out", plain)
check(same_run(long_dir / "runs" / "seed=11", plain), "the resumed point equals the plain run bit for bit")

# --- a failing point is recorded and the others still run ----------------------------------------
first = local / "runs" / names[0]
failing = write("failing.toml", BASE + f'[sweep]\n"initial.from" = ["{first}", "{WORK / "no-such-run"}"]\n')
result = granule("sweep", failing, "--out", WORK / "failing", "--jobs", "2")
check(result.returncode == 6, f"a sweep with a failed point exits 6: {result.returncode}")
check("1 finished, 1 failed" in result.stdout, f"the summary line counts them: {result.stdout[-300:]}")
table = rows(WORK / "failing")
bad = [r for r in table if r["status"] == "failed"]
check(len(bad) == 1 and bad[0]["exit_code"] == "2" and "no-such-run" in bad[0]["error"],
      f"the failed point's exit code and error: {bad}")

# --- bad specs: refused, naming the key, with nothing written ------------------------------------
bad_specs = {
    "unknown key": ("system.restitutio = [0.7]", "system.restitutio"),
    "empty list": ("system.restitution = []", "system.restitution"),
    "not a list": ("system.restitution = 0.7", "system.restitution"),
    "unequal zip": ("system.restitution = [0.7, 0.8]\n\"boundary.shear_velocity\" = [1.0]\nzip = true", "zip"),
    "zip of an unswept key": ("system.restitution = [0.7]\nzip = [\"system.particles\"]", "system.particles"),
    "invalid value": ("system.restitution = [0.7, 1.5]", "system.restitution"),
    "bad seeds": ("seeds = 0", "seeds"),
    "seed twice": ("seed = [1, 2]\nseeds = 2", "seed"),
    "no keys": ("", "[sweep]"),
}
for label, (body, key) in bad_specs.items():
    path = write("bad.toml", BASE + "[sweep]\n" + body + "\n")
    out = WORK / "bad_out"
    result = granule("sweep", path, "--out", out)
    check(result.returncode == 2 and key in result.stderr and not out.exists(),
          f"{label}: exit {result.returncode}, names {key}, writes nothing: {result.stderr.strip()}")
result = granule("sweep", write("other.toml", SPEC.replace("0.9]", "0.95]")), "--out", local)
check(result.returncode == 2 and "another sweep" in result.stderr, f"a DIR of another sweep is refused: {result.stderr}")

# --- the plot ------------------------------------------------------------------------------------
plotted = granule("plot", "sweep", local, "--x", "system.restitution", "--y", "summary.steady_shear.temperature_measured")
check(plotted.returncode == 0 and (local / "sweep.png").exists(), f"plot sweep: {plotted.stderr[-500:]}")
refused = granule("plot", "sweep", local, "--x", "system.restitution", "--y", "no_such_column")
check(refused.returncode == 2 and "no_such_column" in refused.stderr, f"an unknown column is refused: {refused.stderr}")

for label, seconds in timings.items():
    print(f"2×2×2 sweep, {label}: {seconds:.2f} s")
finish()
