"""Hostile calls of the granule module, for tests/python/test_fuzz_api.py: each must return or raise
a Python exception, never take the interpreter down.  One part a process, so that a crash names its
part; before each call its description is written to the journal (flushed), so that the last line
of a crashed part's journal is the call that crashed it.

    PYTHONPATH=build/release/python /usr/bin/python3 tests/python/api_fuzzer.py --part analysis \\
        --seed 1 --journal /tmp/journal.txt --scratch /tmp/fuzz

prints one JSON line: {"part": …, "counts": {"ok": n, "ValueError": n, …}, "bad": [...]}, where
"bad" lists the calls that raised SystemError (an extension that broke the C API's rules).
"""
import argparse
import collections
import json
import math
import os
import random
import re
import threading
import warnings
from pathlib import Path

import numpy as np

import granule

SMALL = {"seed": 1, "system": {"particles": 60, "packing_fraction": 0.1, "restitution": 0.9},
         "initial": {"equilibrate": 0}, "run": {"until_collisions_per_particle": 1}}


def available_memory_bytes():
    with open("/proc/meminfo") as f:
        for line in f:
            if line.startswith("MemAvailable:"):
                return int(line.split()[1]) * 1024
    return 0


class Tally:
    """Runs calls, counting how each ended; journals each before it is made."""

    def __init__(self, journal):
        self.counts = collections.Counter()
        self.bad = []
        self.journal = open(journal, "w", buffering=1)
        self.lock = threading.Lock()

    def call(self, description, function, *args, **kwargs):
        with self.lock:
            self.journal.write(description[:300].replace("\n", " ") + "\n")
        try:
            result = function(*args, **kwargs)
            outcome = "ok"
        except Exception as error:  # every refusal is a Python exception: that is what is counted
            result = None
            outcome = type(error).__name__
            if os.environ.get("API_FUZZER_VERBOSE"):
                print(f"{outcome}: {str(error)[:160]}  <- {description[:120]}")
            if isinstance(error, SystemError):
                self.bad.append(f"{description[:200]}: {error}")
        with self.lock:
            self.counts[outcome] += 1
        return result


# %% Values of every kind a configuration or an argument may be given.

def self_containing_dict():
    d = {"a": 1}
    d["self"] = d
    return d


def self_containing_list():
    items = [1.0]
    items.append(items)
    return items


def deeply_nested(depth):
    value = 1
    for _ in range(depth):
        value = {"k": value}
    return value


HOSTILE = [
    lambda r: float("nan"), lambda r: float("inf"), lambda r: -float("inf"), lambda r: 1e300, lambda r: -1e300,
    lambda r: 5e-324, lambda r: -0.0, lambda r: 0, lambda r: -1, lambda r: 2**31 - 1, lambda r: 2**31,
    lambda r: 2**63 - 1, lambda r: 2**63, lambda r: -2**63 - 1, lambda r: 2**80, lambda r: 10**400,
    lambda r: True, lambda r: None, lambda r: "", lambda r: "x" * r.randint(1, 50), lambda r: "ü\u2603",
    lambda r: "a\x00b", lambda r: b"bytes", lambda r: object(), lambda r: {1, 2}, lambda r: 1 + 2j,
    lambda r: [], lambda r: [1, "a", None], lambda r: (0.5, 0.5), lambda r: {}, lambda r: {"k": float("nan")},
    lambda r: self_containing_dict(), lambda r: self_containing_list(), lambda r: deeply_nested(r.choice([63, 65, 500])),
    lambda r: [[[[[[1]]]]]] * 3, lambda r: np.int64(r.randint(-5, 500)), lambda r: np.uint64(2**64 - 1),
    lambda r: np.int8(-3), lambda r: np.float32(r.random()), lambda r: np.float16(0.5), lambda r: np.float64("nan"),
    lambda r: np.longdouble("1e4000"), lambda r: np.bool_(r.random() < 0.5), lambda r: np.complex64(1j),
    lambda r: np.str_("fast"), lambda r: np.array(3.0), lambda r: np.arange(3), lambda r: np.datetime64("2020"),
    lambda r: r.uniform(-2, 2), lambda r: r.uniform(0, 1), lambda r: r.randint(1, 300),
]


def hostile(r):
    return r.choice(HOSTILE)(r)


# Keys of the configuration, with values a run of this size takes quickly (a hostile value replaces
# them half the time).  No value here may make a valid run of unbounded cost: the fuzzer measures
# refusals and crashes, not the engine's speed.
PLAUSIBLE = {
    ("seed",): [0, 7, 2**63 - 1],
    ("system", "dimension"): [2, 3],
    ("system", "particles"): [2, 3, 40, 120],
    ("system", "packing_fraction"): [0.01, 0.3, 0.7, 1e-6],
    ("system", "area_fraction"): [0.05],
    ("system", "restitution"): [0.1, 0.5, 0.99, 1.0],
    ("system", "tc_duration"): [0.0, 1e-4],
    ("system", "tangential_restitution"): [-1.0, 0.0, 0.7],
    ("system", "inertia_factor"): [0.4, 1.0],
    ("system", "friction"): [0.0, 0.3],
    ("system", "diameters"): [{"distribution": "bidisperse", "ratio": 2.0, "fraction": 0.5}],
    ("system", "gravity"): [[0.0, -1.0]],
    ("boundary", "kind"): ["periodic", "lees-edwards", "walls"],
    ("boundary", "shear_velocity"): [0.0, 1.0, 10.0],
    # Not a gas nearly at rest: under gravity in a periodic box it would fall for ever without a
    # collision (a run that Ctrl-C stops, but a fuzzer waiting for its collisions would not end).
    ("initial", "temperature"): [1.0, 1e-3, 1e50],
    ("initial", "equilibrate"): [0, 0.5],
    ("initial", "placement"): ["random", "lattice", "auto"],
    ("initial", "from"): ["/nonexistent/snapshots.h5"],
    ("run", "until_collisions_per_particle"): [1, 0.5],
    ("run", "until_time"): [0.01],
    ("output", "every_collisions_per_particle"): [0.5],
    ("engine", "particles_per_cell"): [1, 4],
    ("nonsense", "key"): [1],
}


def magnitude(value):
    """float(value) for a number (inf for one beyond floats), None for anything else."""
    if isinstance(value, bool) or not isinstance(value, (int, float, np.number)):
        return None
    try:
        return float(value)
    except (OverflowError, TypeError, ValueError):
        return math.inf


def random_config(r, huge_runs_refused):
    config = json.loads(json.dumps(SMALL))
    for _ in range(r.randint(1, 3)):
        path = r.choice(list(PLAUSIBLE))
        value = r.choice(PLAUSIBLE[path]) if r.random() < 0.5 else hostile(r)
        if path == ("system", "particles") and isinstance(value, (int, np.integer)) and not isinstance(value, bool):
            # A valid N between those listed and the ones memory refuses would run for long.
            if 120 < value and not (huge_runs_refused and value >= 2**31 - 1):
                value = 120
        if path[-1] in ("equilibrate", "until_collisions_per_particle") and 1.0 < (magnitude(value) or 0.0) < 1e300:
            value = 1.0  # a long pre-run is valid, only slow
        table = config
        for key in path[:-1]:
            if not isinstance(table.get(key), dict):
                table[key] = {}
            table = table[key]
        table[path[-1]] = value
    if r.random() < 0.05:
        key = r.choice([1, None, b"k", (1, 2), 1.5, "", "system.particles", np.int64(3), "system"])
        config[key] = hostile(r)  # a hostile key or table
    return config


# %% The parts.

def part_config(tally, r, scratch):
    huge_runs_refused = available_memory_bytes() < 300 * 2**30  # N = 2^31 − 1 needs ~350 GiB
    for _ in range(700):
        config = random_config(r, huge_runs_refused)
        sim = tally.call(f"Simulation({config!r:.250})", granule.Simulation, config)
        if sim is not None:
            tally.call("run after construction", sim.run, until_collisions_per_particle=sim.collisions_per_particle + 0.5,
                       until_time=sim.time + 10.0)
            tally.call("positions", lambda: sim.positions)
    overrides = ["system.restitution=0.5", "system.particles=abc", "run.until_time=nan", "nonsense", "=", "a.b.c=1",
                 "system.particles=" + "9" * 40, "system.box=[[[[1]]]]", "x=" + "[" * 300, "system.restitution=\x00"]
    for _ in range(60):
        chosen = r.sample(overrides, r.randint(1, 3)) if r.random() < 0.8 else hostile(r)
        tally.call(f"Simulation(SMALL, overrides={chosen!r:.200})", granule.Simulation, SMALL, overrides=chosen)


def part_run(tally, r, scratch):
    sim = granule.Simulation({**SMALL, "system": {"particles": 200, "packing_fraction": 0.1, "restitution": 0.9}})
    n = sim.particles
    for _ in range(350):
        c, t = sim.collisions_per_particle, sim.time
        choices = [
            {"until_collisions_per_particle": c + r.choice([0.01, 0.1, 0.3])},
            {"until_time": t + r.choice([1e-4, 1e-3])},
            {"until_collisions_per_particle": c + 0.1, "until_time": 1e300},
            {"until_collisions_per_particle": r.choice([c, c - 0.1, 0.0, -1.0, float("nan"), float("inf"),
                                                        -float("inf"), 1e300, 2.0**62, 2.0**63 / n, 2**70])},
            {"until_time": r.choice([t, 0.0, -5.0, float("nan"), float("inf"), -float("inf")])},
            {"until_collisions_per_particle": hostile(r)},
            {"until_time": hostile(r), "until_collisions_per_particle": c + 0.05},
            {},
        ]
        kwargs = r.choice(choices)
        if c + 5 < (magnitude(kwargs.get("until_collisions_per_particle")) or 0.0) < 2.0**62 / n:
            kwargs["until_collisions_per_particle"] = c + 0.1  # a valid far target is only slow
        if "until_collisions_per_particle" not in kwargs and t + 1e-3 < (magnitude(kwargs.get("until_time")) or 0.0) < math.inf:
            kwargs["until_time"] = t + 1e-3  # a valid far time is only slow
        tally.call(f"run({kwargs!r})", sim.run, **kwargs)
        if r.random() < 0.2:
            tally.call("positions", lambda: sim.positions)
            tally.call("timeseries_row", lambda: sim.timeseries_row)


def part_threads(tally, r, scratch):
    sim = granule.Simulation({**SMALL, "system": {"particles": 1000, "packing_fraction": 0.1, "restitution": 0.95}})
    other = granule.Simulation({**SMALL, "system": {"particles": 1000, "packing_fraction": 0.1, "restitution": 0.95}})
    operations = {
        "run": lambda s: s.run(until_collisions_per_particle=s.collisions_per_particle + 0.2),
        "positions": lambda s: s.positions, "velocities": lambda s: s.velocities, "time": lambda s: s.time,
        "collisions": lambda s: s.collisions, "summary": lambda s: s.summary(), "timeseries": lambda s: s.timeseries,
        "timeseries_row": lambda s: s.timeseries_row, "config_toml": lambda s: s.config_toml,
        "spins": lambda s: s.spins, "box": lambda s: s.box, "masses": lambda s: s.masses,
        "write_snapshot": lambda s: s.write_snapshot(scratch / f"thread_{threading.get_ident()}.h5"),
        "write_snapshot_shared": lambda s: s.write_snapshot(scratch / "shared.h5"),
    }
    names = sorted(operations)

    def worker(seed, target):
        rr = random.Random(seed)
        for _ in range(100):
            name = rr.choice(names) if rr.random() < 0.6 else "run"
            tally.call(f"thread {name}", operations[name], target)

    # Four threads on one Simulation, then a fifth on another one beside them (its own engine).
    for round_ in range(2):
        threads = [threading.Thread(target=worker, args=(r.random(), sim)) for _ in range(4)]
        threads.append(threading.Thread(target=worker, args=(r.random(), other)))
        for thread in threads:
            thread.start()
        for thread in threads:
            thread.join()
    # run_directory from three threads, two of them into the same directory.
    config = {**SMALL, "system": {"particles": 100, "packing_fraction": 0.1}, "run": {"until_collisions_per_particle": 2}}
    outs = [scratch / "run_a", scratch / "run_b", scratch / "run_a"]
    threads = [threading.Thread(target=tally.call, args=(f"run_directory {out}", granule.run_directory, config, out))
               for out in outs]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()


def random_array(r, rng, shape, scale=1.0):
    kind = r.choice(["bool", "c16", "object", "U3"]) if r.random() < 0.06 else r.choice(["f8"] * 8 + ["f4", "i8", "u1", "list"])
    values = rng.random(shape) * scale
    if kind == "list":
        return values.tolist()
    if kind in ("i8", "u1"):
        return (values * 0).astype(kind)  # zeros: inside any box
    return values.astype(kind)


def poisoned(r, rng, array):
    """A copy of `array` with a NaN, ±inf, negative or huge entry, or a wrong shape, some of the time."""
    if not isinstance(array, np.ndarray) or array.dtype.kind != "f" or array.size == 0 or r.random() < 0.8:
        return array
    out = array.copy()
    choice = r.randrange(6)
    if choice < 4:
        out.flat[r.randrange(out.size)] = [np.nan, np.inf, -1.0, 1e300][choice]
        return out
    return out.ravel() if choice == 4 else out.T


def analysis_arguments(r, rng):
    n = r.choice([0, 1, 2, 7, 100, 500])
    d = r.choice([2, 2, 2, 2, 3, 3, 3, 1, 4])
    box = tuple(r.choice([1.0, 2.0, 0.5]) for _ in range(max(d, 1)))
    positions = poisoned(r, rng, random_array(r, rng, (n, d), scale=min(box)))
    velocities = poisoned(r, rng, random_array(r, rng, (n if r.random() < 0.97 else n + 1, d)))
    if r.random() < 0.07:
        box = r.choice([(np.nan, 1.0), (0.0, 1.0), (-1.0, 1.0), (1e31, 1.0), (1e-30, 1e30), (1.0,), "ab", None,
                        (1.0, 1.0, 1.0, 1.0), np.array(box), [np.inf] * d, hostile(r)])
    kwargs = {}
    if r.random() < 0.3:
        kwargs["masses"] = r.choice([rng.random(n) + 0.5, rng.random(n) + 0.5, None, np.zeros(n), np.full(n, np.nan), rng.random(n + 1),
                                     rng.random((n, 2)), -np.ones(n), "abc", hostile(r)])
    if r.random() < 0.2:
        kwargs["shear_velocity"] = r.choice([0.0, 1.0, -1.0, 2.0, np.nan, np.inf, 1e31, 1e-40, hostile(r)])
    if r.random() < 0.2:
        kwargs["shear_offset"] = r.choice([0.0, 0.5, 1.0, 0.25, -0.1, 2.0, np.nan, 1e300, hostile(r)])
    return positions, velocities, box, kwargs


def part_analysis(tally, r, scratch):
    rng = np.random.default_rng(r.randrange(2**32))
    for _ in range(420):
        positions, velocities, box, kwargs = analysis_arguments(r, rng)
        if r.random() < 0.3:
            d = np.shape(positions)[1] if np.ndim(positions) == 2 else 2
            kwargs["cells"] = r.choice([None, (4,) * d, (1,) * d, (0, 1), (1.5, 2), (2**70, 1), (16384,) * 3, "ab", 5,
                                        (np.int64(3),) * d, (16384, 16384, 16384), hostile(r)])
        if r.random() < 0.5:
            kwargs["subtract_shear_profile"] = r.random() < 0.5
        tally.call(f"cell_fields({np.shape(positions)}, {kwargs!r:.200})", granule.cell_fields, positions, velocities,
                   box, **kwargs)
    for _ in range(420):
        positions, velocities, box, kwargs = analysis_arguments(r, rng)
        if r.random() < 0.6:
            kwargs["max_mode"] = r.choice([1, 2, 8, 16, 4, 8, 0, -1, 2049, 2**40, 1.5, "8", np.int64(4), None])
        if r.random() < 0.3:
            kwargs["method"] = r.choice(["fast", "exact", "fast", "exact", "slow", "", 5])
        if r.random() < 0.3:
            kwargs["dk"] = r.choice([None, 0.5, 2.0, 1e300, 1e-300, 0.0, -1.0, np.nan, np.inf, hostile(r)])
        for flag in ("subtract_shear_profile", "exclude_ky_axis"):
            if r.random() < 0.2:
                kwargs[flag] = r.random() < 0.5
        tally.call(f"spectra({np.shape(positions)}, {kwargs!r:.200})", granule.spectra, positions, velocities, box,
                   **kwargs)
    for _ in range(300):
        positions, velocities, box, kwargs = analysis_arguments(r, rng)
        kwargs.pop("masses", None)
        kwargs.pop("shear_velocity", None)
        n = np.shape(positions)[0] if np.ndim(positions) >= 1 else 0
        d = np.shape(positions)[1] if np.ndim(positions) == 2 else 2
        spins = r.choice([rng.normal(size=n), rng.normal(size=(n, 3)), rng.normal(size=(n, d)), rng.normal(size=n + 1),
                          np.full(n, np.nan), None, "ab", hostile(r)])
        if r.random() < 0.3:
            kwargs["diameters"] = r.choice([rng.random(n) * 0.05 + 0.01, np.zeros(n), np.full(n, np.inf), rng.random(n + 1),
                                            np.full(n, 1e300), hostile(r)])
        if r.random() < 0.3:
            kwargs["diameter"] = r.choice([0.01, 0.1, 0.0, -1.0, np.nan, 1e300, 1e-300, hostile(r)])
        if r.random() < 0.3:
            kwargs["walls"] = r.choice([(True,) * d, (False, True), (True, False, True), (1, 0), "ab", (None,) * d, hostile(r)])
        if r.random() < 0.3:
            kwargs["max_distance"] = r.choice([3.0, 1.0, 1.05, 100.0, 1e300, np.nan, -2.0, hostile(r)])
        if r.random() < 0.3:
            kwargs["bins"] = r.choice([1, 20, 0, -1, 100001, 2**70, 2.5, hostile(r)])
        if r.random() < 0.2:
            kwargs["contact_shell"] = r.choice([0.1, 0.0, -0.1, 5.0, np.nan, np.inf, hostile(r)])
        tally.call(f"spin_correlation({np.shape(positions)}, {kwargs!r:.200})", granule.spin_correlation, positions, spins,
                   box, **kwargs)
    # Sizes that must be refused before anything is allocated: views of 2^40 particles, 2^42 cells.
    huge = np.broadcast_to(np.zeros(2), (2**40, 2))
    for _ in range(10):
        tally.call("cell_fields(2^40 particles)", granule.cell_fields, huge, huge, (1.0, 1.0))
        tally.call("spectra(2^40 particles)", granule.spectra, huge, huge, (1.0, 1.0))
        tally.call("cell_fields(16384^3 cells)", granule.cell_fields, np.zeros((3, 3)), np.zeros((3, 3)),
                   (1.0, 1.0, 1.0), cells=(16384, 16384, 16384))


def arity(function):
    """The number of parameters in a pybind11 function's signature line."""
    first = (function.__doc__ or "").splitlines()[0] if function.__doc__ else ""
    inside = first[first.find("(") + 1:]
    depth, count, seen = 0, 0, False
    for ch in inside:
        if ch in "([":
            depth += 1
        elif ch in ")]":
            if depth == 0:
                break
            depth -= 1
        elif ch == "," and depth == 0:
            count += 1
        elif not ch.isspace():
            seen = True
    return count + 1 if seen else 0


def part_theory(tally, r, scratch):
    functions = [getattr(granule.theory, name) for name in sorted(dir(granule.theory)) if not name.startswith("_")]
    functions = [f for f in functions if callable(f)]
    rng = np.random.default_rng(r.randrange(2**32))
    pool = [lambda: r.choice([2, 3]), lambda: r.uniform(0.01, 1.0), lambda: r.uniform(-10, 10),
            lambda: rng.random(r.choice([0, 1, 5])), lambda: rng.random((2, 3)), lambda: np.array([np.nan, np.inf]),
            lambda: hostile(r), lambda: r.choice([7, -2**31, 0, 2**63])]
    for _ in range(400):
        function = r.choice(functions)
        count = max(0, arity(function) + (0 if r.random() < 0.85 else r.choice([-1, 1])))
        args = [r.choice(pool)() for _ in range(count)]
        tally.call(f"theory.{function.__name__}{tuple(args)!r:.200}", function, *args)


def part_paths(tally, r, scratch):
    garbage = scratch / "garbage.toml"
    garbage.write_bytes(bytes(r.randrange(256) for _ in range(2000)))
    good = scratch / "good.toml"
    good.write_text("seed = 3\n[system]\nparticles = 50\n[initial]\nequilibrate = 0\n")
    unreadable = scratch / "unreadable.toml"
    unreadable.write_text(good.read_text())
    unreadable.chmod(0)
    fifo = scratch / "fifo"
    os.mkfifo(fifo)
    not_hdf5 = scratch / "not_hdf5.h5"
    not_hdf5.write_text("plain text")
    paths = [scratch / "missing.toml", scratch, Path("/dev/null"), fifo, garbage, good, unreadable, str(good),
             os.fsencode(good), "a\x00b", 5, None, [good], scratch / "missing" / "x.toml"]
    for path in paths * 3:
        tally.call(f"Simulation({path!r})", granule.Simulation, path)
    sim3 = granule.Simulation({**SMALL, "system": {"dimension": 3, "particles": 60, "packing_fraction": 0.1}})
    sim2 = granule.Simulation(good)
    targets = [scratch / "frames.h5", scratch, scratch / "missing" / "f.h5", not_hdf5, garbage, 5, None, "a\x00b"]
    for target in targets * 2:
        for sim in (sim2, sim3):  # a 3D frame appended to a 2D file too
            tally.call(f"write_snapshot({target!r})", sim.write_snapshot, target)
    for source in [scratch / "frames.h5", scratch / "missing.h5", scratch, not_hdf5, garbage]:
        tally.call(f"write_gsd({source!r})", granule.write_gsd, source, scratch / "out.gsd")
    # An object whose __init__ never ran, methods called on other types, __init__ run twice.
    blank = granule.Simulation.__new__(granule.Simulation)
    for name in ("time", "positions", "summary", "run", "write_snapshot", "timeseries", "config_toml"):
        tally.call(f"blank.{name}", getattr, blank, name)
    tally.call("Simulation.run(5)", granule.Simulation.run, 5)
    tally.call("Simulation.time.fget(None)", granule.Simulation.time.fget, None)
    tally.call("blank.run()", lambda: blank.run())
    tally.call("blank.summary()", lambda: blank.summary())
    tally.call("sim.__init__ again", sim2.__init__, SMALL)
    tally.call("run_directory(bad config)", granule.run_directory, {"system": {"particles": -1}}, scratch / "rd")
    tally.call("run_directory(overrides str)", granule.run_directory, SMALL, scratch / "rd2", "system.particles=5")
    tally.call("run_directory(out is a file)", granule.run_directory, SMALL, garbage)
    if available_memory_bytes() < 300 * 2**30:  # N = 2^31 − 1 needs ~350 GiB: refused before it starts
        tally.call("run_directory(huge)", granule.run_directory, {"system": {"particles": 2**31 - 1}}, scratch / "rd3")


PARTS = {"config": part_config, "run": part_run, "threads": part_threads, "analysis": part_analysis,
         "theory": part_theory, "paths": part_paths}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--part", choices=sorted(PARTS), required=True)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--journal", required=True)
    parser.add_argument("--scratch", required=True)
    args = parser.parse_args()
    warnings.simplefilter("ignore")  # NumPy's warnings on NaN and casts: the outcomes are what is counted
    scratch = Path(args.scratch)
    scratch.mkdir(parents=True, exist_ok=True)
    tally = Tally(args.journal)
    PARTS[args.part](tally, random.Random(f"{args.part}:{args.seed}"), scratch)
    print(json.dumps({"part": args.part, "counts": dict(tally.counts), "bad": tally.bad}), flush=True)


if __name__ == "__main__":
    main()
