"""The measurement files that only figure scripts read (collisions.h5, spectra.h5, f1.h5, spins.h5) are
untrusted too.  Mutants of small real outputs (tests/cli/fuzz_seeds.py) meet:

- the schema check `granule plot` makes before it starts a script (io/file_schema.hpp), in one
  process (tests/fuzz/file_fuzz.cpp): GRANULE_FUZZ_MUTANTS (default 2000) mutants per file, each
  accepted or refused, never a crash, a hang or another error;
- the figure scripts themselves: GRANULE_FUZZ_FIGURE_MUTANTS (default 30) of the accepted mutants
  per file and seed run, spread evenly over them (tests/fuzz/figure_fuzz.py: each drawn in a child
  forked from one interpreter), each drawn or refused with exit 2, never a crash, a hang, an
  exception past the script's guard or a stray file (GRANULE_FUZZ_FIGURES=0 skips them: the
  sanitizer tier, whose Python is the release tier's);
- `granule plot` on a sample of the mutants, exit 0 or 2, nothing written outside its output."""
import os
import subprocess
import sys
from pathlib import Path

from fuzz_seeds import FUZZER, MUTANTS, SEED, WORK, command_line_sample, fuzz_reader, seed_runs
from harness import check, finish

FIGURES = os.environ.get("GRANULE_FUZZ_FIGURES", "1") == "1"
os.environ.setdefault("GRANULE_FUZZ_FIGURE_MUTANTS", "30")
FIGURE_FUZZ = Path(__file__).resolve().parents[1] / "fuzz" / "figure_fuzz.py"
FIGURE_OPTIONS = {"collisions": [], "spectra": [], "f1": ["--dpi", "40"], "spins": ["--dpi", "40"]}

originals = seed_runs()
for reader, source in (("collisions", "collisions.h5"), ("spectra", "spectra.h5"), ("f1", "f1.h5"), ("spins", "spins.h5")):
    runs = {name: out for name, out in originals.items() if (out / source).exists()}
    for name, out in runs.items():
        work = WORK / f"fuzz_{reader}_{name}"
        fuzz_reader(reader, out / source, -(-MUTANTS // len(runs)), work)
        if not FIGURES:
            continue
        drawn = subprocess.run([sys.executable, FIGURE_FUZZ, FUZZER, reader, out / source, str(SEED), work / "accepted.txt",
                                WORK / f"figures_{reader}_{name}", *FIGURE_OPTIONS[reader]],
                               capture_output=True, text=True, timeout=3000)
        print(drawn.stdout.strip().splitlines()[-1] if drawn.stdout.strip() else "", f"({name})")
        check(drawn.returncode == 0, f"figure fuzz of {reader} of {name}: {(drawn.stdout + drawn.stderr)[-3000:]}")


def commands(mutant_dir, out):
    return {
        "collisions.h5": [["plot", "collisions", mutant_dir / "collisions.h5", "--out", out / "collisions.png"]],
        "spectra.h5": [["plot", "spectra", mutant_dir / "spectra.h5", "--out", out / "spectra.png"]],
        "f1.h5": [["plot", "f1", mutant_dir / "f1.h5", "--out", out / "f1.png"]],
        "spins.h5": [["plot", "spins", mutant_dir / "spins.h5", "--out", out / "spins.png"]],
    }


command_line_sample(originals, ("collisions.h5", "spectra.h5", "f1.h5", "spins.h5"), commands)
finish()
