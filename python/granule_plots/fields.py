"""Shaded maps of coarse-grained fields from fields.h5 (thesis Figs 2.4, 2.12-2.18, 3.5-3.14):
density, temperature, kinetic and collisional pressure by default, grey shades lighter for higher
values as in the thesis.  Two columns of 5 × 4.5 inch panels."""
import math


from _common import open_h5, figure, fail, parser, resolve_frame, save, text

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


def main():
    p = parser(KIND, __doc__)
    p.add_argument("--group", default="average")
    p.add_argument("--quantities", nargs="+", default=DEFAULT)
    p.add_argument("--colormap", default="gray")
    a = p.parse_args()
    if a.group not in ("average", "instant"):
        fail(KIND, f"--group {a.group} is not one of average, instant")
    import matplotlib

    if a.colormap not in matplotlib.colormaps:
        fail(KIND, f"--colormap {a.colormap} is not a matplotlib colormap (e.g. gray, viridis, inferno)")
    with open_h5(KIND, a.input) as f:
        if "frames" not in f or a.group not in f:
            fail(KIND, f"{a.input} is not a fields file (no /frames or /{a.group})")
        group = f[a.group]
        missing = [q for q in a.quantities if q not in group]
        if missing:
            fail(KIND, f"--quantities {' '.join(missing)}: not in /{a.group} (available: {', '.join(sorted(group))})")
        k = resolve_frame(KIND, a.frame, len(f["frames/t"]))
        lx, ly = float(f.attrs["length_x"]), float(f.attrs["length_y"])
        t, c = float(f["frames/t"][k]), float(f["frames/c"][k])
        when = f"t = {t:.4g}, c = {c:.4g}"
        if a.group == "average":
            when = f"averaged over t ∈ [{float(f['frames/t_start'][k]):.4g}, {t:.4g}] (c ∈ [{float(f['frames/c_start'][k]):.4g}, {c:.4g}])"
        columns = min(2, len(a.quantities))
        rows = math.ceil(len(a.quantities) / columns)
        fig = figure(5.0 * columns, 4.5 * rows)
        for n, name in enumerate(a.quantities):
            ax = fig.add_subplot(rows, columns, n + 1)
            image = ax.imshow(group[name][k], origin="lower", extent=[0, lx, 0, ly], cmap=a.colormap,
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
    main()
