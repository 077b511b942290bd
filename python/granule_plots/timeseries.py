"""Global diagnostics from timeseries.csv (thesis Figs 2.5-2.7, 3.6): c against t, the kinetic energy
E and the mean temperature T̄ against c and t, flatness κ (eq 1.8), asymmetry, kinetic and
collisional pressure and the collision rate.  For periodic (free-cooling) runs E(c) is drawn beside
the homogeneous law ln T = ln T₀ − (1 − ẽ²) c; rough grains add T_rot beside T̄.  A 13.5 × 10.5 inch figure of nine panels."""
import csv

import numpy as np

from _common import fail, figure, parser, run, run_summary, save


KIND = "timeseries"


def main():
    a = parser(KIND, __doc__).parse_args()
    try:
        rows = list(csv.DictReader(open(a.input)))
        data = {key: np.array([float(r[key]) for r in rows]) for key in rows[0]} if rows else {}
    except (OSError, ValueError, KeyError) as error:
        fail(KIND, f"cannot read {a.input}: {error}")
    for key in ("t", "c", "kinetic_energy", "temperature", "flatness", "pressure_kinetic", "collision_rate"):
        if key not in data:
            fail(KIND, f"{a.input} has no column {key} (is it a Granule timeseries.csv?)")
    summary = run_summary(a.input)
    free = summary.get("boundary", "periodic") == "periodic"
    t, c = data["t"], data["c"]
    later = t > 0  # logarithmic time axes start after the first sample
    time_scale = "log" if free else "linear"
    fig = figure(13.5, 10.5)
    axes = [fig.add_subplot(3, 3, n + 1) for n in range(9)]

    ax = axes[0]
    ax.plot(t[later], c[later])
    ax.set_xscale(time_scale)
    ax.set(xlabel="t", ylabel="c", title="(A) collisions per particle")

    ax = axes[1]
    ax.semilogy(c, data["kinetic_energy"], label="E")
    if free and "restitution" in summary:
        e = summary["restitution"]
        ax.semilogy(c, data["kinetic_energy"][0] * np.exp(-(1 - e * e) * c), "k--", lw=1, label="E₀ exp(−(1−ẽ²) c), homogeneous")
        ax.legend(fontsize=8)
    ax.set(xlabel="c", ylabel="E", title="(B) kinetic energy per disk")

    ax = axes[2]
    ax.plot(t[later], data["kinetic_energy"][later])
    ax.set_xscale(time_scale)
    ax.set_yscale("log")
    ax.set(xlabel="t", ylabel="E", title="(C) kinetic energy per disk")

    ax = axes[3]
    ax.plot(c, data["flatness"])
    ax.axhline(2.0, color="k", ls="--", lw=1)
    ax.set(xlabel="c", ylabel="κ", title="(D) flatness (1.8); 2 for a Maxwellian")

    ax = axes[4]
    ax.semilogy(c, data["temperature"], label="T̄")
    if "rotational_temperature" in data:  # rough grains: the spin's share beside it
        ax.semilogy(c, data["rotational_temperature"], label="T_rot = I⟨|ω|²⟩/d_rot")
        ax.legend(fontsize=8)
    ax.set(xlabel="c", ylabel="T̄", title="(E) mean temperature")

    ax = axes[5]
    ax.plot(t[later], data["temperature"][later])
    ax.set_xscale(time_scale)
    ax.set_yscale("log")
    ax.set(xlabel="t", ylabel="T̄", title="(F) mean temperature")

    ax = axes[6]
    for key in ("asymmetry_x", "asymmetry_y"):
        if key in data:
            ax.plot(c, data[key], label=f"⟨v′_{key[-1]}³⟩ / ⟨v′²⟩^(3/2)")
    ax.legend(fontsize=8)
    ax.set(xlabel="c", title="(G) asymmetry")

    ax = axes[7]
    ax.semilogy(c, data["pressure_kinetic"], label="kinetic")
    if "pressure_collisional" in data:
        ax.semilogy(c[1:], data["pressure_collisional"][1:], label="collisional")
    ax.legend(fontsize=8)
    ax.set(xlabel="c", ylabel="P", title="(H) pressure")

    ax = axes[8]
    ax.plot(c[1:], data["collision_rate"][1:])
    ax.set(xlabel="c", ylabel="dc/dt", title="(I) collision rate")

    fig.suptitle(f"{a.input}: N = {summary.get('particles', '?')}, ẽ = {summary.get('restitution', '?')}, "
                 f"{summary.get('boundary', '')}", fontsize=10)
    save(fig, a.out, a.dpi)


if __name__ == "__main__":
    run(main)
