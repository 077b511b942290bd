"""Spin correlation of neighbouring rough grains from spins.h5 (written by `granule analyze spins`,
README "spins.h5"; thesis Fig C.4): (A) C(r) = <δω_i·δω_j>/<|δω|²> against the centre distance r in
contact distances σ_ij, averaged over the analysed frames, for all pairs and for pairs along the
flow (|Δx| largest) and along the gradient (|Δy| largest), the contact shell shaded; negative values
are neighbours spinning in opposite senses.  (B) C_contact of each frame against c, with the mean
and its standard error.  Two 6 × 4.5 inch panels.  --frame is not used: the average is drawn."""
import numpy as np

from _common import figure, legend, open_h5, parser, require_format, run, save, text

KIND = "spins"
CURVES = (("", "all pairs", "o-"), ("_flow", "along the flow x", "s--"), ("_gradient", "along the gradient y", "^:"))


def finite_limits(values, pad=0.1):
    """Axis limits around the finite values (None when there are none), so an empty bin (NaN) or an
    infinite entry does not stretch the axis."""
    finite = np.concatenate([np.asarray(v, dtype=float).ravel() for v in values])
    finite = finite[np.isfinite(finite)]
    if finite.size == 0:
        return None
    low, high = min(float(finite.min()), 0.0), max(float(finite.max()), 0.0)
    span = high - low if high > low else 1.0
    return low - pad * span, high + pad * span


def draw_correlation(ax, f):
    r = f["r"][:]
    shell = 1.0 + float(f.attrs["contact_shell"])
    drawn = {"r": r}
    ax.axvspan(1.0, shell, color="0.9", label=f"contact: r < {shell:g} σ_ij")
    ax.axhline(0.0, color="k", lw=0.6)
    for suffix, label, style in CURVES:
        c = f["average/C" + suffix][:]
        ax.plot(r, c, style, ms=3, lw=1, label=label)
        drawn["C" + suffix] = c
        drawn["pairs" + suffix] = f["average/pairs" + suffix][:]
    limits = finite_limits([drawn["C" + s] for s, _, _ in CURVES])
    if limits:
        ax.set_ylim(*limits)
    ax.set(xlabel="r / σ_ij", ylabel="C(r) = ⟨δω_i·δω_j⟩ / ⟨|δω|²⟩", title="(A) spin correlation against distance")
    legend(ax)
    return drawn


def draw_contact_series(ax, f):
    c = f["collisions_per_particle"][:]
    contact = f["C_contact"][:]
    mean, error = float(f.attrs["C_contact"]), float(f.attrs["C_contact_error"])
    ax.axhline(0.0, color="k", lw=0.6)
    ax.plot(c, contact, "o", ms=4, label="C_contact of each frame")
    if np.isfinite(mean):
        ax.axhline(mean, color="C1", lw=1, label=f"mean {mean:.3g} ± {error:.2g}")
        if np.isfinite(error):
            ax.axhspan(mean - error, mean + error, color="C1", alpha=0.2)
    limits = finite_limits([contact, [mean]])
    if limits:
        ax.set_ylim(*limits)
    ax.set(xlabel="c (collisions per particle)", ylabel="C_contact", title="(B) contact value per frame")
    legend(ax)
    return {"c": c, "C_contact": contact, "mean": mean, "error": error}


def main():
    a = parser(KIND, __doc__, data=True).parse_args()
    with open_h5(KIND, a.input) as f:
        require_format(KIND, f, a.input, "granule-spins", "granule analyze spins")
        fig = figure(12.0, 4.5)
        axes = [fig.add_subplot(1, 2, n + 1) for n in range(2)]
        data = {"correlation": draw_correlation(axes[0], f), "contact": draw_contact_series(axes[1], f),
                "contact_pairs": float(f.attrs["contact_pairs"]), "frames": len(f["time"])}
        fig.suptitle(f"N = {int(f.attrs['particles'])}, ẽ = {float(f.attrs['restitution']):g}, "
                     f"β = {float(f.attrs['tangential_restitution']):g}, {text(f.attrs['boundary'])}; "
                     f"{data['frames']} frame(s), spins relative to each frame's mean", fontsize=10)
    save(fig, a.out, a.dpi, data, a.data)


if __name__ == "__main__":
    run(main)
