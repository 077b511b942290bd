"""Every file Granule reads is untrusted.  Small real outputs (a sheared 2D run with the TC model and
rough grains; a 3D polydisperse run between walls under gravity) are mutated — attributes and
datasets deleted or given other shapes, counts, types or values (NaN, ±inf, negative, huge), bits
flipped, bytes zeroed, files cut short — and given to each reader:

- in one process (tests/fuzz/file_fuzz.cpp): GRANULE_FUZZ_MUTANTS (default 2000) mutants per reader
  (snapshots.h5, fields.h5, and checkpoint.h5 on resume, half of those edits with their digests
  recomputed as a hostile user would; collisions.h5, spectra.h5 and f1.h5 against the schema
  `granule plot` checks them with), each read cleanly or refused, never a crash, a hang or
  another error;
- GRANULE_FUZZ_FIGURE_MUTANTS (default 50) of the mutants of collisions.h5, spectra.h5 and f1.h5
  per seed run that the schema check accepted, drawn by their figure scripts
  (tests/fuzz/figure_fuzz.py: each in a child forked from one interpreter), each
  drawn or refused with exit 2, never a crash, a hang, an exception past the script's guard or a
  stray file;
- through the command line: a sample of the mutants (snapshots.h5, checkpoint.h5, and fields.h5,
  collisions.h5, spectra.h5 and f1.h5, which figure scripts read with h5py) given to `granule analyze`, `plot` and
  `run --resume`, each exiting with 0 or 2 within a time limit and writing nothing outside its
  output.

Seeded (GRANULE_FUZZ_SEED, default 1): a failure names the seed and the mutant's index, and
`granule_file_fuzz mutate ORIGINAL MUTANT SEED INDEX` writes that mutant again."""
import os
import shutil
import subprocess
import sys
from pathlib import Path

from harness import GRANULE, WORK, check, finish, granule

FUZZER = sys.argv[3]
MUTANTS = int(os.environ.get("GRANULE_FUZZ_MUTANTS", "2000"))
SEED = int(os.environ.get("GRANULE_FUZZ_SEED", "1"))
CLI_MUTANTS = int(os.environ.get("GRANULE_FUZZ_CLI_MUTANTS", "12"))
FIGURES = os.environ.get("GRANULE_FUZZ_FIGURES", "1") == "1"
# Figures drawn per measurement file and seed run, from the mutants its schema check accepted.
os.environ.setdefault("GRANULE_FUZZ_FIGURE_MUTANTS", "50")

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
        spectra = granule("analyze", "spectra", out / "snapshots.h5", "--out", out / "spectra.h5", "--max-mode", 8)
        check(spectra.returncode == 0, f"spectra of {name}: {spectra.stderr[-500:]}")
        originals[name] = out
# f1.h5 (2D only): one window of 2 × 2 cells wide enough for every cell of every frame, bootstrapped.
if "sheared_2d" in originals:
    f1 = granule("analyze", "f1", originals["sheared_2d"] / "snapshots.h5", "--out", originals["sheared_2d"] / "f1.h5",
                 "--cells", "2,2", "--density-window", "300±300", "--temperature-window", "1e6±1e6", "--min-samples", 50,
                 "--bootstrap", 2, "--speed-bins", 16, "--angle-bins", 16)
    check(f1.returncode == 0, f"f1 of sheared_2d: {f1.stderr[-500:]}")

# In one process: every reader, the mutant count split over the seed runs.
per_run = -(-MUTANTS // len(originals))
for reader, source in (("snapshots", "snapshots.h5"), ("fields", "fields.h5"), ("resume", "")):
    for name, out in originals.items():
        original = out / source if source else out
        result = subprocess.run([FUZZER, reader, original, str(per_run), str(SEED), WORK / f"fuzz_{reader}_{name}"],
                                capture_output=True, text=True, timeout=1800)
        print(result.stdout.strip(), f"({name})")
        check(result.returncode == 0, f"{reader} fuzz of {name}: exit {result.returncode}: {(result.stderr or result.stdout)[-2000:]}")

# The measurement files only figure scripts read: the schema check, then the scripts on what it accepted.
FIGURE_FUZZ = Path(__file__).resolve().parents[1] / "fuzz" / "figure_fuzz.py"
FIGURE_OPTIONS = {"collisions": [], "spectra": [], "f1": ["--dpi", "40"]}
for reader, source in (("collisions", "collisions.h5"), ("spectra", "spectra.h5"), ("f1", "f1.h5")):
    runs = {name: out for name, out in originals.items() if (out / source).exists()}
    for name, out in runs.items():
        work = WORK / f"fuzz_{reader}_{name}"
        result = subprocess.run([FUZZER, reader, out / source, str(-(-MUTANTS // len(runs))), str(SEED), work],
                                capture_output=True, text=True, timeout=1800)
        print(result.stdout.strip(), f"({name})")
        check(result.returncode == 0, f"{reader} fuzz of {name}: exit {result.returncode}: {(result.stderr or result.stdout)[-2000:]}")
        if not FIGURES:
            continue
        drawn = subprocess.run([sys.executable, FIGURE_FUZZ, FUZZER, reader, out / source, str(SEED), work / "accepted.txt",
                                WORK / f"figures_{reader}_{name}", *FIGURE_OPTIONS[reader]],
                               capture_output=True, text=True, timeout=3000)
        print(drawn.stdout.strip().splitlines()[-1] if drawn.stdout.strip() else "", f"({name})")
        check(drawn.returncode == 0, f"figure fuzz of {reader} of {name}: {(drawn.stdout + drawn.stderr)[-3000:]}")


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
        "f1.h5": [["plot", "f1", mutant_dir / "f1.h5", "--out", out / "f1.png"]],
    }


for name, out in originals.items():
    for target in (t for t in ("snapshots.h5", "checkpoint.h5", "fields.h5", "collisions.h5", "spectra.h5", "f1.h5")
                   if (out / t).exists()):
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

finish()
