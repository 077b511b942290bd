"""granule.Simulation: construction from a dict or a TOML file, configuration errors with the
command line's messages, runs, state arrays and their invariants."""
import json
import os
import signal
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest

import granule


def test_dict_and_toml_file_give_the_same_run(tmp_path, small_config):
    from_dict = granule.Simulation(small_config)
    path = tmp_path / "run.toml"
    path.write_text(from_dict.config_toml)
    from_file = granule.Simulation(path)
    assert from_dict.particles == from_file.particles == 500
    assert np.array_equal(from_dict.positions, from_file.positions)
    assert np.array_equal(from_dict.velocities, from_file.velocities)


def test_overrides_act_like_set(small_config):
    sim = granule.Simulation(small_config, overrides=["system.restitution=0.5", "system.particles=300"])
    assert sim.particles == 300
    assert sim.summary()["restitution"] == 0.5


@pytest.mark.parametrize(
    "key, value, expected",
    [
        ("restitution", 1.5, "system.restitution"),
        ("particles", 1, "system.particles"),
        ("no_such_key", 3, "system.no_such_key"),
    ],
)
def test_config_errors_carry_the_command_lines_message(tmp_path, granule_cli, small_config, key, value, expected):
    config = {**small_config, "system": {**small_config["system"], key: value}}
    with pytest.raises(granule.ConfigError) as error:
        granule.Simulation(config)
    assert isinstance(error.value, ValueError)
    message = str(error.value)
    assert expected in message
    # The same configuration as a file: `granule run` refuses it with exit 2 and the same message.
    path = tmp_path / "bad.toml"
    path.write_text(f"[system]\n{key} = {value}\n")
    cli = granule_cli("run", path, "--out", tmp_path / "out")
    assert cli.returncode == 2
    assert message in cli.stderr


def test_a_value_toml_cannot_hold_is_refused_by_key(small_config):
    with pytest.raises(TypeError, match="system.restitution: a value of type object"):
        granule.Simulation({"system": {"restitution": object()}})


def test_run_advances_to_the_limits_and_records_the_time_series(small_config):
    sim = granule.Simulation(small_config)
    assert sim.time == 0.0 and sim.collisions == 0
    assert sim.run(until_collisions_per_particle=2) == "collisions reached"
    assert sim.collisions == 1000 and sim.collisions_per_particle == 2.0
    t = sim.time
    assert sim.run(until_time=1.5 * t) == "time reached"
    assert sim.time == pytest.approx(1.5 * t)
    series = sim.timeseries
    assert series["c"][0] == 0.0 and series["c"][-1] == sim.collisions_per_particle
    assert np.all(np.diff(series["t"]) > 0)
    assert set(sim.timeseries_row) == set(series)
    assert sim.timeseries_row["temperature_global"] == series["temperature_global"][-1]
    # Without limits: to the configuration's run.until_collisions_per_particle.
    sim.run()
    assert sim.collisions_per_particle == 5.0
    assert sim.summary()["c"] == 5.0


def test_state_arrays_are_read_only_computed_copies(small_config):
    sim = granule.Simulation(small_config)
    sim.run(until_collisions_per_particle=1)
    positions, velocities = sim.positions, sim.velocities
    assert positions.shape == velocities.shape == (500, 2)
    assert np.all((positions >= 0) & (positions < 1))
    with pytest.raises(ValueError):
        positions[0, 0] = 0.5
    before = positions.copy()
    sim.run(until_collisions_per_particle=2)
    assert np.array_equal(positions, before)  # an earlier array is not changed by the engine
    assert not np.array_equal(sim.positions, before)
    assert np.all(sim.masses == 1.0) and np.all(sim.diameters == sim.diameters[0])
    assert sim.spins is None


def test_collisions_conserve_momentum_and_dissipate_energy(small_config):
    sim = granule.Simulation(small_config)
    v0 = sim.velocities
    sim.run(until_collisions_per_particle=5)
    v = sim.velocities
    # The initial state has zero total momentum; collisions exchange it pairwise.
    scale = np.abs(v0).sum()
    assert np.abs(v0.sum(axis=0)).max() < 1e-12 * scale
    assert np.abs(v.sum(axis=0)).max() < 1e-12 * scale
    assert (v**2).sum() < (v0**2).sum()


def test_spheres_mixtures_and_rough_grains_expose_their_arrays():
    spheres = granule.Simulation({
        "system": {"dimension": 3, "particles": 400, "packing_fraction": 0.05,
                   "diameters": {"distribution": "bidisperse", "ratio": 2.0, "fraction": 0.5}},
    })
    assert spheres.dimension == 3 and spheres.positions.shape == (400, 3)
    assert len(set(spheres.diameters)) == 2 and np.isclose(spheres.masses.mean(), 1.0)
    rough = granule.Simulation({"system": {"particles": 300, "tangential_restitution": 0.5}})
    assert rough.spins.shape == (300,)
    rough.run(until_collisions_per_particle=1)
    assert np.abs(rough.spins).max() > 0


def interrupted(body, seconds=1.0):
    """Runs `body` (Python source that prints "ready" before its long run and its result after
    catching KeyboardInterrupt), sends SIGINT `seconds` after "ready"; returns its output."""
    script = "import sys, granule\n" + textwrap.dedent(body)
    process = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True, env=os.environ)
    assert process.stdout.readline().strip() == "ready"
    time.sleep(seconds)
    process.send_signal(signal.SIGINT)
    out, _ = process.communicate(timeout=60)
    assert process.returncode == 0, out
    return out


def test_ctrl_c_stops_a_run_cleanly_and_it_can_go_on():
    out = interrupted("""
        sim = granule.Simulation({"system": {"particles": 20000, "restitution": 0.99}})
        print("ready", flush=True)
        try:
            sim.run(until_collisions_per_particle=1e6)
        except KeyboardInterrupt:
            c = sim.collisions_per_particle
            sim.run(until_collisions_per_particle=c + 0.1)
            print("interrupted", c, sim.collisions_per_particle, flush=True)
            sys.exit(0)
        sys.exit(1)
    """)
    words = out.split()
    assert words[0] == "interrupted" and 0 < float(words[1]) < 1e6
    # c + 0.1 is reached to the nearest whole collision of the 20000 particles.
    assert float(words[2]) == pytest.approx(float(words[1]) + 0.1, abs=0.5 / 20000)


def test_ctrl_c_stops_a_run_directory_with_its_checkpoint(tmp_path, granule_cli):
    out = tmp_path / "run"
    text = interrupted(f"""
        print("ready", flush=True)
        try:
            granule.run_directory({{"system": {{"particles": 20000, "restitution": 0.99}},
                                   "run": {{"until_collisions_per_particle": 1e6}}}}, {str(out)!r})
        except KeyboardInterrupt:
            print("interrupted", flush=True)
            sys.exit(0)
        sys.exit(1)
    """, seconds=1.5)
    assert text.strip() == "interrupted"
    summary = json.loads((out / "summary.json").read_text())
    assert summary["stop_reason"] == "interrupted" and summary["c"] > 0
    end = summary["c"] + 0.5
    resumed = granule_cli("run", "--resume", out, "--set", f"run.until_collisions_per_particle={end}")
    assert resumed.returncode == 0, resumed.stderr
    assert json.loads((out / "summary.json").read_text())["c"] == pytest.approx(end, abs=1e-4)


def test_speed_dependent_restitution_from_a_dict(small_config):
    """The restitution laws run from Python as from TOML: a viscoelastic gas loses energy without a
    TC model and without collapse, and its resolved configuration names the law."""
    config = {**small_config, "system": {"particles": 500, "packing_fraction": 0.1, "restitution_law": "viscoelastic",
                                         "viscoelastic_constant": 0.1}}
    sim = granule.Simulation(config)
    assert 'restitution_law = "viscoelastic"' in sim.config_toml
    before = float(np.mean(np.sum(sim.velocities ** 2, axis=1)))
    assert sim.run(until_collisions_per_particle=20) == "collisions reached"
    after = float(np.mean(np.sum(sim.velocities ** 2, axis=1)))
    assert 0.0 < after < 0.5 * before
    threshold = {**small_config, "system": {**small_config["system"], "restitution_law": "threshold", "elastic_below": 0.1}}
    assert 'elastic_below = 0.1' in granule.Simulation(threshold).config_toml
    with pytest.raises(ValueError, match="system.viscoelastic_constant is for system.restitution_law"):
        granule.Simulation({**small_config, "system": {**small_config["system"], "viscoelastic_constant": 0.1}})


def test_obstacles_from_a_dict(small_config):
    """Obstacles run from Python as from TOML (a list of dicts is [[obstacles]]): no grain ever
    enters one, and the time series has the drag and lift on each, the drag along the flow."""
    config = {**small_config,
              "system": {"particles": 300, "diameter": 0.02, "box": [2.0, 1.0], "restitution": 0.95,
                         "gravity": [0.3, 0.0]},
              "boundary": {"kind": "walls", "wall_axes": ["y"]},
              "obstacles": [{"centre": [0.5, 0.5], "diameter": 0.3, "restitution": 0.9},
                            {"centre": [1.5, 0.0], "diameter": 0.2}],
              "output": {"every_time": 0.5},
              "initial": {"temperature": 0.1, "equilibrate": 0}}
    sim = granule.Simulation(config)
    assert "[[obstacles]]" in sim.config_toml
    centres = np.array([[0.5, 0.5], [1.5, 0.0]])
    for stop in (1.0, 2.0, 3.0):
        sim.run(until_time=stop)
        for centre, diameter in zip(centres, (0.3, 0.2)):
            distance = np.linalg.norm(sim.positions - centre, axis=1)
            assert float(np.min(distance)) >= 0.5 * (diameter + 0.02) * (1.0 - 1e-9)
    series = sim.timeseries
    assert {"obstacle0_drag", "obstacle0_lift", "obstacle1_collisions", "obstacles_drag"} <= set(series)
    assert float(np.mean(series["obstacle0_drag"][1:])) > 0.0
    with pytest.raises(ValueError, match=r"obstacles\[1\].diameter"):
        granule.Simulation({**config, "obstacles": [config["obstacles"][0], {"centre": [1.0, 0.5], "diameter": -1.0}]})


def test_a_vibrated_floor_from_a_dict(small_config):
    """A wall moving normal to itself runs from Python as from TOML: the floor h(t) = A (1 − cos 2πft)
    stays below every grain, and a bed on it is kept moving (the floor does work)."""
    amplitude, frequency = 0.02, 3.0
    config = {**small_config,
              "system": {"particles": 300, "diameter": 0.02, "box": [1.0, 2.0], "restitution": 0.9,
                         "gravity": [0.0, -1.0], "tc_duration": 1e-5},
              "boundary": {"kind": "walls", "wall_axes": ["y"],
                           "wall_motion": {"wall": "y0", "amplitude": amplitude, "frequency": frequency}},
              "initial": {"temperature": 0.05, "equilibrate": 0}}
    sim = granule.Simulation(config)
    assert 'wall_motion = { wall = "y0", amplitude = 0.02, frequency = 3 }' in sim.config_toml
    for stop in (1.0, 2.0, 3.0):
        sim.run(until_time=stop)
        floor = amplitude * (1.0 - np.cos(2.0 * np.pi * frequency * sim.time))
        assert float(np.min(sim.positions[:, 1])) >= 0.01 + floor - 1e-12
    # Without the floor's work a bed at T = 0.05 would have settled (mean speed ≪ √0.05).
    assert float(np.sqrt(np.mean(np.sum(sim.velocities ** 2, axis=1)))) > 0.05
    with pytest.raises(ValueError, match="boundary.wall_motion.wall"):
        granule.Simulation({**config, "boundary": {**config["boundary"], "wall_motion": {"wall": "x0", "amplitude": 0.1,
                                                                                      "frequency": 1.0}}})


def test_a_biparabolic_floor_from_a_dict(small_config):
    """A floor driven in parabolic arcs, h = 16Ax² up to a quarter cycle x, 8A(2x − 2x² − ¼) up to three
    quarters and 16A(1 − x)² after (written out here), stays below every grain."""
    amplitude, frequency = 0.02, 3.0
    config = {**small_config,
              "system": {"particles": 300, "diameter": 0.02, "box": [1.0, 2.0], "restitution": 0.9,
                         "gravity": [0.0, -1.0], "tc_duration": 1e-5},
              "boundary": {"kind": "walls", "wall_axes": ["y"],
                           "wall_motion": {"wall": "y0", "amplitude": amplitude, "frequency": frequency,
                                           "shape": "biparabolic"}},
              "initial": {"temperature": 0.05, "equilibrate": 0}}
    sim = granule.Simulation(config)
    assert 'shape = "biparabolic"' in sim.config_toml
    for stop in (0.9, 1.7, 2.3):
        sim.run(until_time=stop)
        x = frequency * sim.time % 1.0
        floor = 16 * amplitude * x * x if x < 0.25 else (
            8 * amplitude * (2 * x - 2 * x * x - 0.25) if x < 0.75 else 16 * amplitude * (1 - x) ** 2)
        assert float(np.min(sim.positions[:, 1])) >= 0.01 + floor - 1e-12
