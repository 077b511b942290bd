"""Shaded maps of coarse-grained fields from fields.h5 (thesis Figs 2.4, 2.12-2.18, 3.5-3.14):
density, temperature, kinetic and collisional pressure by default, grey shades lighter for higher
values as in the thesis.  Two columns of 5 × 4.5 inch panels.

A single frame of cells of ~20 disks is dominated by counting noise (a cell's density fluctuates by
~1/√20 ≈ 22 %), which hides stripes of a few percent.  Two remedies, both optional:
--average-frames K averages the K frames ending at --frame, in a Lees–Edwards run in the frame
moving with the shear: each earlier frame is first advected by the mean flow u(y) = γ (y − L_y/2) to
the time of the last one (row y shifted along x by u(y) Δt, periodic linear interpolation), so that
structures carried by the flow stay in place instead of being smeared along x; --smooth S convolves
each map with a Gaussian of standard deviation S cells (truncated at 4 S, across the periodic and
Lees–Edwards images: the kernel of _isosurface.smooth)."""
import math

import numpy as np

from _common import fail, figure, open_h5, parser, resolve_frame, run, save, text
from _isosurface import _shifted_rows, smooth

KIND = "fields"
DEFAULT = ["density", "temperature", "pressure_kinetic", "pressure_collisional"]
TITLES = {
    "density": "density ρ (disks per unit area)",
    "temperature": "temperature T (1.3)",
    "pressure_kinetic": "kinetic pressure ½ Tr τ⁽ᵏ⁾ (1.4)",
    "pressure_collisional": "collisional pressure ½ Tr τ⁽ᶜ⁾ (1.6)",
    "pressure_total": "pressure ½ Tr τ",
    "vorticity": "vorticity ω",
    "velocity_x": "V_x",
    "velocity_y": "V_y",
}


def arguments():
    p = parser(KIND, __doc__)
    p.add_argument("--group", default="average")
    p.add_argument("--quantities", nargs="+", default=None)
    p.add_argument("--colormap", default="gray")
    p.add_argument("--average-frames", type=int, default=1, help="average this many frames ending at --frame")
    p.add_argument("--smooth", type=float, default=0.0, help="Gaussian smoothing, standard deviation in cells (0: none)")
    a = p.parse_args()
    if a.group not in ("average", "instant"):
        fail(KIND, f"--group {a.group} is not one of average, instant")
    if not (0.0 <= a.smooth <= 16.0):
        fail(KIND, f"--smooth {a.smooth} is outside [0, 16] cells")
    import matplotlib

    if a.colormap not in matplotlib.colormaps:
        fail(KIND, f"--colormap {a.colormap} is not a matplotlib colormap (e.g. gray, viridis, inferno)")
    return a


def quantities_of(a, group):
    """The maps asked for; by default those of DEFAULT the group has (the collisional stress needs an
    interval, so /instant has no collisional pressure)."""
    if a.quantities is None:
        return [q for q in DEFAULT if q in group]
    missing = [q for q in a.quantities if q not in group]
    if missing:
        fail(KIND, f"--quantities {' '.join(missing)}: not in /{a.group} (available: {', '.join(sorted(group))})")
    return a.quantities


def shear_advected(rows, shift_per_row):
    """rows[iy, ix] with row iy moved along x by shift_per_row[iy] cells (periodic)."""
    return np.stack([_shifted_rows(row, s) for row, s in zip(rows, shift_per_row)])


def averaged_map(f, group, name, k, a):
    """The map `name` of frame k, averaged over the --average-frames frames ending at k in the frame
    moving with the shear (Lees–Edwards runs), then smoothed; the image offset of frame k in cells."""
    first = k - a.average_frames + 1
    if a.average_frames < 1 or first < 0:
        fail(KIND, f"--average-frames {a.average_frames} is outside [1, {k + 1}] for frame {k}")
    lx, ly = float(f.attrs["length_x"]), float(f.attrs["length_y"])
    nx, ny = int(f.attrs["nx"]), int(f.attrs["ny"])
    lees_edwards = text(f.attrs.get("boundary", "periodic")) == "lees-edwards"
    y = (np.arange(ny) + 0.5) * ly / ny
    t = f["frames/t"]
    total = 0.0
    for frame in range(first, k + 1):
        values = np.asarray(group[name][frame], dtype=np.float64)
        if lees_edwards and frame != k:
            shear_rate = float(f["frames/shear_velocity"][frame]) / ly if "frames/shear_velocity" in f \
                else float(f.attrs["shear_velocity"]) / ly
            values = shear_advected(values, shear_rate * (y - 0.5 * ly) * (float(t[k]) - float(t[frame])) / (lx / nx))
        total = total + values
    mean = total / a.average_frames
    offset = float(f["frames/shear_offset"][k]) / (lx / nx) if lees_edwards and "frames/shear_offset" in f else 0.0
    # V_x in the lab frame jumps by ±U across the y images; the other fields are continuous.
    velocity = 0.0
    if name == "velocity_x" and lees_edwards and int(f.attrs.get("subtract_shear_profile", 0)) == 0:
        velocity = float(f["frames/shear_velocity"][k]) if "frames/shear_velocity" in f else float(f.attrs["shear_velocity"])
    return smooth(mean[np.newaxis], a.smooth, cells_offset=offset, image_velocity=velocity)[0]


def main():
    a = arguments()
    with open_h5(KIND, a.input) as f:
        if "frames" not in f or a.group not in f:
            fail(KIND, f"{a.input} is not a fields file (no /frames or /{a.group})")
        group = f[a.group]
        quantities = quantities_of(a, group)
        k = resolve_frame(KIND, a.frame, len(f["frames/t"]))
        lx, ly = float(f.attrs["length_x"]), float(f.attrs["length_y"])
        t, c = float(f["frames/t"][k]), float(f["frames/c"][k])
        when = f"t = {t:.4g}, c = {c:.4g}"
        if a.group == "average":
            when = f"averaged over t ∈ [{float(f['frames/t_start'][k]):.4g}, {t:.4g}] (c ∈ [{float(f['frames/c_start'][k]):.4g}, {c:.4g}])"
        if a.average_frames > 1:
            when += f"\nmean of {a.average_frames} frames from c = {float(f['frames/c'][max(0, k - a.average_frames + 1)]):.4g}"
            if text(f.attrs.get("boundary", "periodic")) == "lees-edwards":
                when += " in the frame moving with the shear"
        if a.smooth > 0:
            when += f"{'; ' if a.average_frames > 1 else chr(10)}Gaussian smoothing σ = {a.smooth:g} cells"
        columns = min(2, len(quantities))
        rows = math.ceil(len(quantities) / columns)
        fig = figure(5.0 * columns, 4.5 * rows)
        for n, name in enumerate(quantities):
            ax = fig.add_subplot(rows, columns, n + 1)
            image = ax.imshow(averaged_map(f, group, name, k, a), origin="lower", extent=[0, lx, 0, ly], cmap=a.colormap,
                              interpolation="nearest", aspect="equal")
            fig.colorbar(image, ax=ax, shrink=0.85)
            ax.set_title(TITLES.get(name, name), fontsize=10)
            ax.set_xlabel("x")
            ax.set_ylabel("y")
        boundary = text(f.attrs.get("boundary", "periodic"))
        fig.suptitle(f"N = {int(f.attrs['particles'])}, ẽ = {float(f.attrs['restitution']):g}, {boundary}; "
                     f"{f.attrs['nx']} × {f.attrs['ny']} cells; {when}", fontsize=10)
    save(fig, a.out, a.dpi)


if __name__ == "__main__":
    run(main)
