"""A swept quantity from a sweep's results.csv (`granule sweep`): --y against --x, one line per
combination of the other swept keys, each point the mean over its seeds with the standard error.
When the sweep varies the restitution of 2D Lees–Edwards runs and --y is a steady-shear
temperature, the kinetic-theory curves (3.1) (Tan's fit) and (3.2) (Jenkins–Richman) of each line
are drawn beside it, computed by `granule theory steady-shear` (thesis Figs 3.1–3.3).  An 8 × 6
inch figure."""
import csv
import io
import subprocess
from collections import defaultdict

import numpy as np

from _common import fail, figure, parser, run, save

KIND = "sweep"
THEORY = {"T_fit_3.1": "(3.1) Tan's fit", "T_JR_3.2": "(3.2) Jenkins–Richman"}


def number(kind, row, key):
    try:
        return float(row[key])
    except ValueError:
        fail(kind, f"{key} = {row[key]!r} of point {row['point']} is not a number")


def theory_curve(granule, rows, x_values):
    """T(ẽ) of (3.1) and (3.2) for the line's γ, σ and ν, or None when they do not apply."""
    first = rows[0]
    if first.get("summary.boundary") != "lees-edwards" or first.get("summary.dimension") != "2" \
            or first.get("summary.polydisperse") != "false" or not granule:
        return None
    gamma = float(first["summary.shear_velocity"]) / float(first["summary.box.1"])
    e_max = min(max(x_values), 0.999)
    if min(x_values) >= e_max:
        return None
    command = [granule, "theory", "steady-shear", "--e-min", repr(min(x_values)), "--e-max", repr(e_max), "--points", "60",
               "--shear-rate", repr(abs(gamma)), "--diameter", first["summary.diameter"], "--area-fraction",
               first["summary.packing_fraction"], "--csv"]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        return None
    lines = [line for line in result.stdout.splitlines() if line and not line.startswith("#")]
    table = list(csv.DictReader(io.StringIO("\n".join(lines))))
    return {key: ([float(r["restitution"]) for r in table], [float(r[key]) for r in table]) for key in THEORY}


def main():
    p = parser(KIND, __doc__, data=True, frame=False)
    p.add_argument("--x", required=True)
    p.add_argument("--y", required=True)
    p.add_argument("--granule", help="the granule executable, for the theory curves")
    a = p.parse_args()
    try:
        with open(a.input, newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as error:
        fail(KIND, f"cannot read {a.input}: {error}")
    if not rows:
        fail(KIND, f"{a.input} has no points")
    columns = list(rows[0])
    for option, key in (("--x", a.x), ("--y", a.y)):
        if key not in columns:
            fail(KIND, f"{option} {key}: results.csv has no such column; it has {', '.join(columns)}")
    # The swept keys are the columns between "point" and "status".
    swept = columns[1:columns.index("status")]
    others = [k for k in swept if k not in (a.x, "seed")]
    done = [r for r in rows if r["status"] in ("finished", "collapsed") and r[a.y] != ""]
    if not done:
        fail(KIND, f"no point of {a.input} has finished with a value of {a.y}")
    lines = defaultdict(list)
    for r in done:
        lines[tuple(r[k] for k in others)].append(r)

    fig = figure(8, 6)
    ax = fig.add_subplot(1, 1, 1)
    data = []
    show_theory = a.x == "system.restitution" and a.y.startswith("summary.steady_shear.temperature")
    for n, (label_values, members) in enumerate(sorted(lines.items())):
        by_x = defaultdict(list)
        for r in members:
            by_x[number(KIND, r, a.x)].append(number(KIND, r, a.y))
        xs = sorted(by_x)
        means = [float(np.mean(by_x[x])) for x in xs]
        errors = [float(np.std(by_x[x], ddof=1) / np.sqrt(len(by_x[x]))) if len(by_x[x]) > 1 else 0.0 for x in xs]
        setting = ", ".join(f"{k} = {v}" for k, v in zip(others, label_values))
        label = setting or "measured"
        colour = f"C{n % 10}"
        ax.errorbar(xs, means, yerr=errors, fmt="o", color=colour, capsize=3, label=label)
        line = {"label": label, "x": xs, "mean": means, "standard_error": errors}
        curves = theory_curve(a.granule, members, xs) if show_theory else None
        for (key, name), style in zip(THEORY.items(), ("-", "--")):
            if curves:
                ax.plot(*curves[key], style, color=colour, lw=1, label=f"{name}, {setting}" if setting else name)
                line[key] = curves[key]
        data.append(line)
    ax.set(xlabel=a.x, ylabel=a.y, title=f"{a.y} against {a.x}")
    if a.y.startswith("summary.steady_shear.temperature") or a.y.startswith("summary.t"):
        ax.set_yscale("log")
    ax.legend(fontsize=7)
    save(fig, a.out, a.dpi, data, a.data)


if __name__ == "__main__":
    run(main)
