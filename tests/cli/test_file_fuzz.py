"""Every file Granule reads is untrusted.  Small real outputs (tests/cli/fuzz_seeds.py) are mutated
— attributes and datasets deleted or given other shapes, counts, types or values (NaN, ±inf,
negative, huge), bits flipped, bytes zeroed, files cut short — and given to each reader of the
files Granule reads itself:

- in one process (tests/fuzz/file_fuzz.cpp): GRANULE_FUZZ_MUTANTS (default 2000) mutants per reader
  (snapshots.h5, fields.h5, and checkpoint.h5 on resume, half of those edits with their digests
  recomputed as a hostile user would), each read cleanly or refused, never a crash, a hang or
  another error;
- through the command line: a sample of the mutants (snapshots.h5, checkpoint.h5, and fields.h5,
  which figure scripts also read with h5py) given to `granule analyze`, `plot` and `run --resume`,
  each exiting with 0 or 2 within a time limit and writing nothing outside its output.

The measurement files only figure scripts read are fuzzed by test_measurement_fuzz.py, the text files
(sweep records and summaries, timeseries.csv) by test_text_fuzz.py."""
from fuzz_seeds import MUTANTS, WORK, command_line_sample, fuzz_reader, seed_runs
from harness import finish

originals = seed_runs()
per_run = -(-MUTANTS // len(originals))
for reader, source in (("snapshots", "snapshots.h5"), ("fields", "fields.h5"), ("resume", "")):
    for name, out in originals.items():
        fuzz_reader(reader, out / source if source else out, per_run, WORK / f"fuzz_{reader}_{name}")


def commands(mutant_dir, out):
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
    }


command_line_sample(originals, ("snapshots.h5", "checkpoint.h5", "fields.h5"), commands)
finish()
