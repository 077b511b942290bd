"""Collision statistics from collisions.h5 (written by `granule run`, thesis §2.3 and §3.2.2-3.2.3).
Impact parameters: (A) the distribution β(b/σ) (3.20) over the whole interval, per density window and
in the last time window (Figs 2.16, 3.30); (B) the cumulative B(b) − b/σ (3.21, Fig 3.31); (C) β of
every time window against t.  Free paths before collision, of one --window group: (D) the angular
part L(l_max, α) with the fitted angular factor of (3.24) and its α₀ (Fig 3.32); (E) L(l, α) against
l at fixed α with (3.24), erf(√(l/l̄)) times the angular factor (Fig 3.33); (F) the magnitude
distribution 𝒫(l) on log axes beside the matched form (3.36) and the exponential, with their
Kolmogorov distances.  One row of three 5 × 4.5 inch panels per statistic in the file.
A 3D file (spheres) has (b/σ)² for b/σ, uniform under molecular chaos, and cos θ (θ from the flow
axis x) for α: panels (D) and (E) compare with isotropy, (1 + cos θ)/2, for there is no (3.24) to fit."""
import math

import numpy as np
from scipy.special import erf

from _common import angle_ticks, fail, figure, legend, open_h5, parser, require_format, run, save, text

KIND = "collisions"
PANEL_WIDTH, PANEL_HEIGHT = 5.0, 4.5
FIXED_ANGLES = [("π/2", 0.5 * math.pi), ("π", math.pi), ("2π", 2.0 * math.pi)]  # the α of panel (E)
FIXED_COSINES = [("−½", -0.5), ("0", 0.0), ("1", 1.0)]  # the cos θ of panel (E) in 3D


def numbered(group, prefix):
    """The subgroups `<prefix>_<i>` in order of i."""
    names = [name for name in group if name.startswith(prefix + "_")]
    return sorted(names, key=lambda name: int(name.rsplit("_", 1)[1]))


def window_label(group):
    """'all collisions', or the density / speed window a group was measured in."""
    for quantity, symbol in (("density", "ρ"), ("speed", "v")):
        if f"{quantity}_low" in group.attrs:
            return f"{symbol} ∈ [{float(group.attrs[quantity + '_low']):.4g}, {float(group.attrs[quantity + '_high']):.4g})"
    return "all collisions"


def normalised_beta(counts, width):
    """β(b/σ) of a histogram, normalised to unit integral over [0, 1] as (3.20)."""
    total = counts.sum()
    return counts / (total * width) if total > 0 else np.full(len(counts), np.nan)


def angular_part(alpha, alpha0):
    """The angular factor of (3.24), normalised (as the fit in collisions.h5) to 0 at α = 0 and 1 at 2π."""
    def f(a):
        return np.arctan(a / alpha0) + np.arctan((a - math.pi) / alpha0) + np.arctan((a - 2.0 * math.pi) / alpha0)

    return (f(alpha) - f(0.0)) / (f(2.0 * math.pi) - f(0.0))


def isotropic_part(cos_theta):
    """The isotropic law of cos θ in 3D, cumulative from −1: (1 + cos θ)/2."""
    return 0.5 * (1.0 + cos_theta)


def draw_impact_parameters(fig, axes, g, three_d):
    edges = g["bin_edges"][:]
    b = "(b/σ)²" if three_d else "b/σ"
    width = edges[1] - edges[0]
    groups = ["total"] + numbered(g, "density_window")
    drawn = {}
    ax_beta, ax_cumulative, ax_windows = axes
    for name in groups:
        group = g[name]
        samples = float(group.attrs["samples"])
        if samples <= 0:
            continue
        label = window_label(group)
        beta, excess = group["density"][:], np.concatenate([[0.0], group["cumulative_minus_uniform"][:]])
        ks = float(group.attrs["ks_uniform"])
        ax_beta.stairs(beta, edges, label=f"{label} ({samples:.0f})", lw=1.2)
        ax_cumulative.plot(edges, excess, "o-", ms=2, lw=1, label=f"{label}: max |·| = {ks:.3g}")
        drawn[name] = {"label": label, "samples": samples, "ks_uniform": ks, "beta": beta, "cumulative_minus_uniform": excess}

    windows = g["windows"]
    t_start, t_end, counts = windows["t_start"][:], windows["t_end"][:], windows["counts"][:]
    per_window = np.array([normalised_beta(row, width) for row in counts]).reshape(len(t_start), len(edges) - 1)
    if len(t_start):
        label = f"last window, t ∈ [{t_start[-1]:.4g}, {t_end[-1]:.4g}]"
        ax_beta.stairs(per_window[-1], edges, color="k", ls=":", lw=1, label=label)
        drawn["last_window"] = {"label": label, "samples": float(counts[-1].sum()), "beta": per_window[-1]}
        # Windows are consecutive runs of collisions (from a window's first collision to its last),
        # so each band spans from its start to the next window's start.
        rows = np.append(t_start, t_end[-1])
        image = ax_windows.pcolormesh(edges, rows, per_window, cmap="viridis", vmin=0.0)
        fig.colorbar(image, ax=ax_windows, shrink=0.85, label=f"β({b})")
        ax_windows.set_ylabel("t")
    else:
        ax_windows.text(0.5, 0.5, "no complete time window", ha="center", transform=ax_windows.transAxes)
    ax_beta.axhline(1.0, color="grey", ls="--", lw=0.8, label="uniform (elastic, isotropic)")
    ax_beta.set(xlim=(0, 1), ylim=(0, None), xlabel=b, ylabel=f"β({b})", title="(A) impact parameters β (3.20)")
    ax_cumulative.axhline(0.0, color="grey", lw=0.8)
    ax_cumulative.set(xlim=(0, 1), xlabel=b, ylabel=f"B(b) − {b}", title="(B) cumulative minus uniform (3.21)")
    ax_windows.set(xlabel=b, title=f"(C) β per window of {int(g.attrs['window_collisions'])} collisions")
    for ax in (ax_beta, ax_cumulative):
        legend(ax)
    return {"bin_edges": edges, "curves": drawn, "windows": {"t_start": t_start, "t_end": t_end, "beta": per_window}}


def draw_free_paths(axes, fp, name, three_d):
    g = fp[name]
    l_edges, a_edges = fp["length_edges"][:], fp["angle_edges"][:]
    attrs = {key: float(value) for key, value in g.attrs.items() if key not in ("density_low", "density_high", "speed_low", "speed_high")}
    ax_angle, ax_length, ax_magnitude = axes
    label = window_label(g)
    if attrs["paths"] <= 0:
        for ax in axes:
            ax.text(0.5, 0.5, f"no free paths in {name}", ha="center", transform=ax.transAxes)
        return {"window": name, "label": label, **attrs}
    alpha0, lbar = attrs["alpha0"], attrs["lbar"]

    # (D) Fig 3.32: the measured angular part against the fitted factor of (3.24) (2D) or isotropy (3D).
    if three_d:
        fine_alpha = np.linspace(-1.0, 1.0, 401)
        model_alpha = isotropic_part(fine_alpha)
        ax_angle.plot(a_edges[1:], g["angular_cumulative"][:], "o", ms=3, label="L(l_max, cos θ) / L(l_max, 1)")
        ax_angle.plot(fine_alpha, model_alpha, ":", color="grey", lw=1.2,
                      label=f"isotropic (1 + cos θ)/2: KS {attrs['ks_isotropic']:.3g}")
        ax_angle.set(xlabel="cos θ (θ the angle of the path from +x)", ylabel="angular part",
                     title="(D) L(l_max, cos θ) (3.23) and isotropy")
    else:
        fine_alpha = np.linspace(0.0, 2.0 * math.pi, 721)
        model_alpha = angular_part(fine_alpha, alpha0)
        ax_angle.plot(a_edges[1:], g["angular_cumulative"][:], "o", ms=3, label="L(l_max, α) / L(l_max, 2π)")
        ax_angle.plot(fine_alpha, model_alpha, "-", lw=1.2, label=f"(3.24): α₀ = {alpha0:.3g} (rms {attrs['alpha0_rms']:.2g})")
        ax_angle.plot(fine_alpha, fine_alpha / (2.0 * math.pi), ":", color="grey", lw=1, label="isotropic α/2π")
        angle_ticks(ax_angle)
        ax_angle.set(xlabel="α (angle of the path from +x)", ylabel="angular part", title="(D) L(l_max, α) (3.23) and (3.24)")

    # (E) Fig 3.33: L(l, α) at fixed α against the factorised form (3.24).
    fine_l = np.linspace(0.0, l_edges[-1], 400)
    cumulative = g["cumulative"][:]
    radial = []
    symbol_of_angle = "cos θ" if three_d else "α"
    for symbol, alpha in FIXED_COSINES if three_d else FIXED_ANGLES:
        a = int(np.argmin(np.abs(a_edges[1:] - alpha)))
        angular = isotropic_part(a_edges[a + 1]) if three_d else angular_part(a_edges[a + 1], alpha0)
        model = angular * erf(np.sqrt(fine_l / lbar))
        points = ax_length.plot(l_edges[1:], cumulative[:, a], "o", ms=2, label=f"{symbol_of_angle} = {symbol}")
        ax_length.plot(fine_l, model, "-", lw=1, color=points[0].get_color())
        radial.append({"alpha": a_edges[a + 1], "l": l_edges[1:], "measured": cumulative[:, a], "model_l": fine_l, "model": model})
    angular_name = "isotropic angular part" if three_d else "(3.24): angular part"
    ax_length.plot([], [], "k-", lw=1, label=f"{angular_name} × erf(√(l/l̄)), l̄ = {lbar:.3g}")
    ax_length.set(xlabel="l", ylabel=f"L(l, {symbol_of_angle})", ylim=(0, None),
                  title=f"(E) L(l, {symbol_of_angle}) at fixed {symbol_of_angle} (3.23)")

    # (F) 𝒫(l), log axes: (3.36) rises as 1/√l at short paths where the exponential stays flat.
    centres = 0.5 * (l_edges[1:] + l_edges[:-1])
    measured = g["magnitude_density"][:]
    seen = measured > 0
    ax_magnitude.loglog(centres[seen], measured[seen], "o", ms=3, label=f"measured ({attrs['paths']:.0f} paths)")
    ax_magnitude.loglog(centres, g["matched_density"][:], "-", lw=1.2,
                        label=f"(3.36): l₀ = {attrs['l0_matched']:.3g}, KS {attrs['ks_matched']:.3g}")
    ax_magnitude.loglog(centres, g["exponential_density"][:], "--", lw=1.2,
                        label=f"exp(−l/λ)/λ: λ = {attrs['lambda_exponential']:.3g}, KS {attrs['ks_exponential']:.3g}")
    ax_magnitude.set(xlabel="l", ylabel=r"$\mathcal{P}(l)$", title=r"(F) free-path lengths $\mathcal{P}(l)$")
    for ax in axes:
        legend(ax)
    return {"window": name, "label": label, **attrs,
            "angular": {"alpha": a_edges[1:], "measured": g["angular_cumulative"][:], "model_alpha": fine_alpha, "model": model_alpha},
            "radial": radial,
            "magnitude": {"l": centres, "measured": measured, "matched": g["matched_density"][:],
                          "exponential": g["exponential_density"][:]}}


def main():
    p = parser(KIND, __doc__, data=True)
    p.add_argument("--window", default="total")
    a = p.parse_args()
    with open_h5(KIND, a.input) as f:
        require_format(KIND, f, a.input, "granule-collisions", "granule run")
        rows = [group for group in ("impact_parameters", "free_paths") if group in f]
        if not rows:
            fail(KIND, f"{a.input} holds neither impact parameters nor free paths (collisions.* settings of the run)")
        if "free_paths" in f:
            windows = ["total"] + numbered(f["free_paths"], "density_window") + numbered(f["free_paths"], "speed_window")
            if a.window not in windows:
                fail(KIND, f"--window {a.window} is not a free-path group of {a.input} (allowed: {', '.join(windows)})")
        elif a.window != "total":
            fail(KIND, f"--window {a.window}: {a.input} has no free paths (allowed: total)")
        three_d = int(f.attrs.get("dimension", 2)) == 3
        fig = figure(3 * PANEL_WIDTH, len(rows) * PANEL_HEIGHT)
        data = {}
        for row, group in enumerate(rows):
            axes = [fig.add_subplot(len(rows), 3, 3 * row + column + 1) for column in range(3)]
            if group == "impact_parameters":
                data[group] = draw_impact_parameters(fig, axes, f[group], three_d)
            else:
                data[group] = draw_free_paths(axes, f[group], a.window, three_d)
        free_paths = f"; free paths: {data['free_paths']['label']}" if "free_paths" in data else ""
        fig.suptitle(f"N = {int(f.attrs['particles'])}, ẽ = {float(f.attrs['restitution']):g}, {text(f.attrs['boundary'])}; "
                     f"collisions over c ∈ [{float(f.attrs['from_c']):.4g}, {float(f.attrs['to_c']):.4g}], "
                     f"t ∈ [{float(f.attrs['from_t']):.4g}, {float(f.attrs['to_t']):.4g}]{free_paths}", fontsize=10)
    save(fig, a.out, a.dpi, data, a.data)


if __name__ == "__main__":
    run(main)
