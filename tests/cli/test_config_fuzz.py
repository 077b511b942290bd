"""Seeded config fuzzing through the real `granule run`: mutations of three small valid
configurations (deleted keys, hostile values, wrong types, unknown keys, broken TOML, bad --set
overrides), each run with a timeout (a hang is a failure).  An invalid configuration must exit 2
and leave its --out directory uncreated; a valid one must exit 0 (or 3 on inelastic collapse)
with complete outputs.  The value pool holds invalid values and cheap valid ones only: the
parse-level tier (tests/unit/test_config_fuzz.cpp) covers the rest, including run.until_time,
whose large valid values ask for arbitrarily long runs, and deleting system.particles (4000)."""
import json
import random
import subprocess
import time

from harness import GRANULE, WORK, check, finish

MUTATIONS = 240
TIMEOUT = 20  # seconds per run; the runs take well under one

BASES = {
    "periodic": {
        "": {"seed": "3"},
        "system": {"particles": "200", "area_fraction": "0.05", "restitution": "0.8"},
        "run": {"until_collisions_per_particle": "2"},
        "output": {"every_collisions_per_particle": "0.5", "snapshot_every_collisions_per_particle": "1"},
    },
    "lees_edwards": {
        "system": {"particles": "300", "area_fraction": "0.1", "box": "[1.0, 1.5]", "restitution": "0.8",
                   "tc_duration": "1e-6"},
        "boundary": {"kind": '"lees-edwards"', "shear_velocity": "20.0"},
        "initial": {"temperature": "2.0", "equilibrate": "1"},
        "run": {"until_collisions_per_particle": "3"},
        "output": {"every_time": "0.01", "snapshot_every_collisions_per_particle": "1.5"},
        "engine": {"particles_per_cell": "1.5"},
        "fields": {"subtract_shear_profile": "true"},
    },
    "measurements": {
        "system": {"particles": "400", "diameter": "0.01", "restitution": "0.9"},
        "run": {"until_collisions_per_particle": "3"},
        "output": {"every_collisions_per_particle": "0.5", "snapshot_every_time": "0.1"},
        "diagnostics": {"cells": "[8, 8]"},
        "fields": {"cells": "[10, 12]", "every_collisions_per_particle": "1"},
        "collisions": {"free_paths": "true", "window_collisions_per_particle": "0.5",
                       "from_collisions_per_particle": "1", "density_windows": "[[0, 300], [300, 1e9]]",
                       "speed_windows": "[[0, 1], [1, 1e3]]", "impact_bins": "20", "length_bins": "50",
                       "angle_bins": "36", "max_length": "0.5"},
    },
}

KEYS = {
    "": ["seed"],
    "system": ["particles", "area_fraction", "diameter", "box", "restitution", "tc_duration", "gravity",
               "tangential_restitution", "inertia_factor", "friction"],
    "boundary": ["kind", "shear_velocity", "wall_axes", "wall_restitution", "wall_tangential_restitution"],
    "initial": ["temperature", "equilibrate", "placement"],
    "run": ["until_collisions_per_particle"],
    "output": ["every_collisions_per_particle", "every_time", "snapshot_every_collisions_per_particle",
               "snapshot_every_time"],
    "engine": ["particles_per_cell", "cells"],
    "diagnostics": ["cells"],
    "fields": ["enabled", "cells", "every_collisions_per_particle", "every_time", "subtract_shear_profile"],
    "collisions": ["impact_parameters", "free_paths", "window_collisions_per_particle", "from_collisions_per_particle",
                   "density_windows", "speed_windows", "impact_bins", "length_bins", "angle_bins", "max_length"],
}
PATHS = [f"{s}.{k}" if s else k for s, keys in KEYS.items() for k in keys]

VALUES = ["nan", "inf", "-inf", "0", "-0.0", "-1", "1e308", "-1e308", "1e-308", "9223372036854775807",
          "2147483648", "99999999999999999999", "0.5", "1", "2", "3", "1e30", "1e-30", "1e300", '"text"', "true",
          '"lees-edwards"', '"lattice"', "[]", "[1.0]", "[1.0, 2.0, 3.0]", "[nan, 1.0]", "[1.0, 1e-300]",
          "[[nan, 1.0]]", "[[2.0, 1.0]]", "[[0, 1e300]]", "[3, 3]", "[40000, 40000]", "{ a = 1 }", "1979-05-27"]
# Plausible values, accepted for many keys, so that valid runs are well represented.
PLAUSIBLE = ["0.5", "1", "2", "3", "0.9", "1e-6", "1e6", "1e10", "1e-60", "1e60", "0.0025", "true", "false",
             '"random"', '"lattice"', '"periodic"', '"lees-edwards"', "[3, 3]", "[2.0, 1.0]", "[[0, 1e300]]",
             "[[0.5, 1.5]]"]
# Valid collision targets above 3 per particle ask for long runs, not for a test: re-drawn.
LONG_RUN_KEYS = {"run.until_collisions_per_particle", "initial.equilibrate"}
BAD_SETS = ["=1", "system.restitution", "system.=1", ".x=1", "a.b.c=1", "system.restitution=[", "system=1",
            "seed.x=1", "system.particles=1\nseed=2", "system.box=[1,", "==", "run.until_collisions_per_particle=1e300",
            "boundary.shear_velocity=1e300", "initial.temperature=1e308"]


def serialise(config):
    lines = [f"{k} = {v}" for k, v in config.get("", {}).items()]
    for section, keys in config.items():
        if section:
            lines.append(f"[{section}]")
            lines += [f"{k} = {v}" for k, v in keys.items()]
    return "\n".join(lines) + "\n"


def value_for(rng, path):
    while True:
        value = rng.choice(PLAUSIBLE) if rng.random() < 0.6 else rng.choice(VALUES)
        try:
            long_run = path in LONG_RUN_KEYS and 3 < float(value) <= 1e18
        except ValueError:
            long_run = False
        if not long_run:
            return value


def mutate(rng, config, log):
    """One structural edit: delete a key, give it a pool value, or add an unknown key or section."""
    roll = rng.random()
    if roll < 0.08:
        section = rng.choice(["system", "nosuch", ""])
        config.setdefault(section, {})["colour"] = rng.choice(VALUES)
        log.append(f"unknown key {section}.colour")
        return
    path = rng.choice(PATHS)
    section, _, key = path.rpartition(".")
    if roll < 0.3 and path != "system.particles":
        config.get(section, {}).pop(key, None)
        log.append(f"delete {path}")
    else:
        value = value_for(rng, path)
        config.setdefault(section, {})[key] = value
        log.append(f"{path} = {value}")


def break_text(rng, text, log):
    at = rng.randrange(len(text))
    kind = rng.randrange(4)
    if kind == 0:
        line = text[text.rfind("\n", 0, at) + 1:].split("\n")[0]
        log.append(f"duplicate line {line!r}")
        return text.replace(line, line + "\n" + line, 1)
    if kind == 1:
        log.append(f"delete char {at}")
        return text[:at] + text[at + 1:]
    if kind == 2:
        log.append(f"insert char at {at}")
        return text[:at] + rng.choice("[]=\"'{}#\n.,x0-") + text[at:]
    log.append(f"truncate at {at}")
    return text[:at]


rng = random.Random(1995)
outcomes = {}
slowest = (0.0, "")
start = time.monotonic()
for i in range(MUTATIONS):
    base = list(BASES)[i % len(BASES)]
    config = json.loads(json.dumps(BASES[base]))
    log = [base]
    for _ in range(1 + rng.randrange(2)):
        mutate(rng, config, log)
    text = serialise(config)
    if rng.random() < 0.15:
        text = break_text(rng, text, log)
    overrides = []
    if rng.random() < 0.25:
        paths = [rng.choice(PATHS) for _ in range(1 + rng.randrange(2))]
        overrides = [rng.choice(BAD_SETS) if rng.random() < 0.4 else f"{p}={value_for(rng, p)}" for p in paths]
        log += [f"--set {o!r}" for o in overrides]
    path = WORK / f"case{i}.toml"
    path.write_text(text)
    out = WORK / f"case{i}"
    command = [GRANULE, "run", str(path), "--out", str(out)] + [a for o in overrides for a in ("--set", o)]
    where = f"case {i}: {'; '.join(log)}"
    t0 = time.monotonic()
    try:
        r = subprocess.run(command, capture_output=True, text=True, timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        check(False, f"{where}: no result after {TIMEOUT} s (hang)")
        outcomes["hang"] = outcomes.get("hang", 0) + 1
        continue
    seconds = time.monotonic() - t0
    slowest = max(slowest, (seconds, where))
    outcomes[r.returncode] = outcomes.get(r.returncode, 0) + 1
    if r.returncode == 2:
        check("error" in r.stderr, f"{where}: exit 2 without a message")
        check(not out.exists(), f"{where}: refused, but created {out}")
    elif r.returncode in (0, 3):
        complete = all((out / name).is_file() for name in ("config.toml", "timeseries.csv", "summary.json", "snapshots.h5"))
        check(complete, f"{where}: exit {r.returncode} with incomplete outputs: {sorted(p.name for p in out.iterdir())}")
    else:
        check(False, f"{where}: exit {r.returncode}: {r.stderr.strip()[-400:]}")

print(f"config fuzz through granule run: {MUTATIONS} mutations in {time.monotonic() - start:.1f} s; "
      f"outcomes (exit code: count) {outcomes}; slowest {slowest[0]:.2f} s ({slowest[1]})")
finish()
