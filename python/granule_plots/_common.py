"""Shared helpers of the plot scripts run by `granule plot` (Debian's /usr/bin/python3, Agg backend).

Every script takes the input file first, then --out, --frame (if the input has frames to choose), --dpi; bad input exits with code 2
and a message naming the option and its allowed range, writing nothing.  Figures have a fixed size
in inches, so a picture is (width_in × dpi) × (height_in × dpi) pixels.  Scripts that draw curves of
an analysis also take --data FILE: the numbers drawn, as JSON, so they can be checked or re-plotted.
"""
import argparse
import json
import os
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def parser(kind, description, data=False, frame=True):
    p = argparse.ArgumentParser(prog=f"granule plot {kind}", description=description)
    p.add_argument("input")
    p.add_argument("--out", required=True)
    if frame:
        p.add_argument("--frame", type=int, default=-1)
    p.add_argument("--dpi", type=int, default=100)
    if data:
        p.add_argument("--data", help="also write the numbers drawn, as JSON")
    return p


def fail(kind, message):
    """Bad input: exit code 2, nothing written."""
    print(f"granule plot {kind}: error: {message}", file=sys.stderr)
    sys.exit(2)


def resolve_index(kind, option, index, count, things):
    """`index` among `count` items (negative counts from the end), or exit 2 naming `option`."""
    if index < -count or index >= count:
        fail(kind, f"{option} {index} is out of range: the file has {count} {things} (allowed {-count} … {count - 1})")
    return index % count


def resolve_frame(kind, frame, frames):
    return resolve_index(kind, "--frame", frame, frames, "frames")


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


def _plain(value):
    """JSON-ready: arrays to lists, NaN and ±inf (not JSON) to null."""
    import numpy as np

    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple, np.ndarray)):
        return [_plain(v) for v in value]
    if isinstance(value, (float, np.floating)):
        return float(value) if np.isfinite(value) else None
    if isinstance(value, np.integer):
        return int(value)
    return value


def save(fig, out, dpi, data=None, data_path=None):
    """Write the PNG atomically (temporary name, then rename) at exactly figsize × dpi pixels, and
    the numbers drawn (`data`) as JSON to `data_path` when it is given; both are renamed only once
    both are complete."""
    written = [(f"{out}.partial", out)]
    try:
        fig.savefig(written[0][0], dpi=dpi, format="png")
        plt.close(fig)
        if data_path:
            written.append((f"{data_path}.partial", data_path))
            Path(written[1][0]).write_text(json.dumps(_plain(data)))
        for partial, final in written:
            os.replace(partial, final)
    except OSError as error:  # an output that cannot be written: exit 4, as granule's own files
        for partial, _ in written:
            Path(partial).unlink(missing_ok=True)
        print(f"granule plot: I/O error: cannot write {out}: {error}", file=sys.stderr)
        sys.exit(4)


def run(main):
    """Runs a script's main.  What h5py, NumPy or the JSON reader raise while a damaged, truncated
    or foreign input is read (a missing dataset or key, a wrong shape, an attribute of several
    values where one is expected, a value no number can be made of, a failed checksum, an array too
    large to allocate, values finite but so far apart that matplotlib cannot lay the figure out) is
    bad input: exit 2 with the reason, nothing written."""
    from numpy.linalg import LinAlgError

    kind = Path(sys.argv[0]).stem
    try:
        sys.exit(main())
    except (OSError, KeyError, ValueError, IndexError, TypeError, AttributeError, ArithmeticError, MemoryError,
            LinAlgError) as error:
        source = sys.argv[1] if len(sys.argv) > 1 else "the input"
        fail(kind, f"cannot read {source}: {type(error).__name__}: {error}")


def open_h5(kind, path):
    """An HDF5 file opened for reading, or exit 2 naming it."""
    import h5py

    try:
        return h5py.File(path, "r")
    except OSError as error:
        fail(kind, f"cannot read {path} as HDF5: {error}")


def require_format(kind, f, path, expected, producer):
    """Exit 2 unless the HDF5 file's `format` attribute is `expected` (written by `producer`)."""
    if text(f.attrs.get("format", "")) != expected:
        fail(kind, f"{path} is not a {expected} file (written by `{producer}`)")


def angle_ticks(ax, axis="x"):
    """Angle axis from 0 to 2π labelled in multiples of π/2."""
    import math

    import numpy as np

    getattr(ax, f"set_{axis}ticks")(np.arange(5) * 0.5 * math.pi, ["0", "π/2", "π", "3π/2", "2π"])


def legend(ax):
    """A small legend, only when something is labelled."""
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=7)
