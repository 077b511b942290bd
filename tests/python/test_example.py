"""The worked example runs, and its homogeneous stage follows Haff's law."""
import os
import subprocess
import sys
from pathlib import Path

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "python" / "free_cooling.py"


def test_free_cooling_example_follows_haff_early_on(tmp_path):
    figure = tmp_path / "free_cooling.png"
    result = subprocess.run([sys.executable, EXAMPLE, "--figure", figure], capture_output=True, text=True,
                            timeout=120, env=os.environ)
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    row = next(line.split() for line in lines if line.split()[:1] == ["10"])  # the row at c = 10
    assert abs(float(row[2]) - 1) < 0.05 and abs(float(row[3]) - 1) < 0.05
    assert figure.stat().st_size > 10000
