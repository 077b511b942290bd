"""`granule theory shear-start`: the early-time temperature of a hot or cold start under shear
(thesis (4.26)-(4.30)) and its clustering window ((4.37), (4.39)-(4.40)).  Checks the command's
plumbing against numbers computed here from the thesis's definitions: T(0) = T_i, T0 of (4.5),
the hot/cold regime and window, --temperature-over-steady, and a run config read with --config
(options override it); bad input exits 2 with nothing on stdout."""
import csv
import io
import math
import re

from harness import WORK, check, finish, granule


def curve(r):
    rows = list(csv.DictReader(io.StringIO(r.stdout)))
    return {key: [float(row[key]) for row in rows] for key in rows[0]}


def close(a, b, rel):
    return abs(a - b) <= rel * abs(b)


def steady_temperature(e, nu, particles, box_x, box_y, gamma):
    """T0 = l²γ²/(πε) (4.5), l = πσ/8ν, σ from ν = πNσ²/(4 Lx Ly)."""
    sigma = math.sqrt(4 * nu * box_x * box_y / (math.pi * particles))
    l = math.pi * sigma / (8 * nu)
    return l * l * gamma * gamma / (math.pi * (1 - e * e))


T0 = steady_temperature(0.6, 0.05, 20000, 1.0, 1.0, 100.0)  # the defaults: Fig. 4.5's system

# A hot start: T_i = 1e6 ≈ 1e6 T0, h ≈ 400 > γ = 100 at kl = √ε.
hot = granule("theory", "shear-start", "--initial-temperature", "1e6", "--csv")
check(hot.returncode == 0, f"hot start: exit {hot.returncode}: {hot.stderr}")
c = curve(hot)
check(list(c) == ["t", "strain", "A_4.29", "T_4.28", "T_4.26"], f"columns {list(c)}")
check(len(c["t"]) == 21 and c["t"][0] == 0.0, "21 rows from t = 0")
check(close(c["T_4.26"][0], 1e6, 1e-9) and close(c["T_4.28"][0], 1e6, 1e-9), "T(0) = T_i")
check(all(close(s, 100.0 * t, 1e-9) for s, t in zip(c["strain"][1:], c["t"][1:])), "strain = γt")
check(all(b < a for a, b in zip(c["T_4.26"], c["T_4.26"][1:])), "a hot start cools monotonically")
check(all(close(T, A * c["T_4.28"][-1] / c["A_4.29"][-1], 1e-8) for T, A in zip(c["T_4.28"], c["A_4.29"])),
      "T_4.28 = T_sat A(t)")

table = granule("theory", "shear-start", "--initial-temperature", "1e6")
check(table.returncode == 0, f"hot start table: exit {table.returncode}")
check("hot start" in table.stdout and "clustering window (4.37)" in table.stdout and ": open;" in table.stdout,
      f"hot start: regime or window missing: {table.stdout}")
match = re.search(r"T0 = l\^2 gamma\^2/\(pi eps\) \(4\.5\) (\S+)", table.stdout)
check(match and close(float(match.group(1)), T0, 1e-5), f"T0 of (4.5): {match and match.group(1)} vs {T0}")
match = re.search(r"gamma/h (\S+):", table.stdout)
# h = k√(T_i/N) with kl = √ε: k = √ε/l.
sigma = math.sqrt(4 * 0.05 / (math.pi * 20000))
h = math.sqrt(1 - 0.36) / (math.pi * sigma / (8 * 0.05)) * math.sqrt(1e6 / 20000)
check(match and close(float(match.group(1)), 100.0 / h, 1e-5), f"gamma/h: {match and match.group(1)} vs {100 / h}")

# A cold start below T0: γ/h > 1, the window (4.39)-(4.40) is empty, T rises.
cold = granule("theory", "shear-start", "--temperature-over-steady", "0.5")
check(cold.returncode == 0, f"cold start: exit {cold.returncode}: {cold.stderr}")
check("cold start" in cold.stdout and "(4.39)-(4.40)" in cold.stdout and "empty (no clustering at early times)" in cold.stdout,
      f"cold start: regime or window missing: {cold.stdout}")
cold_curve = curve(granule("theory", "shear-start", "--temperature-over-steady", "0.5", "--csv"))
check(close(cold_curve["T_4.26"][0], 0.5 * T0, 1e-9), f"T_i = 0.5 T0: {cold_curve['T_4.26'][0]} vs {0.5 * T0}")
check(all(b > a for a, b in zip(cold_curve["T_4.26"], cold_curve["T_4.26"][1:])), "a cold start heats monotonically")

# --kl and --mode choose k; the window then says whether that wavenumber clusters.
inside = granule("theory", "shear-start", "--initial-temperature", "1e6", "--kl", "0.5")
check("k l = 0.5 (--kl)" in inside.stdout and "inside: clusters" in inside.stdout, f"--kl 0.5: {inside.stdout}")
mode = granule("theory", "shear-start", "--initial-temperature", "1e6", "--mode", "3")
check(re.search(r"k l = (\S+) \(mode n = 3\)", mode.stdout) and
      close(float(re.search(r"k l = (\S+) \(mode", mode.stdout).group(1)), 2 * math.pi * 3 * math.pi * sigma / 0.4, 1e-5),
      f"--mode 3: {mode.stdout}")

# --config: the system of a run config gives the same curve as the same numbers as options.
config = WORK / "sheared.toml"
config.write_text('[system]\nparticles = 5000\narea_fraction = 0.1\nrestitution = 0.8\nbox = [1.0, 2.0]\n'
                  '[boundary]\nkind = "lees-edwards"\nshear_velocity = 100.0\n[initial]\ntemperature = 2e5\n')
from_config = granule("theory", "shear-start", "--config", config, "--csv")
from_options = granule("theory", "shear-start", "-e", "0.8", "--area-fraction", "0.1", "--particles", "5000",
                       "--box-x", "1", "--box-y", "2", "--shear-rate", "50", "--initial-temperature", "2e5", "--csv")
check(from_config.returncode == 0 and from_options.returncode == 0, f"config: {from_config.stderr} {from_options.stderr}")
a, b = curve(from_config), curve(from_options)
check(all(close(x, y, 1e-9) for key in a for x, y in zip(a[key], b[key])), "--config equals the same options")
# An option overrides the config.
over = curve(granule("theory", "shear-start", "--config", config, "-e", "0.9", "--temperature-over-steady", "20", "--csv"))
flags = curve(granule("theory", "shear-start", "-e", "0.9", "--area-fraction", "0.1", "--particles", "5000",
                      "--box-x", "1", "--box-y", "2", "--shear-rate", "50", "--temperature-over-steady", "20", "--csv"))
check(all(close(x, y, 1e-9) for key in over for x, y in zip(over[key], flags[key])), "options override --config")

# Bad input: exit 2, a message naming what to change, nothing on stdout.
periodic = WORK / "periodic.toml"
periodic.write_text("[system]\nparticles = 1000\n")
elastic = WORK / "elastic.toml"
elastic.write_text('[system]\nrestitution = 1.0\n[boundary]\nkind = "lees-edwards"\nshear_velocity = 1.0\n')
REFUSED = [
    (["--config", periodic], "give --shear-rate"),
    (["--config", elastic], "--restitution (system.restitution in"),
    (["--config", WORK / "missing.toml"], "cannot read the config file"),
    ([], "give the start: --initial-temperature"),
    (["--initial-temperature", "1", "--temperature-over-steady", "2"], "excludes"),
    (["--initial-temperature", "1", "--kl", "0.5", "--mode", "2"], "excludes"),
    (["--temperature-over-steady", "1e100"], "T_i = --temperature-over-steady * T0"),
]
for args, fragment in REFUSED:
    r = granule("theory", "shear-start", *args)
    where = "shear-start " + " ".join(map(str, args))
    check(r.returncode == 2, f"{where}: exit {r.returncode}, expected 2")
    check(fragment in r.stderr, f"{where}: message lacks {fragment!r}: {r.stderr!r}")
    check(r.stdout == "", f"{where}: printed before refusing: {r.stdout[:200]!r}")

finish()
