"""granule.Simulation and `granule run` make a new run's initial state with one function
(driver/run_start.hpp): from an earlier run's frame (initial.from), sheared (initial.shear_profile
with Lees–Edwards images) and static, the state at the start of production is the same bit for bit,
and so is the trajectory from it."""
import h5py
import numpy as np
import pytest

import granule

LEES_EDWARDS = {"boundary": {"kind": "lees-edwards", "shear_velocity": 5.0}, "system": {"tc_duration": 1e-4}}


def merged(base, *extras):
    out = {key: dict(value) if isinstance(value, dict) else value for key, value in base.items()}
    for extra in extras:
        for section, values in extra.items():
            out.setdefault(section, {}).update(values)
    return out


def cli_run(granule_cli, directory, sim):
    config = directory.parent / f"{directory.name}.toml"
    config.write_text(sim.config_toml)
    result = granule_cli("run", config, "--out", directory)
    assert result.returncode == 0, result.stderr
    return directory


def assert_same_start_and_end(granule_cli, tmp_path, config):
    sim = granule.Simulation(config)
    start = {"positions": sim.positions, "velocities": sim.velocities, "spins": sim.spins,
             "time": sim.time, "shear_velocity": sim.shear_velocity}
    out = cli_run(granule_cli, tmp_path / "cli", sim)
    sim.run()
    with h5py.File(out / "snapshots.h5") as f:
        # Frame 0 is the state at the start of production, the last the end of the run.
        assert np.array_equal(f["positions"][0], start["positions"])
        assert np.array_equal(f["velocities"][0], start["velocities"])
        assert f["time"][0] == start["time"]
        if start["spins"] is not None:
            assert np.array_equal(f["spins"][0], start["spins"])
        assert np.array_equal(f["positions"][-1], sim.positions)
        assert np.array_equal(f["velocities"][-1], sim.velocities)
        assert f["time"][-1] == sim.time
    return start


def test_a_sheared_start_is_the_clis(tmp_path, granule_cli, small_config):
    start = assert_same_start_and_end(granule_cli, tmp_path,
                                      merged(small_config, LEES_EDWARDS, {"initial": {"shear_profile": True}}))
    # The images move with the profile from the start.
    assert start["shear_velocity"] == 5.0


def test_a_static_start_is_the_clis(tmp_path, granule_cli, small_config):
    start = assert_same_start_and_end(granule_cli, tmp_path,
                                      merged(small_config, LEES_EDWARDS, {"initial": {"shear_profile": False}}))
    # The static gas: no mean flow in the initial velocities.
    assert abs(start["velocities"][:, 0].mean()) < 0.2


def test_a_start_from_another_runs_frame_is_the_clis(tmp_path, granule_cli, small_config):
    sheared = merged(small_config, LEES_EDWARDS, {"initial": {"shear_profile": True}})
    source = cli_run(granule_cli, tmp_path / "source", granule.Simulation(sheared))
    config = merged(small_config, LEES_EDWARDS, {"initial": {"from": str(source), "frame": 2}})
    start = assert_same_start_and_end(granule_cli, tmp_path, config)
    with h5py.File(source / "snapshots.h5") as f:
        assert np.array_equal(f["positions"][2], start["positions"])
        assert np.array_equal(f["velocities"][2], start["velocities"])
    # A frame carries its flow: the images move with the protocol from the start.
    assert start["shear_velocity"] == 5.0


def test_a_frame_of_another_system_is_refused_as_by_the_cli(tmp_path, granule_cli, small_config):
    source = cli_run(granule_cli, tmp_path / "source", granule.Simulation(small_config))
    other = merged(small_config, {"system": {"particles": 400}, "initial": {"from": str(source)}})
    with pytest.raises(granule.ConfigError, match="system.. must match the run it starts from"):
        granule.Simulation(other)
