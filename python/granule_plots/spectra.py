"""Fourier spectra from spectra.h5 (written by `granule analyze spectra`, docs/spectra.md), one
analysed frame (--frame counts the frames of the file): (A) the annulus sum R(k) of the mass power and
(B) P(k), P_x(k), P_y(k) of the momentum power against |k| (thesis Figs 2.8-2.10), R beside the level
of uncorrelated positions (modes × N/4π²); (C-E) the power maps R, P_x, P_y over (k_x, k_y) on log
shades, k = 0 left out, the dominant mode ±k circled (Figs 3.21-3.27); (F) the dominant length 2π/|k|
of R and P against c beside L0 = l/√(1−ẽ²) (1.1).  Two rows of three 5 × 4.5 inch panels.
3D runs (Appendix C): (A, B) the shell-averaged S_R(k) and S_P(k) over the uncorrelated level, with
the band 1 ± 2 sd of an ideal gas; (C-E) the maps on the plane k_z = 0; the dominant modes are those of
the whole 3D lattice (marked on the plane by their (k_x, k_y))."""
import math

import numpy as np
from matplotlib.colors import LogNorm

from _common import figure, legend, open_h5, parser, require_format, resolve_frame, run, save, text

KIND = "spectra"
MAPS = [("R", "(C) R = |ρ̃|² (3.13)"), ("Px", "(D) P_x = |p̃_x|² (3.14)"), ("Py", "(E) P_y = |p̃_y|² (3.15)")]


def mark_cluster_k(ax, ring_k, dk, cluster_k):
    """Mark the wavenumber of the cluster length only where the rings reach, not to squash them."""
    if cluster_k is not None and len(ring_k) and cluster_k <= ring_k[-1] + dk:
        ax.axvline(cluster_k, color="grey", ls=":", lw=1, label="2π/L0 (1.1)")
    elif cluster_k is not None:
        ax.plot([], [], " ", label=f"2π/L0 = {cluster_k:.3g} lies beyond the rings")


def draw_shells(ax_mass, ax_momentum, f, k, cluster_k):
    """3D: the shell-averaged spectra over the uncorrelated level, beside its band 1 ± 2 sd."""
    ring_k = f["shell_k"][:]
    drawn = {"k": ring_k, "modes": f["shell_modes"][k]}
    for ax, name, title in ((ax_mass, "R", "(A) mass S_R(k) = ⟨R⟩_shell / (Σm²/4π²)"),
                            (ax_momentum, "P", "(B) momentum S_P(k) = ⟨P⟩_shell / (Σm²v²/4π²)")):
        value, sd = f["S_" + name][k], f[f"S_{name}_sd"][k]
        ax.fill_between(ring_k, 1 - 2 * sd, 1 + 2 * sd, color="0.85", label="uncorrelated positions: 1 ± 2 sd")
        ax.plot(ring_k, value, "o-", ms=3, lw=1, label=f"S_{name}(k)")
        mark_cluster_k(ax, ring_k, float(f.attrs["dk"]), cluster_k)
        ax.set(xlabel="|k|", ylim=(0, None), title=title)
        legend(ax)
        drawn["S_" + name], drawn[f"S_{name}_sd"] = value, sd
    return drawn


def draw_annulus(ax_mass, ax_momentum, f, k, cluster_k):
    ring_k = f["annulus_k"][:]
    uncorrelated = f["annulus_modes"][k] * float(f.attrs["particles"]) / (4.0 * math.pi ** 2)
    ax_mass.plot(ring_k, f["annulus_R"][k], "o-", ms=3, lw=1, label="R(k)")
    ax_mass.plot(ring_k, uncorrelated, "k--", lw=0.8, label="uncorrelated positions: modes × N/4π²")
    for name, label in (("P", "P = P_x + P_y"), ("Px", "P_x"), ("Py", "P_y")):
        ax_momentum.plot(ring_k, f["annulus_" + name][k], "o-", ms=2, lw=1, label=label)
    for ax, title in ((ax_mass, "(A) mass spectrum R(k)"), (ax_momentum, "(B) momentum spectrum P(k)")):
        mark_cluster_k(ax, ring_k, float(f.attrs["dk"]), cluster_k)
        ax.set(xlabel="|k|", ylim=(0, None), title=title)
        legend(ax)
    return {"k": ring_k, "modes": f["annulus_modes"][k], "uncorrelated_R": uncorrelated,
            **{name: f["annulus_" + name][k] for name in ("R", "P", "Px", "Py")}}


def draw_map(fig, ax, f, k, name, title):
    kx, ky, power = f["kx"][k], f["ky"][k], f[name][k]
    shown = np.ma.masked_where(~np.isfinite(power) | (power <= 0) | ((kx == 0) & (ky == 0)), power)
    image = ax.pcolormesh(kx, ky, shown, shading="nearest", cmap="viridis", norm=LogNorm(shown.min(), shown.max()))
    fig.colorbar(image, ax=ax, shrink=0.85)
    drawn = {"power_min": shown.min(), "power_max": shown.max()}
    if "dominant" in f:
        d = f["dominant/" + name]
        top = np.array([d["kx"][k], d["ky"][k]])
        # 3D: the dominant mode of the whole lattice, drawn at its (k_x, k_y) and labelled with its k_z.
        off_plane = f", k_z = {d['kz'][k]:.3g}" if "kz" in d else ""
        ax.plot([top[0], -top[0]], [top[1], -top[1]], "o", mfc="none", mec="r", ms=9,
                label=f"dominant: 2π/|k| = {d['length'][k]:.3g}{off_plane}")
        legend(ax)
        drawn["dominant_k"] = top
    ax.set(xlabel="k_x", ylabel="k_y", aspect="equal", title=title)
    return drawn


def draw_dominant(ax, f, k, cluster_length):
    c = f["collisions_per_particle"][:]
    series = {"c": c}
    for name, label in (("R", "mass R"), ("P", "momentum P")):
        series[name] = f[f"dominant/{name}/length"][:]
        ax.plot(c, series[name], "o-", ms=3, lw=1, label=label)
    if cluster_length is not None:
        ax.axhline(cluster_length, color="grey", ls="--", lw=1, label="L0 = l/√(1−ẽ²) (1.1)")
    ax.axvline(c[k], color="k", ls=":", lw=0.8, label="this frame")
    ax.set(xlabel="c", ylabel="dominant length 2π/|k|", ylim=(0, None), title="(F) dominant length")
    legend(ax)
    return series


def main():
    a = parser(KIND, __doc__, data=True).parse_args()
    with open_h5(KIND, a.input) as f:
        require_format(KIND, f, a.input, "granule-spectra", "granule analyze spectra")
        k = resolve_frame(KIND, a.frame, len(f["time"]))
        # L0 is infinite (stored as such or 0) for elastic runs: no cluster length to mark.
        cluster_length = float(f.attrs["L0"])
        cluster_length = cluster_length if math.isfinite(cluster_length) and cluster_length > 0 else None
        cluster_k = 2.0 * math.pi / cluster_length if cluster_length else None
        fig = figure(15.0, 9.0)
        axes = [fig.add_subplot(2, 3, n + 1) for n in range(6)]
        data = {"frame": k, "frame_index": f["frame_index"][k], "t": f["time"][k], "c": f["collisions_per_particle"][k],
                "L0": cluster_length}
        three_d = int(f.attrs.get("dimension", 2)) == 3
        if three_d:
            data["shells"] = draw_shells(axes[0], axes[1], f, k, cluster_k)
        else:
            data["annulus"] = draw_annulus(axes[0], axes[1], f, k, cluster_k)
        plane = " on k_z = 0" if three_d else ""
        data["maps"] = {name: draw_map(fig, ax, f, k, name, title + plane) for ax, (name, title) in zip(axes[2:5], MAPS)}
        if "dominant" in f:
            data["dominant"] = draw_dominant(axes[5], f, k, cluster_length)
        else:
            axes[5].text(0.5, 0.5, "no dominant-mode series in the file", ha="center", transform=axes[5].transAxes)
        fraction = f.attrs["packing_fraction"] if three_d else f.attrs["area_fraction"]
        fig.suptitle(f"N = {int(f.attrs['particles'])}, {'φ' if three_d else 'ν'} = {float(fraction):g}, "
                     f"ẽ = {float(f.attrs['restitution']):g}, {text(f.attrs['boundary'])}; snapshot "
                     f"{int(data['frame_index'])} at t = {data['t']:.4g}, c = {data['c']:.4g}; M = {int(f.attrs['max_mode'])}",
                     fontsize=10)
    save(fig, a.out, a.dpi, data, a.data)


if __name__ == "__main__":
    run(main)
