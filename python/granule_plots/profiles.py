"""Streamwise-averaged profiles V_x, V_y, ρ and T against y from fields.h5 (thesis Figs 3.15-3.16);
for Lees-Edwards runs V_x is drawn beside the imposed mean flow u(y) = γ (y − L_y/2).  A 10 × 8 inch
figure of four panels."""

from _common import fail, figure, open_h5, parser, resolve_frame, run, save, text

KIND = "profiles"
PANELS = [("velocity_x", "(A) V_x"), ("velocity_y", "(B) V_y"), ("density", "(C) density ρ"), ("temperature", "(D) temperature T")]


def main():
    a = parser(KIND, __doc__).parse_args()
    with open_h5(KIND, a.input) as f:
        if "profiles" not in f or "frames" not in f:
            fail(KIND, f"{a.input} is not a fields file (no /profiles)")
        k = resolve_frame(KIND, a.frame, len(f["frames/t"]))
        y = f["profiles/y"][:]
        ly = float(f.attrs["length_y"])
        sheared = text(f.attrs.get("boundary", "periodic")) == "lees-edwards"
        subtracted = int(f.attrs.get("subtract_shear_profile", 0)) == 1
        gamma = float(f.attrs.get("shear_velocity", 0.0)) / ly
        fig = figure(10.0, 8.0)
        for n, (name, title) in enumerate(PANELS):
            ax = fig.add_subplot(2, 2, n + 1)
            ax.plot(y, f["profiles/" + name][k], "o-", ms=3)
            if name == "velocity_x" and sheared and not subtracted:
                ax.plot(y, gamma * (y - 0.5 * ly), "k--", lw=1, label="u(y) = γ (y − L_y/2)")
                ax.legend(fontsize=8)
            ax.set_xlabel("y")
            ax.set_title(title, fontsize=10)
        relative = " (relative to u(y))" if subtracted else ""
        fig.suptitle(f"Streamwise averages{relative} at t = {float(f['frames/t'][k]):.4g}, c = {float(f['frames/c'][k]):.4g}",
                     fontsize=10)
    save(fig, a.out, a.dpi)


if __name__ == "__main__":
    run(main)
