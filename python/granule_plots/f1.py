"""The single-particle velocity distribution from the f1.h5 of `granule analyze f1` (docs/f1.md,
thesis Chapter 5).  Rows 1-2 draw one window (--window K, the group windows/NNN in file order):
(A) h(v, θ) against v at θ = nπ/4 with h* (Fig 5.1); (B) φ(v) with φ* (5.18, 5.20); (C) J(v) with its
fit (5.22, Fig 5.3); (D) ψ(θ, v) with ψ* (5.21) at v ≈ (½, 1, 3/2, 2, 3)√(2T) (Fig 5.2); (E) b⁽⁰⁾,
√(2T) b⁽¹⁾, 2T b⁽²⁾ against θ: the fits (5.27) as points, the sine series (5.29) of the Appendix B
table as curves, the Jenkins-Richman coefficients dotted (Fig 5.4); (F) −log f** against v at
θ = 0, π/4, π/2, 3π/4 from the table, and −log f*, −log f** at the profile angle from the file
(the twice-fitted form (5.28)); (G, H) f*, f** and the Jenkins-Richman anisotropic Maxwellian
(5.32)-(5.34) against v at the profile angle and against θ at the profile speed (Figs 5.10, 5.11).
Row 3 draws every window of the file against its temperature, one marker per density window:
(I) b₀⁽⁰⁾, √(2T) b₀⁽¹⁾, 2T b₀⁽²⁾ (Figs 5.5, 5.8); (J) the phases ε₂ⱼ (Fig 5.6); (K) Tr τ, Tr τ*,
Tr τ** per particle (5.30, 5.31, Fig 5.7); (L) (b₀⁽¹⁾)²/b₀⁽²⁾ (Fig 5.9).  Error bars of row 3 are
percentile bootstrap intervals: the 16th to 84th percentile of the file's converged replicates (±1 sd
for a Gaussian spread, but not stretched by one wild replicate), or ±1 bootstrap sd for files without
the replicates.  Each panel's y range is set by robust quantiles: the 5th percentile of the lower ends
to the 95th of the upper ends, widened to hold every estimate; a bar reaching beyond it is clipped at
the edge and marked there with an open triangle.  Twelve 4 × 3.6 inch panels, three rows of four."""
import math

import numpy as np

from _common import angle_ticks, figure, legend, open_h5, parser, require_format, resolve_index, run, save, text

KIND = "f1"
PANEL_WIDTH, PANEL_HEIGHT = 4.0, 3.6
PSI_SPEEDS = (0.5, 1.0, 1.5, 2.0, 3.0)        # in units of √(2T): the v of panel (D), as Fig 5.2
NEGLOG_ANGLES = (0.0, 0.25, 0.5, 0.75)        # θ/π of panel (F)
COEFFICIENT_LABELS = ("b⁽⁰⁾", "√(2T) b⁽¹⁾", "2T b⁽²⁾")
FINE_ANGLES = np.linspace(0.0, 2.0 * math.pi, 721)


def series(table, theta):
    """b⁽ⁱ⁾(θ) of (5.29) from the Appendix B table (rows j = 0 … 6 of (ε₂ⱼ, b₂ⱼ⁽⁰⁾, b₂ⱼ⁽¹⁾, b₂ⱼ⁽²⁾)):
    an array (len(θ), 3) in the snapshots' units."""
    theta = np.asarray(theta, dtype=float)
    b = np.tile(table[0, 1:], (len(theta), 1))
    for j in range(1, len(table)):
        b += np.sin(2 * j * (theta[:, None] + table[j, 0])) * table[j, 1:]
    return b


def in_pi(angle):
    """An angle as a multiple of π for labels: 0, π/4 → "0.25π", π → "π"."""
    multiple = f"{angle / math.pi:.3g}"
    return {"0": "0", "1": "π"}.get(multiple, multiple + "π")


PERCENTILES = (16.0, 84.0)  # the central 68 % of the replicates: ±1 sd for a Gaussian spread
ROBUST_QUANTILES = (5.0, 95.0)  # of the interval ends: the y range of a row-3 panel


def interval(estimate, replicates, sd):
    """(lower, upper) of the percentile bootstrap interval, or estimate ∓ sd without replicates."""
    if replicates is None or len(replicates) < 2:
        return estimate - sd, estimate + sd
    low, high = np.nanpercentile(replicates, PERCENTILES, axis=0)
    return low, high


def draw_interval(ax, x, y, bounds, **style):
    """A point with its interval as an error bar (clipped later by robust_range)."""
    low, high = bounds
    ax.errorbar(x, y, [[max(0.0, y - low)], [max(0.0, high - y)]], capsize=2, ms=4, **style)
    ax._intervals = getattr(ax, "_intervals", []) + [(x, y, low, high, style.get("color", "k"))]


def robust_range(ax):
    """Sets the y range from robust quantiles of the interval ends, holding every estimate, and marks
    the bars that reach beyond it with open triangles at the edge; returns how many were clipped."""
    intervals = [i for i in getattr(ax, "_intervals", []) if np.isfinite(i[1])]
    if not intervals:
        return 0
    ys = np.array([i[1] for i in intervals])
    lows = np.array([i[2] for i in intervals if np.isfinite(i[2])] or [ys.min()])
    highs = np.array([i[3] for i in intervals if np.isfinite(i[3])] or [ys.max()])
    bottom = min(np.percentile(lows, ROBUST_QUANTILES[0]), ys.min())
    top = max(np.percentile(highs, ROBUST_QUANTILES[1]), ys.max())
    pad = 0.05 * (top - bottom) if top > bottom else 0.05 * max(1.0, abs(top))
    bottom, top = bottom - pad, top + pad
    ax.set_ylim(bottom, top)
    clipped = 0
    for x, _, low, high, color in intervals:
        for end, edge, marker in ((low, bottom, "v"), (high, top, "^")):
            if np.isfinite(end) and (end < edge if marker == "v" else end > edge):
                ax.plot(x, edge, marker, mfc="none", mec=color, ms=6, clip_on=False)
                clipped += 1
    return clipped


def dimensionless(b, s):
    """(b⁽⁰⁾, s b⁽¹⁾, s² b⁽²⁾), s = √(2T): the units of Figs 5.4, 5.5, where an elastic gas gives (log 2πT, 0, 1)."""
    return np.asarray(b) * np.array([1.0, s, s * s])


def draw_cumulative(ax_h, ax_phi, ax_j, ax_psi, g):
    v, angles = g["speed_edges"][:], g["angle_edges"][:]
    h, h_fit = g["h"][:], g["h_fit"][:]
    eighth = (len(angles) - 1) // 8  # angle bins are a multiple of 8: θ = nπ/4 are edges
    curves = []
    for n in range(1, 9):
        column = n * eighth
        points = ax_h.plot(v, h[:, column], "o", ms=2)
        ax_h.plot(v, h_fit[:, column], "-", lw=0.8, color=points[0].get_color())
        curves.append({"n": n, "theta": angles[column], "h": h[:, column], "h_fit": h_fit[:, column]})
    ax_h.plot([], [], "ko", ms=2, label="h (5.11), θ = π/4 … 2π")
    ax_h.plot([], [], "k-", lw=0.8, label="h* (5.25)")
    ax_h.set(xlabel="v", ylabel="h(v, θ)", title="(A) cumulative h(v, θ = nπ/4)")

    phi, phi_fit, j, j_fit = g["phi"][:], g["phi_fit"][:], g["J"][:], g["J_fit"][:]
    ax_phi.plot(v, phi, "o", ms=2, label="φ = h(v, 2π)/2π (5.18)")
    ax_phi.plot(v, phi_fit, "-", lw=1, label="φ* = (1 − exp(−J))/2π (5.20)")
    ax_phi.axhline(1.0 / (2.0 * math.pi), color="grey", ls=":", lw=0.8, label="1/2π")
    ax_phi.set(xlabel="v", ylabel="φ(v)", title="(B) speed part φ(v)")
    ax_j.plot(v, j, "o", ms=2, label="J = −log(1 − 2πφ)")
    ax_j.plot(v, j_fit, "-", lw=1, label="J = Σ aₘ vᵐ, m = 2 … 4 (5.22)")
    ax_j.set(xlabel="v", ylabel="J(v)", title="(C) J(v) and its fit")

    psi, psi_fit, theta = g["psi"][:], g["psi_fit"][:], angles[:-1]
    s = float(g.attrs["speed_scale"])
    rows = sorted({int(np.argmin(np.abs(v - u * s))) for u in PSI_SPEEDS if u * s <= v[-1]})
    psi_curves = []
    for k in rows:
        points = ax_psi.plot(theta, psi[k], "o", ms=2, label=f"v = {v[k]:.3g}")
        ax_psi.plot(theta, psi_fit[k], "-", lw=0.8, color=points[0].get_color())
        psi_curves.append({"v": v[k], "psi": psi[k], "psi_fit": psi_fit[k]})
    ax_psi.plot([], [], "k-", lw=0.8, label="ψ* (5.21)")
    angle_ticks(ax_psi)
    ax_psi.set(xlabel="θ", ylabel="ψ(θ, v)", title="(D) periodic part ψ (5.19)")
    for ax in (ax_h, ax_phi, ax_j, ax_psi):
        legend(ax)
    return {"v": v, "h_at_n_pi_over_4": curves, "phi": phi, "phi_fit": phi_fit, "J": j, "J_fit": j_fit,
            "psi_theta": theta, "psi": psi_curves}


def draw_coefficients(ax, g, table, s):
    theta = g["theta"][:]
    fitted = dimensionless(g["b"][:], s)
    drawn = dimensionless(series(table, FINE_ANGLES), s)
    b0, b2_mean, b2_amplitude, phase = g["jenkins_richman"][:]
    jr_b2 = b2_mean + b2_amplitude * np.sin(2.0 * (FINE_ANGLES + phase))
    for i, label in enumerate(COEFFICIENT_LABELS):
        points = ax.plot(theta, fitted[:, i], "o", ms=2, label=f"{label} (5.27)")
        ax.plot(FINE_ANGLES, drawn[:, i], "-", lw=1, color=points[0].get_color())
    ax.plot([], [], "k-", lw=1, label="sine series (5.29)")
    ax.axhline(b0, color="C0", ls=":", lw=1)
    ax.axhline(0.0, color="C1", ls=":", lw=1)
    ax.plot(FINE_ANGLES, s * s * jr_b2, ":", color="C2", lw=1)
    ax.plot([], [], "k:", lw=1, label="Jenkins–Richman (5.32)")
    angle_ticks(ax)
    ax.set(xlabel="θ", title="(E) b⁽ⁱ⁾(θ), dimensionless")
    legend(ax)
    return {"theta": theta, "b": fitted, "series_theta": FINE_ANGLES, "series": drawn,
            "jenkins_richman": {"b0": b0, "twoT_b2": s * s * jr_b2}}


def draw_neglog(ax, g, table):
    v = np.linspace(0.0, float(g.attrs["fit_speed_max"]), 201)
    curves = []
    for fraction in NEGLOG_ANGLES:
        b = series(table, [fraction * math.pi])[0]
        neglog = b[0] + b[1] * v + b[2] * v * v
        ax.plot(v, neglog, "-", lw=1, label=f"−log f**, θ = {in_pi(fraction * math.pi)}")
        curves.append({"theta": fraction * math.pi, "neglog_f_twice": neglog})
    at = float(g.attrs["profile_angle"])
    speeds = g["profile_speeds"][:]
    once, twice = g["f_once_vs_speed"][:], g["f_twice_vs_speed"][:]
    with np.errstate(divide="ignore", invalid="ignore"):
        neglog_once, neglog_twice = -np.log(once), -np.log(twice)
    ax.plot(speeds, neglog_once, "ks", ms=2, mfc="none", label=f"−log f* at θ = {in_pi(at)}")
    ax.plot(speeds, neglog_twice, "k--", lw=0.8, label=f"−log f** at θ = {in_pi(at)}")
    ax.set(xlabel="v", ylabel="−log f", title="(F) −log f** = b⁽⁰⁾ + b⁽¹⁾v + b⁽²⁾v² (5.28)")
    legend(ax)
    return {"v": v, "curves": curves, "profile_angle": at, "profile_v": speeds,
            "neglog_f_once": neglog_once, "neglog_f_twice": neglog_twice}


def draw_profiles(ax_speed, ax_angle, g):
    drawn = {}
    for ax, along, x_name, fixed, title in (
            (ax_speed, "speed", "profile_speeds", f"θ = {in_pi(float(g.attrs['profile_angle']))}", "(G) f against v (Fig 5.10)"),
            (ax_angle, "angle", "profile_angles", f"v = {float(g.attrs['profile_speed']):.3g}", "(H) f against θ (Fig 5.11)")):
        x = g[x_name][:]
        curves = {name: g[f"f_{name}_vs_{along}"][:] for name in ("once", "twice", "jr")}
        ax.plot(x, curves["once"], "s", ms=2, mfc="none", label="f* (5.25)")
        ax.plot(x, curves["twice"], "--", lw=1, label="f** (5.28)")
        ax.plot(x, curves["jr"], "-", lw=1, label="Jenkins–Richman (5.32)")
        ax.set(ylabel="f", title=f"{title}, {fixed}")
        legend(ax)
        drawn[along] = {"x": x, **curves}
    ax_speed.set(xlabel="v", yscale="log")
    ax_angle.set(xlabel="θ")
    angle_ticks(ax_angle)
    return drawn


def window_rows(f):
    """Per window of the file: what row 3 draws, in the units of Figs 5.5-5.9."""
    rows = []
    for name in sorted(f["windows"]):
        g = f["windows"][name]
        s = float(g.attrs["speed_scale"])
        table, error = g["table"][:], g["table_error"][:]
        trace = {kind: g[f"stress_{kind}"][:] for kind in ("direct", "once", "twice")}
        kinds = ("direct", "once", "twice")
        replicated = "bootstrap_table" in g
        tables = g["bootstrap_table"][:] if replicated else None
        traces = g["bootstrap_traces"][:] if replicated else None
        row = {"name": name, "density_center": float(g.attrs["density_center"]),
               "T": float(g.attrs["temperature"]), "rho": float(g.attrs["density"]), "speed_scale": s,
               "means": dimensionless(table[0, 1:], s), "means_error": dimensionless(error[0, 1:], s),
               "phases": table[1:, 0], "phases_error": error[1:, 0],
               "trace": {kind: t[0] + t[2] for kind, t in trace.items()},
               "trace_error": dict(zip(kinds, g["stress_trace_error"][:])),
               "ratio": float(g.attrs["ratio_b1_squared_over_b2"]), "ratio_error": float(g.attrs["ratio_error"]),
               "percentile_intervals": replicated}
        row["means_interval"] = interval(row["means"], None if tables is None else
                                         np.array([dimensionless(t[0, 1:], s) for t in tables]), row["means_error"])
        row["phases_interval"] = interval(row["phases"], None if tables is None else tables[:, 1:, 0],
                                          row["phases_error"])
        row["trace_interval"] = {kind: interval(row["trace"][kind], None if traces is None else traces[:, n],
                                                row["trace_error"][kind]) for n, kind in enumerate(kinds)}
        row["ratio_interval"] = interval(row["ratio"], g["bootstrap_ratio"][:] if replicated else None, row["ratio_error"])
        rows.append(row)
    return rows


def draw_windows(ax_means, ax_phases, ax_stress, ax_ratio, rows, chosen):
    densities = sorted({row["density_center"] for row in rows})
    markers = "os^Dv<>p"
    for row in rows:
        marker = markers[densities.index(row["density_center"]) % len(markers)]
        t = row["T"]
        low, high = row["means_interval"]
        for i in range(3):
            draw_interval(ax_means, t, row["means"][i], (low[i], high[i]), fmt=marker, color=f"C{i}")
        low, high = row["phases_interval"]
        for j, phase in enumerate(row["phases"]):
            draw_interval(ax_phases, t, phase, (low[j], high[j]), fmt=marker, color=f"C{j}")
        for n, kind in enumerate(("direct", "once", "twice")):
            draw_interval(ax_stress, t, row["trace"][kind], row["trace_interval"][kind], fmt=marker, color=f"C{n}",
                          mfc="none" if kind != "direct" else None)
        draw_interval(ax_ratio, t, row["ratio"], row["ratio_interval"], fmt=marker, color="k")
    # Legends: colours say the quantity, markers the density window.
    for ax, labels in ((ax_means, COEFFICIENT_LABELS), (ax_phases, [f"ε{2 * j}" for j in range(1, 7)]),
                       (ax_stress, ("Tr τ (5.31)", "Tr τ* (5.30)", "Tr τ** (5.30)"))):
        for n, label in enumerate(labels):
            ax.plot([], [], "s", color=f"C{n}", label=label)
    for n, density in enumerate(densities):
        for ax in (ax_means, ax_phases, ax_stress, ax_ratio):
            ax.plot([], [], markers[n % len(markers)], color="grey", mfc="none", label=f"ρ window {density:.4g}")
    t = rows[chosen]["T"]
    clipped = {}
    bars = "16–84 % bootstrap" if all(row["percentile_intervals"] for row in rows) else "±1 sd bootstrap"
    for ax, key in ((ax_means, "means"), (ax_phases, "phases"), (ax_stress, "stress"), (ax_ratio, "ratio")):
        clipped[key] = robust_range(ax)
        ax.plot([], [], " ", label=f"bars: {bars}" + (f"; {clipped[key]} clipped (△▽)" if clipped[key] else ""))
        ax.axvline(t, color="grey", lw=0.6, ls=":")
        ax.set(xlabel="T of the window")
        legend(ax)
    ax_means.axhline(1.0, color="C2", lw=0.6, ls="--")
    ax_means.axhline(0.0, color="C1", lw=0.6, ls="--")
    ax_means.set(title="(I) means b₀⁽ⁱ⁾ (Figs 5.5, 5.8)")
    ax_phases.set(ylabel="ε₂ⱼ", title="(J) phases (Fig 5.6)")
    ax_stress.set(ylabel="Tr⟨v′v′⟩ per particle", title="(K) kinetic stress (Fig 5.7)")
    ax_ratio.set(ylabel="(b₀⁽¹⁾)²/b₀⁽²⁾", title="(L) ratio (Fig 5.9)")
    return clipped


def main():
    p = parser(KIND, __doc__, data=True)
    p.add_argument("--window", type=int, default=0)
    a = p.parse_args()
    with open_h5(KIND, a.input) as f:
        require_format(KIND, f, a.input, "granule-f1", "granule analyze f1")
        rows = window_rows(f)
        chosen = resolve_index(KIND, "--window", a.window, len(rows), "windows")
        g = f["windows"][rows[chosen]["name"]]
        s, table = float(g.attrs["speed_scale"]), g["table"][:]
        fig = figure(4 * PANEL_WIDTH, 3 * PANEL_HEIGHT)
        axes = [fig.add_subplot(3, 4, n + 1) for n in range(12)]
        data = {"window": chosen, "group": rows[chosen]["name"],
                **{key: float(value) for key, value in g.attrs.items() if key in (
                    "density_center", "density_half_width", "temperature_center", "temperature_half_width",
                    "density", "temperature", "speed_scale", "samples", "snapshots")}}
        data["once"] = draw_cumulative(*axes[0:4], g)
        data["coefficients"] = draw_coefficients(axes[4], g, table, s)
        data["twice"] = draw_neglog(axes[5], g, table)
        data["profiles"] = draw_profiles(axes[6], axes[7], g)
        data["clipped_bars"] = draw_windows(*axes[8:12], rows, chosen)
        data["windows"] = rows
        fig.suptitle(f"N = {int(f.attrs['particles'])}, ν = {float(f.attrs['area_fraction']):g}, "
                     f"ẽ = {float(f.attrs['restitution']):g}, {text(f.attrs['boundary'])}; rows 1–2: window {chosen} "
                     f"(ρ {data['density_center']:.4g} ± {data['density_half_width']:.4g}, "
                     f"T {data['temperature_center']:.4g} ± {data['temperature_half_width']:.4g}; "
                     f"{int(data['samples'])} samples in {int(data['snapshots'])} snapshots)", fontsize=10)
    save(fig, a.out, a.dpi, data, a.data)


if __name__ == "__main__":
    run(main)
