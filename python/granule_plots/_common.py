"""Shared helpers of the plot scripts run by `granule plot` (Debian's /usr/bin/python3, Agg backend).

Every script takes the input file first, then --out, --frame, --dpi; bad input exits with code 2
and a message naming the option and its allowed range, writing nothing.  Figures have a fixed size
in inches, so a picture is (width_in × dpi) × (height_in × dpi) pixels.
"""
import argparse
import json
import os
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def parser(kind, description):
    p = argparse.ArgumentParser(prog=f"granule plot {kind}", description=description)
    p.add_argument("input")
    p.add_argument("--out", required=True)
    p.add_argument("--frame", type=int, default=-1)
    p.add_argument("--dpi", type=int, default=100)
    return p


def fail(kind, message):
    """Bad input: exit code 2, nothing written."""
    print(f"granule plot {kind}: error: {message}", file=sys.stderr)
    sys.exit(2)


def resolve_frame(kind, frame, frames):
    if frame < -frames or frame >= frames:
        fail(kind, f"--frame {frame} is out of range: the file has {frames} frames (allowed {-frames} … {frames - 1})")
    return frame % frames


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def run_summary(input_path):
    """summary.json beside the input (restitution, boundary, ...), or {} if there is none."""
    path = Path(input_path).with_name("summary.json")
    try:
        return json.loads(path.read_text())
    except (OSError, ValueError):
        return {}


def figure(width_in, height_in):
    return plt.figure(figsize=(width_in, height_in), layout="constrained")


def save(fig, out, dpi):
    """Write the PNG atomically (temporary name, then rename) at exactly figsize × dpi pixels."""
    partial = f"{out}.partial"
    fig.savefig(partial, dpi=dpi, format="png")
    plt.close(fig)
    os.replace(partial, out)


def open_h5(kind, path):
    """An HDF5 file opened for reading, or exit 2 naming it."""
    import h5py

    try:
        return h5py.File(path, "r")
    except OSError as error:
        fail(kind, f"cannot read {path} as HDF5: {error}")
