"""Shared by the end-to-end tests (run as `python3 test_x.py GRANULE WORKDIR`): a fresh work
directory, the granule command, checks that collect failures, and the closing summary line
"N passed, M failed" with a non-zero exit status when anything failed."""
import shutil
import subprocess
import sys
from pathlib import Path

GRANULE, WORK = sys.argv[1], Path(sys.argv[2])
shutil.rmtree(WORK, ignore_errors=True)
WORK.mkdir(parents=True)
_counts = {"checks": 0}
failures = []


def check(condition, message):
    _counts["checks"] += 1
    if not condition:
        failures.append(message)


def granule(*args):
    return subprocess.run([GRANULE, *map(str, args)], capture_output=True, text=True, timeout=300)


def finish():
    for message in failures:
        print("FAIL:", message)
    print(f"{_counts['checks'] - len(failures)} passed, {len(failures)} failed")
    sys.exit(1 if failures else 0)
