"""The text files Granule reads back are untrusted too: a sweep point's record and its run's
summary.json (as a sweep restart and --collect read them), and timeseries.csv (on --resume and
before `plot timeseries`).  Mutated a byte, a line, a number or a JSON value at a time
(tests/fuzz/text_mutator.cpp), they meet:

- their readers in one process (tests/fuzz/file_fuzz.cpp): GRANULE_FUZZ_MUTANTS (default 2000) of
  each, each read cleanly or refused, never a crash, a hang or another error;
- the command line: mutants of timeseries.csv given to `plot timeseries`, and of a sweep's records
  and summaries to `granule sweep DIR --collect` and a restart, each exiting with 0 or 2 (a sweep
  also 6, when an accepted mutant says a point failed) within a time limit and writing nothing
  outside its output.

`granule_file_fuzz mutate-text ORIGINAL MUTANT SEED INDEX` writes a mutant again."""
import shutil
import subprocess
import time
from pathlib import Path

from fuzz_seeds import CLI_MUTANTS, FUZZER, MUTANTS, SEED, WORK, files_under, fuzz_reader, seed_runs
from harness import GRANULE, check, finish, granule

originals = seed_runs()

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
        fuzz_reader(reader, original, -(-MUTANTS // len(files)), WORK / f"fuzz_{reader}_{k}")
    print(f"{reader}: {time.monotonic() - started:.1f} s")


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
