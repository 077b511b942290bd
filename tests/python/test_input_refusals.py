"""What the module refuses, and how: each refusal a Python exception of the kind Python code expects,
whose message names the argument or key, the value and what is allowed (the fuzzer,
test_fuzz_api.py, shows that nothing crashes; this file pins the behaviour)."""
import os
import threading

import numpy as np
import pytest

import granule

FAST = {"seed": 1, "system": {"particles": 100, "packing_fraction": 0.1, "restitution": 0.9},
        "initial": {"equilibrate": 0}, "run": {"until_collisions_per_particle": 1}}


def with_system(**system):
    return {**FAST, "system": {**FAST["system"], **system}}


# %% Configurations given as dicts

def test_a_dict_that_contains_itself_is_refused_by_key():
    inner = {"particles": 100}
    inner["loop"] = inner
    with pytest.raises(ValueError, match=r"system\.loop: the dict contains itself"):
        granule.Simulation({"system": inner})
    items = [0.0]
    items.append(items)
    with pytest.raises(ValueError, match=r"boundary\.shear_history\[1\]: the list contains itself"):
        granule.Simulation({"boundary": {"shear_history": items}})


def test_nesting_deeper_than_64_levels_is_refused():
    value = 1
    for _ in range(100):
        value = {"k": value}
    with pytest.raises(ValueError, match="nested deeper than 64 levels"):
        granule.Simulation({"system": value})


def test_numpy_scalars_are_the_numbers_they_hold():
    config = {"seed": np.int64(1), "system": {"particles": np.uint16(100), "packing_fraction": np.float32(0.1),
                                               "restitution": np.float64(0.9)},
              "initial": {"equilibrate": np.int8(0), "shear_profile": np.bool_(False)}}
    sim = granule.Simulation(config)
    assert sim.particles == 100
    assert np.array_equal(sim.positions, granule.Simulation(FAST).positions)


@pytest.mark.parametrize("value, error, words", [
    (2**80, OverflowError, "seed: an integer of 81 bits"),
    (np.uint64(2**64 - 1), OverflowError, "seed: an integer of 64 bits"),
    (object(), TypeError, "seed: a value of type object"),
    (np.complex64(1), TypeError, "seed: a value of type complex64"),
    (np.arange(3), TypeError, "seed: a value of type ndarray"),
])
def test_values_toml_cannot_hold_are_refused_by_key(value, error, words):
    with pytest.raises(error, match=words):
        granule.Simulation({**FAST, "seed": value})


def test_keys_must_be_strings():
    with pytest.raises(TypeError, match="system: keys must be strings, not int"):
        granule.Simulation({"system": {1: 2}})


def test_a_run_larger_than_the_memory_is_refused_before_it_starts(tmp_path):
    with open("/proc/meminfo") as f:
        available = next(int(line.split()[1]) * 1024 for line in f if line.startswith("MemAvailable:"))
    if available > 300 * 2**30:
        pytest.skip("this machine could hold a run of 2^31 − 1 disks")
    with pytest.raises(MemoryError, match=r"a run of N = 2147483647 needs about .* GiB of memory, but .* GiB are"):
        granule.Simulation(with_system(particles=2**31 - 1))
    with pytest.raises(MemoryError):
        granule.run_directory(with_system(particles=2**31 - 1), tmp_path / "run")


# %% Configurations given as paths

def test_paths_are_refused_as_open_refuses_them(tmp_path):
    with pytest.raises(FileNotFoundError):
        granule.Simulation(tmp_path / "missing.toml")
    with pytest.raises(IsADirectoryError):
        granule.Simulation(tmp_path)
    with pytest.raises(granule.ConfigError, match="not a regular file"):
        granule.Simulation("/dev/null")
    with pytest.raises(TypeError, match="config must be a dict or the path of a TOML file"):
        granule.Simulation(5)
    good = tmp_path / "good.toml"
    good.write_text("[system]\nparticles = 100\n[initial]\nequilibrate = 0\n")
    for path in (good, str(good), os.fsencode(good)):
        assert granule.Simulation(path).particles == 100
    if os.geteuid() != 0:  # root reads any file
        good.chmod(0)
        with pytest.raises(PermissionError):
            granule.Simulation(good)


# %% run() targets

@pytest.mark.parametrize("kwargs, words", [
    ({"until_collisions_per_particle": float("nan")}, r"until_collisions_per_particle = nan: must be a number of collisions per particle in \[0.01, "),
    ({"until_collisions_per_particle": float("inf")}, "until_collisions_per_particle = inf"),
    ({"until_collisions_per_particle": -1}, "until_collisions_per_particle = -1"),
    ({"until_collisions_per_particle": 1e300}, r"to 2\^62 collisions"),
    ({"until_time": 0}, r"until_time = 0: must be a time in \(0, ∞\)"),
    ({"until_time": float("nan")}, "until_time = nan"),
    ({"until_time": -5}, "until_time = -5"),
    ({"until_time": float("-inf")}, "until_time = -inf"),
])
def test_run_targets_outside_the_engines_range_are_refused(kwargs, words):
    sim = granule.Simulation(FAST)
    with pytest.raises(ValueError, match=words):
        sim.run(**kwargs)
    assert sim.collisions == 0


def test_a_target_reached_already_is_refused_with_the_present_value():
    sim = granule.Simulation(FAST)
    sim.run(until_collisions_per_particle=0.5)
    with pytest.raises(ValueError, match=r"until_collisions_per_particle = 0.5 is reached already: the run is at c = 0.5"):
        sim.run(until_collisions_per_particle=0.5)
    with pytest.raises(ValueError, match=r"until_time = .* is reached already: the run is at t = "):
        sim.run(until_time=sim.time)
    sim.run()  # the configuration's c = 1
    with pytest.raises(ValueError, match=r"the configuration's run.until_collisions_per_particle = 1 is reached"):
        sim.run()


def test_the_limits_given_replace_the_configurations():
    sim = granule.Simulation(FAST)  # run.until_collisions_per_particle = 1
    sim.run(until_collisions_per_particle=0.2)
    t = sim.time
    while sim.collisions_per_particle <= 1.0:
        t *= 2
        assert sim.run(until_time=t) == "time reached"
    assert sim.time == t


# %% One Simulation, several threads

def test_a_simulation_used_from_another_thread_while_it_runs_raises(small_config):
    sim = granule.Simulation({**small_config, "system": {**small_config["system"], "particles": 4000}})
    outcomes, lock = [], threading.Lock()

    def work(index):
        for _ in range(20):
            try:
                if index % 2 == 0:
                    sim.run(until_collisions_per_particle=sim.collisions_per_particle + 0.5)
                else:
                    sim.positions, sim.summary(), sim.timeseries
                outcome = "ok"
            except RuntimeError as error:
                assert "Simulation is being run from another thread" in str(error)
                outcome = "refused"
            except ValueError as error:  # another thread reached the target first
                assert "is reached already" in str(error)
                outcome = "reached"
            with lock:
                outcomes.append(outcome)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(4)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert len(outcomes) == 80 and "ok" in outcomes and "refused" in outcomes
    # The engine is consistent after it all: it runs on, and its arrays are whole.
    sim.run(until_collisions_per_particle=sim.collisions_per_particle + 0.1)
    assert np.all(np.isfinite(sim.positions))


def test_an_uninitialised_simulation_is_refused():
    blank = granule.Simulation.__new__(granule.Simulation)
    with pytest.raises(TypeError, match="never initialised"):
        blank.positions
    with pytest.raises(TypeError, match="never initialised"):
        blank.run()
    with pytest.raises(TypeError, match="called on a int"):
        granule.Simulation.run(5)


def test_run_directories_in_threads_run_side_by_side_each_in_its_own_directory(tmp_path):
    config = {**FAST, "run": {"until_collisions_per_particle": 2}}
    results = {}

    def work(name, out):
        try:
            results[name] = granule.run_directory(config, out)["c"]
        except (RuntimeError, FileExistsError) as error:
            results[name] = type(error).__name__

    outs = {"a": tmp_path / "a", "b": tmp_path / "b", "a again": tmp_path / "a"}
    threads = [threading.Thread(target=work, args=item) for item in outs.items()]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert results["b"] == 2.0
    assert sorted(map(str, (results["a"], results["a again"]))) in (["2.0", "RuntimeError"], ["2.0", "FileExistsError"])


def test_a_frame_of_another_system_is_not_appended_and_the_file_is_kept(tmp_path):
    path = tmp_path / "frames.h5"
    granule.Simulation(FAST).write_snapshot(path)
    with pytest.raises(ValueError, match="holds snapshots of another system"):
        granule.Simulation(with_system(particles=120)).write_snapshot(path)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["frames.h5"]


# %% Analyses

@pytest.fixture
def configuration():
    rng = np.random.default_rng(3)
    return rng.random((200, 2)), rng.normal(size=(200, 2))


@pytest.mark.parametrize("analysis", [granule.cell_fields, granule.spectra])
@pytest.mark.parametrize("bad", [np.nan, np.inf, -0.5, 1.5])
def test_positions_must_be_finite_and_inside_the_box(configuration, analysis, bad):
    positions, velocities = configuration
    positions = positions.copy()
    positions[17, 1] = bad
    with pytest.raises(ValueError, match=rf"positions\[17, 1\] = {bad}: positions must be finite and inside the box"):
        analysis(positions, velocities, (1.0, 1.0))


@pytest.mark.parametrize("analysis", [granule.cell_fields, granule.spectra])
def test_arrays_of_the_wrong_dtype_or_shape_are_refused(configuration, analysis):
    positions, velocities = configuration
    with pytest.raises(TypeError, match="positions must hold real numbers"):
        analysis(positions.astype(complex), velocities, (1.0, 1.0))
    with pytest.raises(TypeError, match="velocities must hold real numbers"):
        analysis(positions, velocities.astype(object), (1.0, 1.0))
    with pytest.raises(ValueError, match="positions must be an N × 2 or N × 3 array"):
        analysis(positions[:, :1], velocities, (1.0, 1.0))
    with pytest.raises(ValueError, match="velocities must have the shape of positions"):
        analysis(positions, velocities[:10], (1.0, 1.0))
    with pytest.raises(ValueError, match=r"velocities\[3, 0\] = nan"):
        v = velocities.copy()
        v[3, 0] = np.nan
        analysis(positions, v, (1.0, 1.0))
    with pytest.raises(ValueError, match=r"masses\[0\] = 0"):
        analysis(positions, velocities, (1.0, 1.0), masses=np.zeros(200))
    for box in ((np.nan, 1.0), (0.0, 1.0), (1.0,), (1e-30, 1e30)):
        with pytest.raises(ValueError, match="box"):
            analysis(positions, velocities, box)
    # Lists and integer arrays are numbers too.
    analysis(positions.tolist(), (velocities * 10).astype(np.int32), [1.0, 1.0])


def test_sizes_beyond_the_memory_are_refused_before_anything_is_allocated():
    huge = np.broadcast_to(np.zeros(2), (2**40, 2))  # a view: 16 TiB if it were copied
    for analysis in (granule.cell_fields, granule.spectra):
        with pytest.raises(MemoryError, match="of N = 1099511627776 .* GiB are available"):
            analysis(huge, huge, (1.0, 1.0))
    with pytest.raises(MemoryError, match="on 4398046511104 cells"):
        granule.cell_fields(np.zeros((3, 3)), np.zeros((3, 3)), (1.0, 1.0, 1.0), cells=(16384, 16384, 16384))


def test_analysis_parameters_are_checked(configuration):
    positions, velocities = configuration
    with pytest.raises(ValueError, match=r"dk = nan: must be in \(0, ∞\)"):
        granule.spectra(positions, velocities, (1.0, 1.0), dk=float("nan"))
    with pytest.raises(ValueError, match="more than 2\\^32 annuli"):
        granule.spectra(positions, velocities, (1.0, 1.0), dk=1e-300)
    with pytest.raises(ValueError, match="shear_offset = nan"):
        granule.spectra(positions, velocities, (1.0, 1.0), shear_offset=float("nan"))
    with pytest.raises(ValueError, match="shear_velocity = inf"):
        granule.cell_fields(positions, velocities, (1.0, 1.0), shear_velocity=float("inf"))
    with pytest.raises(TypeError, match=r"cells\[0\] must be an integer, not float"):
        granule.cell_fields(positions, velocities, (1.0, 1.0), cells=(1.5, 2))
    with pytest.raises(ValueError, match=r"cells\[1\] = 0: must be an integer in \[1, 16384\]"):
        granule.cell_fields(positions, velocities, (1.0, 1.0), cells=(2, 0))
    assert granule.cell_fields(positions, velocities, (1.0, 1.0), cells=(np.int64(4), 5))["count"].shape == (5, 4)
    empty = granule.spectra(np.zeros((0, 2)), np.zeros((0, 2)), (1.0, 1.0), max_mode=4)
    assert empty["ideal_density"] == 0.0
