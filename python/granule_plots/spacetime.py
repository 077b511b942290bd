"""Space-time pictures of the streamwise profiles (thesis Figs 4.7-4.8, §4.3): the local area
fraction ν(y, t) = πσ²ρ/4, V_x(y, t) and T(y, t) as shaded panels, time across and y up, so that
dense streamwise layers converging into a central plug read as bands that move together.  Above
them, when the snapshots store it, the protocol's image velocity U(t).  Reads the granule-spacetime
HDF5 file that `granule plot spacetime` writes (docs/plots.md).  A 10 × 9 inch figure."""
import numpy as np

from _common import fail, figure, open_h5, parser, require_format, run, save, text

KIND = "spacetime"
SOURCES = {
    "fields/instant": "streamwise averages of the instantaneous fields (fields.h5)",
    "fields/average": "streamwise averages of the interval-averaged fields (fields.h5)",
    "snapshots": "rows binned from the snapshots",
}


def edges(centres, low=None, high=None):
    """Cell edges around sorted centres: midpoints, the ends half a step out (or at low/high)."""
    centres = np.asarray(centres, dtype=float)
    if len(centres) == 1:
        half = 0.5 * (high - low) if low is not None else max(abs(centres[0]) * 0.01, 0.5)
        return np.array([centres[0] - half, centres[0] + half])
    middle = 0.5 * (centres[1:] + centres[:-1])
    first = low if low is not None else centres[0] - (middle[0] - centres[0])
    last = high if high is not None else centres[-1] + (centres[-1] - middle[-1])
    return np.concatenate([[first], middle, [last]])


def extrapolated(xp, fp):
    """x ↦ f(x), piecewise linear through (xp, fp) and continued by the end segments, so that it
    stays invertible over the whole axis (the c axis above the time axis)."""
    def f(x):
        x = np.asarray(x, dtype=float)
        low = fp[0] + (x - xp[0]) * (fp[1] - fp[0]) / (xp[1] - xp[0])
        high = fp[-1] + (x - xp[-1]) * (fp[-1] - fp[-2]) / (xp[-1] - xp[-2])
        return np.where(x < xp[0], low, np.where(x > xp[-1], high, np.interp(x, xp, fp)))
    return f


def panel(fig, ax, cax, t_edges, y_edges, values, cmap, norm, label):
    import matplotlib
    from matplotlib.colors import LogNorm
    from matplotlib.ticker import FuncFormatter, NullFormatter

    colors = matplotlib.colormaps[cmap].copy()
    colors.set_bad("0.85")  # empty rows
    mesh = ax.pcolormesh(t_edges, y_edges, values.T, cmap=colors, norm=norm, shading="flat")
    bar = fig.colorbar(mesh, cax=cax, label=label)
    if isinstance(norm, LogNorm):  # plain numbers (0.1, not 10⁻¹); minor ticks labelled only within a decade
        plain = FuncFormatter(lambda v, _: f"{v:g}")
        bar.ax.yaxis.set_major_formatter(plain)
        bar.ax.yaxis.set_minor_formatter(plain if norm.vmax < 10.0 * norm.vmin else NullFormatter())
    ax.set_ylabel("y")


def main():
    a = parser(KIND, __doc__, frame=False).parse_args()
    import matplotlib.colors as mcolors

    with open_h5(KIND, a.input) as f:
        require_format(KIND, f, a.input, "granule-spacetime", "granule plot spacetime")
        t, c, y = f["t"][:], f["c"][:], f["y"][:]
        density, vx, temperature = f["density"][:], f["velocity_x"][:], f["temperature"][:]
        ly, sigma = float(f.attrs["length_y"]), float(f.attrs["diameter"])
        source, boundary = text(f.attrs["source"]), text(f.attrs["boundary"])
        relative = int(f.attrs["relative"]) == 1
        protocol = {name: f[f"protocol/{name}"][:] for name in ("t", "shear_velocity")} if "protocol" in f else None
        title = (f"N = {int(f.attrs['particles'])}, ẽ = {float(f.attrs['restitution']):g}, {boundary}; "
                 f"{SOURCES.get(source, source)}, {len(y)} rows")
    if len(t) == 0:
        fail(KIND, f"{a.input} has no frames")
    empty = density <= 0.0
    nu = 0.25 * np.pi * sigma**2 * density
    vx = np.ma.masked_where(empty, vx)
    temperature = np.ma.masked_where(empty | (temperature <= 0.0), temperature)
    t_edges, y_edges = edges(t), edges(y, 0.0, ly)

    fig = figure(10.0, 9.0)
    rows = [0.7, 2.6, 2.6, 2.6] if protocol is not None else [2.6, 2.6, 2.6]
    grid = fig.add_gridspec(len(rows), 2, height_ratios=rows, width_ratios=[1.0, 0.025])
    axes = [fig.add_subplot(grid[k, 0]) for k in range(len(rows))]
    for ax in axes[1:]:
        ax.sharex(axes[0])
    panels = axes[1:] if protocol is not None else axes
    if protocol is not None:
        strip = axes[0]
        strip.plot(protocol["t"], protocol["shear_velocity"], "k.-", lw=1, ms=3)
        strip.set_ylabel("U(t)")
        strip.text(0.005, 0.92, "(A) image velocity U of the shear protocol", transform=strip.transAxes, fontsize=9,
                   va="top")
        fig.add_subplot(grid[0, 1]).axis("off")
    first = ord("A") + (1 if protocol is not None else 0)
    v_max = float(np.max(np.abs(vx))) if vx.count() else 1.0
    v_label = "V_x − u(y)" if relative else "V_x"
    v_name = "streamwise velocity V_x(y, t) − u(y)" if relative else "streamwise velocity V_x(y, t)"
    specs = [
        (nu, "viridis", mcolors.Normalize(vmin=0.0, vmax=max(float(nu.max()), 1e-300)),
         "ν = πσ²ρ/4", "local area fraction ν(y, t)"),
        (vx, "RdBu_r", mcolors.Normalize(vmin=-v_max, vmax=v_max or 1.0),
         f"{v_label} (length/time)", v_name),
        (temperature, "inferno", mcolors.LogNorm() if temperature.count() else None,
         "T (length²/time², log scale)", "temperature T(y, t) = ½⟨(v − V)²⟩ (1.3)"),
    ]
    for n, (ax, (values, cmap, norm, label, name)) in enumerate(zip(panels, specs)):
        panel(fig, ax, fig.add_subplot(grid[len(rows) - 3 + n, 1]), t_edges, y_edges, values, cmap, norm, label)
        ax.set_title(f"({chr(first + n)}) {name}", fontsize=9, loc="left")
        ax.set_ylim(0.0, ly)
    for ax in axes[:-1]:
        ax.tick_params(labelbottom=False)
    axes[-1].set_xlabel("t")
    axes[0].set_xlim(t_edges[0], t_edges[-1])
    if len(t) > 1 and np.all(np.diff(t) > 0) and np.all(np.diff(c) > 0):
        t_to_c = extrapolated(t, c)
        top = axes[0].secondary_xaxis("top", functions=(t_to_c, extrapolated(c, t)))
        # c grows fastest while the gas is hot: ticks at the c of the time ticks (2 digits), not evenly in c.
        low, high = axes[0].get_xlim()
        ticks = [x for x in axes[-1].get_xticks() if low <= x <= high]
        top.set_xticks(sorted({float(f"{float(t_to_c(x)):.2g}") for x in ticks}))
        top.set_xlabel("c (collisions per particle)")
    fig.suptitle(title, fontsize=10)
    save(fig, a.out, a.dpi)


if __name__ == "__main__":
    run(main)
