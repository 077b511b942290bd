"""One figure of `granule reproduce` from the JSON the command wrote beside it (figures/NAME.json):
measured points (with error bars when the JSON gives standard errors) and theory lines, on linear
or logarithmic axes.  A 6.4 × 4.2 inch figure at 100 dpi."""
import json
import math

from _common import fail, figure, legend, parser, run, save

KIND = "reproduce"


def finite(values):
    return [math.nan if v is None else float(v) for v in values]


def main():
    p = parser(KIND, __doc__, frame=False)
    args = p.parse_args()
    try:
        spec = json.loads(open(args.input).read())
    except (OSError, ValueError) as error:
        fail(KIND, f"cannot read {args.input}: {error}")
    fig = figure(6.4, 4.2)
    ax = fig.add_subplot(1, 1, 1)
    for series in spec["series"]:
        x, y = finite(series["x"]), finite(series["y"])
        if series.get("line"):
            ax.plot(x, y, "-", lw=1.5, label=series["label"])
        elif any(math.isfinite(e) for e in finite(series.get("error", []))):
            # One seed gives no error: such points are drawn without a bar.
            errors = [e if math.isfinite(e) else 0.0 for e in finite(series["error"])]
            ax.errorbar(x, y, yerr=errors, fmt="o", ms=4, capsize=3, label=series["label"])
        else:
            ax.plot(x, y, "o" if len(x) < 30 else ".-", ms=3, lw=0.8, label=series["label"])
    if spec.get("log_x"):
        ax.set_xscale("log")
    if spec.get("log_y"):
        ax.set_yscale("log")
    ax.set_xlabel(spec.get("x_label", ""))
    ax.set_ylabel(spec.get("y_label", ""))
    ax.set_title(spec.get("title", ""), fontsize=10)
    ax.grid(True, which="major", alpha=0.3)
    legend(ax)
    save(fig, args.out, args.dpi)


if __name__ == "__main__":
    run(main)
