"""`granule theory` refuses numeric options outside the ranges its formulas hold in (NaN, ±inf,
e = 2, negative lengths, zero rates ...) with exit 2, a message naming the option and the allowed
range, and nothing on stdout; values at the edges of each range are accepted and print only
finite numbers."""
import math

from harness import check, finish, granule

# (subcommand and options, the option the message must name, a fragment of the allowed range)
REFUSED = [
    (["haff", "-e", "2"], "--restitution = 2", "(0, 1)"),
    (["haff", "-e", "nan"], "--restitution = nan", "(0, 1)"),
    (["haff", "-e", "1"], "--restitution = 1", "(0, 1)"),
    (["haff", "--area-fraction", "0.91"], "--area-fraction = 0.91", "0.9068996821171089)"),
    (["haff", "--diameter", "-1"], "--diameter = -1", "[1e-30, 1e+30]"),
    (["haff", "--temperature", "inf"], "--temperature = inf", "[1e-60, 1e+60]"),
    (["haff", "--contact-value", "0.5"], "--contact-value = 0.5", "[1, 1e+30]"),
    (["haff", "--collisions", "-1"], "--collisions = -1", "[0, "),
    (["haff", "-e", "0.9", "--collisions", "5264"], "--collisions = 5264", "ε c ≤ 1000"),
    (["haff", "--points", "0"], "--points = 0", "[1, 10000]"),
    (["free-stability", "--eps", "0"], "--eps = 0", "(0, 1]"),
    (["free-stability", "--eps", "-inf"], "--eps = -inf", "(0, 1]"),
    (["free-stability", "--K-min", "0"], "--K-min = 0", "(0, 1000000]"),
    (["free-stability", "--K-max", "1e7"], "--K-max = 10000000", "(0, 1000000]"),
    (["free-stability", "--points", "-3"], "--points = -3", "[1, 10000]"),
    (["shear-stability", "--sqrt-eps", "1.5"], "--sqrt-eps = 1.5", "(0, 1]"),
    (["shear-stability", "-e", "-0.5"], "--restitution = -0.5", "(0, 1)"),
    (["shear-stability", "--theta-deg", "nan"], "--theta-deg = nan", "[0, 180]"),
    (["shear-stability", "--delta-max", "1e7"], "--delta-max = 10000000", "[0, 1000000]"),
    (["shear-stability", "--delta-min", "-1"], "--delta-min = -1", "[0, 1000000]"),
    (["shear-scales", "-e", "1.0"], "--restitution = 1", "(0, 1)"),
    (["shear-scales", "--particles", "1"], "--particles = 1", "[2, 2147483647]"),
    (["shear-scales", "--box", "0"], "--box = 0", "[1e-30, 1e+30]"),
    (["shear-scales", "--diameter", "1e31"], "--diameter = 1e+31", "[1e-30, 1e+30]"),
    (["shear-scales", "--shear-rate", "0"], "--shear-rate = 0", "[1e-30, 1e+30]"),
    (["shear-scales", "--mode", "0"], "--mode = 0", "[1, 2147483647]"),
    (["shear-scales", "--initial-temperature", "-1"], "--initial-temperature = -1", "[1e-60, 1e+60]"),
    (["steady-shear", "-e", "nan"], "--restitution = nan", "(0, 1)"),
    (["steady-shear", "--e-max", "1"], "--e-max = 1", "(0, 1)"),
    (["steady-shear", "--e-min", "0"], "--e-min = 0", "(0, 1)"),
    (["steady-shear", "--shear-rate", "-100"], "--shear-rate = -100", "[1e-30, 1e+30]"),
    (["steady-shear", "--box-y", "inf"], "--box-y = inf", "[1e-30, 1e+30]"),
    (["steady-shear", "--particles", "0"], "--particles = 0", "[2, 2147483647]"),
    (["shear-start", "-e", "1", "--initial-temperature", "1"], "--restitution = 1", "(0, 1)"),
    (["shear-start", "--initial-temperature", "0"], "--initial-temperature = 0", "[1e-60, 1e+60]"),
    (["shear-start", "--temperature-over-steady", "-2"], "--temperature-over-steady = -2", "(0, 1e+120]"),
    (["shear-start", "--initial-temperature", "1", "--kl", "0"], "--kl = 0", "(0, 1000000]"),
    (["shear-start", "--initial-temperature", "1", "--mode", "-1"], "--mode = -1", "[1, 2147483647]"),
    (["shear-start", "--initial-temperature", "1", "--time-max", "inf"], "--time-max = inf", "(0, 1e+300]"),
    (["shear-start", "--initial-temperature", "1", "--box-y", "0"], "--box-y = 0", "[1e-30, 1e+30]"),
    (["shear-start", "--initial-temperature", "1", "--points", "0"], "--points = 0", "[1, 10000]"),
    # Each option in range, but together beyond double precision: the last guard.
    (["steady-shear", "--area-fraction", "1e-300", "--diameter", "1e30", "--shear-rate", "1e30"],
     "T_fit_3.1 = inf", "beyond double precision"),
]

ACCEPTED = [
    ["haff", "-e", "1e-300", "--area-fraction", "0.9", "--diameter", "1e-30", "--temperature", "1e60", "--points", "1"],
    ["haff", "-e", "0.9999999", "--diameter", "1e30", "--temperature", "1e-60", "--contact-value", "1e30"],
    ["haff", "-e", "0.9", "--collisions", "5263", "--points", "10000", "--csv"],
    ["free-stability", "--eps", "1", "--K-min", "1e-300", "--K-max", "1e6", "--points", "3", "--asymptotic"],
    ["shear-stability", "--sqrt-eps", "1", "--theta-deg", "180", "--delta-min", "0", "--delta-max", "1e6", "--points", "3"],
    ["shear-stability", "-e", "1e-9", "--theta-deg", "0", "--points", "2"],
    ["shear-scales", "-e", "0.999", "--particles", "2", "--box", "1e30", "--shear-rate", "1e-30", "--mode", "1"],
    ["shear-scales", "--particles", "2147483647", "--diameter", "1e-9", "--initial-temperature", "1e60"],
    ["shear-start", "-e", "0.999", "--particles", "2", "--box-x", "1e30", "--box-y", "1e30", "--shear-rate", "1e-30",
     "--initial-temperature", "1e-60", "--points", "2"],
    ["shear-start", "--particles", "2147483647", "--diameter", "1e-9", "--temperature-over-steady", "1e-30", "--kl", "1e6"],
    ["steady-shear", "-e", "0.5", "--shear-rate", "1e30", "--box-x", "1e-30", "--box-y", "1e-30", "--particles", "2"],
]


def numbers(text):
    """Every numeric token of the output (lines of the tables and summaries)."""
    out = []
    for token in text.replace(",", " ").replace("=", " ").split():
        try:
            out.append(float(token))
        except ValueError:
            pass
    return out


for args, option, allowed in REFUSED:
    r = granule("theory", *args)
    where = "granule theory " + " ".join(args)
    check(r.returncode == 2, f"{where}: exit {r.returncode}, expected 2")
    check(option in r.stderr and allowed in r.stderr, f"{where}: message lacks '{option}' or '{allowed}': {r.stderr!r}")
    check(r.stdout == "", f"{where}: printed before refusing: {r.stdout[:200]!r}")

for args in ACCEPTED:
    r = granule("theory", *args)
    where = "granule theory " + " ".join(args)
    check(r.returncode == 0, f"{where}: exit {r.returncode}: {r.stderr}")
    values = numbers(r.stdout)
    check(values and all(math.isfinite(v) for v in values), f"{where}: non-finite output: {r.stdout[:400]!r}")

finish()
