"""Shared by the file fuzz tests (test_file_fuzz.py, test_measurement_fuzz.py): the small real
outputs that are mutated (a sheared 2D run with the TC model and rough grains; a 3D polydisperse
run between walls under gravity; each with its spectra and spin correlation, the 2D one with its f1
analysis), the
in-process fuzzer of a reader, and the command-line sample.

Seeded (GRANULE_FUZZ_SEED, default 1): a failure names the seed and the mutant's index, and
`granule_file_fuzz mutate ORIGINAL MUTANT SEED INDEX` writes that mutant again."""
import os
import shutil
import subprocess
import sys

from harness import GRANULE, WORK, check, granule

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


def seed_runs():
    """The seed runs' directories by name, with spectra.h5, spins.h5 (and f1.h5 in 2D) beside their outputs."""
    originals = {}
    for name, settings in RUNS.items():
        out = WORK / name
        result = granule("run", "--out", out, *settings)
        check(result.returncode == 0, f"seed run {name}: exit {result.returncode}: {result.stderr[-500:]}")
        if result.returncode == 0:
            spectra = granule("analyze", "spectra", out / "snapshots.h5", "--out", out / "spectra.h5", "--max-mode", 8)
            check(spectra.returncode == 0, f"spectra of {name}: {spectra.stderr[-500:]}")
            spins = granule("analyze", "spins", out, "--out", out / "spins.h5", "--bins", 8)
            check(spins.returncode == 0, f"spins of {name}: {spins.stderr[-500:]}")
            originals[name] = out
    # f1.h5 (2D only): one window of 2 × 2 cells wide enough for every cell of every frame, bootstrapped.
    if "sheared_2d" in originals:
        f1 = granule("analyze", "f1", originals["sheared_2d"] / "snapshots.h5", "--out", originals["sheared_2d"] / "f1.h5",
                     "--cells", "2,2", "--density-window", "300±300", "--temperature-window", "1e6±1e6", "--min-samples", 50,
                     "--bootstrap", 2, "--speed-bins", 16, "--angle-bins", 16)
        check(f1.returncode == 0, f"f1 of sheared_2d: {f1.stderr[-500:]}")
    return originals


def fuzz_reader(reader, original, mutants, work):
    """granule_file_fuzz READER on `mutants` mutants of `original`; prints its counts."""
    result = subprocess.run([FUZZER, reader, original, str(mutants), str(SEED), work], capture_output=True, text=True,
                            timeout=1800)
    print(result.stdout.strip(), f"({original.parent.name if original.is_file() else original.name})")
    check(result.returncode == 0, f"{reader} fuzz of {original}: exit {result.returncode}: {(result.stderr or result.stdout)[-2000:]}")


def files_under(path):
    return {p for p in path.rglob("*") if p.is_file()}


def command_line_sample(originals, targets, commands):
    """Each command of commands(mutant_dir, out)[target] on mutants of each of `targets` of each
    seed run: exit 0 or 2 within a time limit, nothing written outside its output.  A figure takes
    seconds: fewer mutants for the files only figures read (all but snapshots.h5 and checkpoint.h5)."""
    for name, out in originals.items():
        for target in (t for t in targets if (out / t).exists()):
            for index in range(CLI_MUTANTS if target in ("snapshots.h5", "checkpoint.h5") else min(CLI_MUTANTS, 4)):
                mutant_dir = WORK / f"cli_{name}" / "run"
                shutil.rmtree(mutant_dir.parent, ignore_errors=True)
                shutil.copytree(out, mutant_dir)
                made = subprocess.run([FUZZER, "mutate", out / target, mutant_dir / target, str(SEED), str(index)],
                                      capture_output=True, text=True, timeout=120)
                check(made.returncode == 0, f"mutate {target}: {made.stderr}")
                outputs = WORK / f"cli_{name}" / "outputs"
                for command in commands(mutant_dir, outputs)[target]:
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
