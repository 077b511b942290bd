"""Every file Granule reads is untrusted.  Small real outputs (a sheared 2D run with the TC model and
rough grains; a 3D polydisperse run between walls under gravity) are mutated — attributes and
datasets deleted or given other shapes, counts, types or values (NaN, ±inf, negative, huge), bits
flipped, bytes zeroed, files cut short — and given to each reader:

- in one process (tests/fuzz/file_fuzz.cpp): GRANULE_FUZZ_MUTANTS (default 2000) mutants per reader
  (snapshots.h5, fields.h5, and checkpoint.h5 on resume, half of those edits with their digests
  recomputed as a hostile user would), each read cleanly or refused, never a crash, a hang or
  another error;
- in one process, text files mutated a byte, a line, a number or a JSON value at a time: a sweep
  point's record and its run's summary.json (as a sweep restart and --collect read them), and
  timeseries.csv, GRANULE_FUZZ_MUTANTS of each;
- through the command line: a sample of the mutants (snapshots.h5, checkpoint.h5, and fields.h5,
  collisions.h5 and spectra.h5, which figure scripts read with h5py) given to `granule analyze`, `plot` and
  `run --resume`, each exiting with 0 or 2 within a time limit and writing nothing outside its
  output; mutants of timeseries.csv given to `plot timeseries` likewise, and of a sweep's records and
  summaries to `granule sweep DIR --collect` and a restart, which may also exit with 6 when an
  accepted mutant says a point failed.

Seeded (GRANULE_FUZZ_SEED, default 1): a failure names the seed and the mutant's index, and
`granule_file_fuzz mutate ORIGINAL MUTANT SEED INDEX` (`mutate-text` for a text file) writes that
mutant again."""
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

from harness import GRANULE, WORK, check, finish, granule

FUZZER = sys.argv[3]
MUTANTS = int(os.environ.get("GRANULE_FUZZ_MUTANTS", "2000"))
SEED = int(os.environ.get("GRANULE_FUZZ_SEED", "1"))
CLI_MUTANTS = int(os.environ.get("GRANULE_FUZZ_CLI_MUTANTS", "12"))

RUNS = {
    "sheared_2d": ["--set", "system.particles=300", "--set", "boundary.kind=lees-edwards", "--set", "boundary.shear_velocity=20",
                   "--set", "system.restitution=0.9", "--set", "system.tc_duration=1e-7", "--set", "system.tangential_restitution=0.5",
                   "--set", "fields.enabled=true", "--set", "fields.every_collisions_per_particle=2",
                   "--set", "output.snapshot_every_collisions_per_particle=2", "--set", "run.until_collisions_per_particle=6"],
    "walls_3d": ["--set", "system.dimension=3", "--set", "system.particles=300", "--set", "system.box=[1, 1, 1]",
                 "--set", "system.packing_fraction=0.1",
                 "--set", "boundary.kind=walls", "--set", "boundary.wall_axes=[\"y\"]", "--set", "system.gravity=[0, -1, 0]",
                 "--set", "system.diameters={distribution = \"bidisperse\", ratio = 1.4, fraction = 0.5}",
                 "--set", "system.tangential_restitution=0.3", "--set", "fields.enabled=true",
                 "--set", "fields.every_collisions_per_particle=2",
                 "--set", "output.snapshot_every_collisions_per_particle=2", "--set", "run.until_collisions_per_particle=6"],
}

originals = {}
for name, settings in RUNS.items():
    out = WORK / name
    result = granule("run", "--out", out, *settings)
    check(result.returncode == 0, f"seed run {name}: exit {result.returncode}: {result.stderr[-500:]}")
    if result.returncode == 0:
        spectra = granule("analyze", "spectra", out / "snapshots.h5", "--out", out / "spectra.h5")
        check(spectra.returncode == 0, f"spectra of {name}: {spectra.stderr[-500:]}")
        originals[name] = out

# In one process: every reader, the mutant count split over the seed runs.
per_run = -(-MUTANTS // len(originals))
for reader, source in (("snapshots", "snapshots.h5"), ("fields", "fields.h5"), ("resume", "")):
    for name, out in originals.items():
        original = out / source if source else out
        result = subprocess.run([FUZZER, reader, original, str(per_run), str(SEED), WORK / f"fuzz_{reader}_{name}"],
                                capture_output=True, text=True, timeout=1800)
        print(result.stdout.strip(), f"({name})")
        check(result.returncode == 0, f"{reader} fuzz of {name}: exit {result.returncode}: {(result.stderr or result.stdout)[-2000:]}")

# A tiny sweep of two points, whose records and summaries a restart and --collect read back.
SWEEP_SPEC = """seed = 3
[system]
particles = 100
[run]
until_collisions_per_particle = 2
[sweep]
system.restitution = [0.7, 0.9]
"""
sweep_spec = WORK / "sweep.toml"
sweep_spec.write_text(SWEEP_SPEC)
sweep_dir = WORK / "sweep"
result = granule("sweep", sweep_spec, "--out", sweep_dir, "--jobs", "2")
check(result.returncode == 0, f"seed sweep: exit {result.returncode}: {result.stderr[-500:]}")
records = sorted((sweep_dir / "points").glob("*.json"))

# In one process: the text readers, the mutant count split over their originals.
text_originals = {"sweep-record": records[:1], "timeseries": [out / "timeseries.csv" for out in originals.values()]}
for reader, files in text_originals.items():
    started = time.monotonic()
    for k, original in enumerate(files):
        result = subprocess.run([FUZZER, reader, original, str(-(-MUTANTS // len(files))), str(SEED), WORK / f"fuzz_{reader}_{k}"],
                                capture_output=True, text=True, timeout=1800)
        print(result.stdout.strip(), f"({original.parent.name})")
        check(result.returncode == 0, f"{reader} fuzz of {original}: exit {result.returncode}: {(result.stderr or result.stdout)[-2000:]}")
    print(f"{reader}: {time.monotonic() - started:.1f} s")


def files_under(path):
    return {p for p in path.rglob("*") if p.is_file()}


# Through the command line: each command on mutants of the file it reads; exit 0 or 2, nothing
# written outside its output.
def commands(run, mutant_dir, out):
    snapshots = mutant_dir / "snapshots.h5"
    return {
        "snapshots.h5": [
            ["analyze", "fields", snapshots, "--out", out / "fields.h5"],
            ["analyze", "spectra", snapshots, "--out", out / "spectra.h5"],
            ["analyze", "f1", snapshots, "--out", out / "f1.h5"],
            ["plot", "config", snapshots, "--out", out / "config.png"],
            ["plot", "export", snapshots, "--format", "xyz", "--out", out / "export.xyz"],
            ["analyze", "collisions", mutant_dir, "--frame", "-1", "--out", out / "collisions"],
        ],
        "checkpoint.h5": [["run", "--resume", mutant_dir]],
        # Read by the figure scripts (h5py) after Granule's own reading layer has opened them.
        "fields.h5": [
            ["plot", "fields", mutant_dir / "fields.h5", "--out", out / "fields.png"],
            ["plot", "export", mutant_dir / "fields.h5", "--format", "vtk", "--out", out / "fields.vti"],
        ],
        "collisions.h5": [["plot", "collisions", mutant_dir / "collisions.h5", "--out", out / "collisions.png"]],
        "spectra.h5": [["plot", "spectra", mutant_dir / "spectra.h5", "--out", out / "spectra.png"]],
    }


for name, out in originals.items():
    for target in ("snapshots.h5", "checkpoint.h5", "fields.h5", "collisions.h5", "spectra.h5"):
        # A figure takes seconds: fewer mutants for the files only figures read.
        for index in range(CLI_MUTANTS if target in ("snapshots.h5", "checkpoint.h5") else min(CLI_MUTANTS, 4)):
            mutant_dir = WORK / f"cli_{name}" / "run"
            shutil.rmtree(mutant_dir.parent, ignore_errors=True)
            shutil.copytree(out, mutant_dir)
            made = subprocess.run([FUZZER, "mutate", out / target, mutant_dir / target, str(SEED), str(index)],
                                  capture_output=True, text=True, timeout=120)
            check(made.returncode == 0, f"mutate {target}: {made.stderr}")
            outputs = WORK / f"cli_{name}" / "outputs"
            for command in commands(name, mutant_dir, outputs)[target]:
                shutil.rmtree(outputs, ignore_errors=True)
                outputs.mkdir(parents=True)
                before = files_under(WORK / f"cli_{name}")
                label = f"{' '.join(map(str, command[:2]))} on {name} {target} mutant {SEED}/{index} ({made.stdout.strip()})"
                try:
                    result = subprocess.run([GRANULE, *map(str, command)], capture_output=True, text=True, timeout=120,
                                            cwd=outputs)
                except subprocess.TimeoutExpired:
                    check(False, f"{label}: no exit within 120 s")
                    continue
                check(result.returncode in (0, 2), f"{label}: exit {result.returncode}: {result.stderr[-600:]}")
                if command[0] == "run":
                    continue  # a resume rewrites its own run directory
                stray = [p for p in files_under(WORK / f"cli_{name}") - before if outputs not in p.parents]
                check(not stray, f"{label}: wrote outside its output: {sorted(map(str, stray))[:3]}")


def run_mutant_command(command, label, allowed, sandbox, outputs):
    """Runs granule COMMAND on a mutant; it must exit with one of `allowed` within the time limit
    and write nothing under `sandbox` outside `outputs` (files or directories)."""
    before = {p: p.stat().st_mtime_ns for p in files_under(sandbox)}
    try:
        result = subprocess.run([GRANULE, *map(str, command)], capture_output=True, text=True, timeout=120, cwd=sandbox)
    except subprocess.TimeoutExpired:
        check(False, f"{label}: no exit within 120 s")
        return None
    check(result.returncode in allowed, f"{label}: exit {result.returncode}: {result.stderr[-600:]}")
    changed = [p for p in files_under(sandbox) if before.get(p) != p.stat().st_mtime_ns
               and not any(p == o or o in p.parents for o in outputs)]
    check(not changed, f"{label}: wrote outside its output: {sorted(map(str, changed))[:3]}")
    return result


def text_mutant(original, mutant, index):
    made = subprocess.run([FUZZER, "mutate-text", original, mutant, str(SEED), str(index)], capture_output=True, text=True,
                          timeout=120)
    check(made.returncode == 0, f"mutate-text {original}: {made.stderr}")
    return made.stdout.strip()


started = time.monotonic()
# timeseries.csv through plot timeseries (a figure takes seconds: a few mutants).
for index in range(min(CLI_MUTANTS, 4)):
    name, out = list(originals.items())[index % len(originals)]
    sandbox = WORK / "cli_timeseries"
    shutil.rmtree(sandbox, ignore_errors=True)
    shutil.copytree(out, sandbox / "run")
    what = text_mutant(out / "timeseries.csv", sandbox / "run" / "timeseries.csv", index)
    (sandbox / "outputs").mkdir()
    run_mutant_command(["plot", "timeseries", sandbox / "run", "--out", sandbox / "outputs" / "timeseries.png"],
                       f"plot timeseries on {name} mutant {SEED}/{index} ({what})", (0, 2), sandbox, [sandbox / "outputs"])

# A point's record (even mutants) or its summary.json (odd) through --collect and a restart: 6 when
# an accepted mutant says a point failed or is pending, as for any incomplete sweep.
if records:
    point = records[0].stem
    for index in range(CLI_MUTANTS):
        sandbox = WORK / "cli_sweep"
        shutil.rmtree(sandbox, ignore_errors=True)
        shutil.copytree(sweep_dir, sandbox / "sweep")
        target = Path("points") / f"{point}.json" if index % 2 == 0 else Path("runs") / point / "summary.json"
        what = text_mutant(sweep_dir / target, sandbox / "sweep" / target, index)
        label = f"{target} mutant {SEED}/{index} ({what})"
        results_before = (sandbox / "sweep" / "results.csv").read_text()
        collected = run_mutant_command(["sweep", sandbox / "sweep", "--collect"], f"sweep --collect on {label}", (0, 2, 6),
                                       sandbox, [sandbox / "sweep" / "results.csv"])
        if collected is not None and collected.returncode == 2:
            check((sandbox / "sweep" / "results.csv").read_text() == results_before,
                  f"sweep --collect on {label}: refused, yet results.csv changed")
        if index < 4:  # a restart may run a point again: a few
            run_mutant_command(["sweep", sweep_spec, "--out", sandbox / "sweep"], f"sweep restart on {label}", (0, 2, 6),
                               sandbox, [sandbox / "sweep"])
print(f"command-line sample of the text files: {time.monotonic() - started:.1f} s")

finish()
