"""Phase-space scatter plots of one snapshot (thesis Figs 2.1, 2.11, 2.13): each point is one disk,
x and y against v_x and v_y, v_x against v_y, and x against y.  A 12 × 8 inch figure of six panels."""
import numpy as np

from _common import fail, figure, open_h5, parser, resolve_frame, run, save

KIND = "phase"
PANELS = [(0, 2, "x", "v_x"), (1, 2, "y", "v_x"), (2, 3, "v_x", "v_y"), (0, 3, "x", "v_y"), (1, 3, "y", "v_y"), (0, 1, "x", "y")]


def main():
    p = parser(KIND, __doc__)
    p.add_argument("--max-points", type=int, default=200000)
    a = p.parse_args()
    if a.max_points < 100:
        fail(KIND, f"--max-points {a.max_points} is below 100")
    with open_h5(KIND, a.input) as f:
        if "positions" not in f:
            fail(KIND, f"{a.input} is not a snapshot file (no /positions)")
        k = resolve_frame(KIND, a.frame, len(f["time"]))
        columns = np.hstack([f["positions"][k], f["velocities"][k]])
        t, c = float(f["time"][k]), float(f["collisions_per_particle"][k])
    if len(columns) > a.max_points:  # a fixed random subset keeps huge systems readable
        columns = columns[np.random.default_rng(0).choice(len(columns), a.max_points, replace=False)]
    fig = figure(12.0, 8.0)
    size = max(0.2, min(4.0, 4000.0 / len(columns)))
    for n, (i, j, xlabel, ylabel) in enumerate(PANELS):
        ax = fig.add_subplot(2, 3, n + 1)
        ax.scatter(columns[:, i], columns[:, j], s=size, c="k", linewidths=0, rasterized=True)
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
    fig.suptitle(f"{len(columns)} disks at t = {t:.4g}, c = {c:.4g}", fontsize=10)
    save(fig, a.out, a.dpi)


if __name__ == "__main__":
    run(main)
