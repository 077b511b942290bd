"""No call of the granule module takes the interpreter down: thousands of seeded hostile calls
(tests/python/api_fuzzer.py) — configurations of every type with NaN, huge values, cycles and
NumPy scalars, run() targets, four threads on one Simulation, every analysis and theory function
with bad arrays, paths of every kind — each return or raise a Python exception.  Each part runs in
its own interpreter, so a crash is seen (the process dies) and named by the last call its journal
holds.  GRANULE_FUZZ_SEED chooses another seed."""
import collections
import json
import os
import subprocess
import sys
from pathlib import Path

FUZZER = Path(__file__).with_name("api_fuzzer.py")
PARTS = ("config", "run", "threads", "analysis", "theory", "paths")


def run_part(part, seed, tmp_path):
    journal = tmp_path / f"{part}.journal"
    result = subprocess.run([sys.executable, FUZZER, "--part", part, "--seed", str(seed), "--journal", journal,
                             "--scratch", tmp_path / part], capture_output=True, text=True, timeout=240,
                            env=os.environ)
    if result.returncode != 0 or not result.stdout.strip():
        last = journal.read_text(errors="replace").splitlines()[-1:] if journal.exists() else []
        return None, f"{part}: exit status {result.returncode}, last call {last}, stderr {result.stderr[-1500:]}"
    return json.loads(result.stdout.strip().splitlines()[-1]), None


def test_no_call_crashes_the_interpreter(tmp_path, capsys):
    seed = int(os.environ.get("GRANULE_FUZZ_SEED", "1"))
    totals, crashes, bad = collections.Counter(), [], []
    for part in PARTS:
        report, crash = run_part(part, seed, tmp_path)
        if crash:
            crashes.append(crash)
            continue
        totals.update(report["counts"])
        bad += report["bad"]
    calls = sum(totals.values())
    raised = ", ".join(f"{kind}={count}" for kind, count in sorted(totals.items()) if kind != "ok")
    line = (f"fuzz_api (seed {seed}): calls={calls} succeeded={totals['ok']} raised={calls - totals['ok']} "
            f"({raised}) crashes={len(crashes)}")
    with capsys.disabled():
        print(f"\n{line}")
    assert not crashes, crashes
    assert not bad, f"SystemError (the C API misused): {bad}"
    assert calls >= 2000, line
    # Each kind of refusal the module promises was reached, and the calls that may succeed did.
    for kind in ("ok", "ValueError", "TypeError", "OverflowError", "MemoryError", "RuntimeError", "ConfigError",
                 "FileNotFoundError", "IsADirectoryError"):
        assert totals[kind] > 0, (kind, line)
