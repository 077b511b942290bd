"""A granule.Simulation follows the trajectory of `granule run` for the same configuration and seed,
bit for bit, however its run is split; and write_snapshot writes frames the CLI's readers take."""
import csv
import json

import h5py
import numpy as np
import pytest

import granule

CASES = {
    "free cooling": {},
    "Lees-Edwards with the TC model": {
        "system": {"tc_duration": 1e-4},
        "boundary": {"kind": "lees-edwards", "shear_velocity": 5.0},
    },
    "spheres, bidisperse": {
        "system": {"dimension": 3, "diameters": {"distribution": "bidisperse", "ratio": 1.5, "fraction": 0.3}},
    },
    "rough disks with a pre-run": {
        "system": {"tangential_restitution": 0.2},
        "initial": {"equilibrate": 1.0},
    },
}


def merged(base, extra):
    out = {key: dict(value) if isinstance(value, dict) else value for key, value in base.items()}
    for section, values in extra.items():
        out.setdefault(section, {}).update(values)
    return out


def cli_run(granule_cli, tmp_path, sim):
    config = tmp_path / "config.toml"
    config.write_text(sim.config_toml)
    out = tmp_path / "cli"
    result = granule_cli("run", config, "--out", out)
    assert result.returncode == 0, result.stderr
    return out


@pytest.mark.parametrize("case", CASES)
def test_final_state_equals_the_cli_bit_for_bit(tmp_path, granule_cli, small_config, case):
    sim = granule.Simulation(merged(small_config, CASES[case]))
    out = cli_run(granule_cli, tmp_path, sim)
    # Split differently from the CLI's stops: the trajectory must not notice.
    sim.run(until_collisions_per_particle=1.37)
    sim.run(until_time=sim.time * 1.01)
    sim.run()
    with h5py.File(out / "snapshots.h5") as f:
        assert np.array_equal(f["positions"][-1], sim.positions)
        assert np.array_equal(f["velocities"][-1], sim.velocities)
        assert f["time"][-1] == sim.time
        assert f["events"][-1] == sim.events
        if sim.spins is not None:
            assert np.array_equal(f["spins"][-1], sim.spins)
        if "diameters" in f:
            assert np.array_equal(f["diameters"][()], sim.diameters)


def test_time_series_of_one_run_equals_timeseries_csv(tmp_path, granule_cli, small_config):
    sim = granule.Simulation(small_config)
    out = cli_run(granule_cli, tmp_path, sim)
    sim.run()
    with open(out / "timeseries.csv") as f:
        rows = list(csv.DictReader(f))
    series = sim.timeseries
    assert list(series) == list(rows[0])
    # timeseries.csv keeps 12 significant digits.
    for name in ("t", "c", "temperature", "kinetic_energy", "pressure_collisional", "collision_rate"):
        assert np.allclose(series[name], [float(row[name]) for row in rows], rtol=1e-11, atol=1e-300), name
    summary = sim.summary()
    cli_summary = json.loads((out / "summary.json").read_text())
    for key in ("collisions", "events", "t", "c", "stop_reason", "particles", "diameter"):
        assert summary[key] == cli_summary[key], key


def test_write_snapshot_appends_frames_the_cli_reads(tmp_path, granule_cli, small_config):
    sim = granule.Simulation(small_config)
    path = tmp_path / "snapshots.h5"
    sim.write_snapshot(path)
    sim.run(until_collisions_per_particle=2)
    sim.write_snapshot(path)
    with h5py.File(path) as f:
        assert f["positions"].shape == (2, 500, 2)
        assert np.array_equal(f["positions"][1], sim.positions)
        assert f["collisions_per_particle"][1] == 2.0
    result = granule_cli("analyze", "fields", path, "--cells", "5,5", "--out", tmp_path / "fields.h5")
    assert result.returncode == 0, result.stderr


def test_run_directory_writes_the_files_of_granule_run(tmp_path, granule_cli, small_config):
    config = merged(small_config, {"collisions": {"free_paths": True}})
    summary = granule.run_directory(config, tmp_path / "py")
    cli = cli_run(granule_cli, tmp_path, granule.Simulation(config))
    assert summary["c"] == 5.0 and summary["stop_reason"] == "collisions reached"
    assert (tmp_path / "py" / "config.toml").read_text() == (cli / "config.toml").read_text()
    assert (tmp_path / "py" / "timeseries.csv").read_bytes() == (cli / "timeseries.csv").read_bytes()
    for name, datasets in (("snapshots.h5", ("positions", "velocities", "time")),
                           ("fields.h5", ("instant/temperature", "average/pressure_collisional")),
                           ("collisions.h5", None)):
        with h5py.File(tmp_path / "py" / name) as ours, h5py.File(cli / name) as theirs:
            names = list(datasets or [])
            if not names:  # every dataset of the file
                theirs.visititems(lambda key, item: names.append(key) if isinstance(item, h5py.Dataset) else None)
            assert names
            for dataset in names:
                assert np.array_equal(ours[dataset][()], theirs[dataset][()]), (name, dataset)
    # The command line continues it from its checkpoint.
    resumed = granule_cli("run", "--resume", tmp_path / "py", "--set", "run.until_collisions_per_particle=7")
    assert resumed.returncode == 0, resumed.stderr
    with pytest.raises(FileExistsError):
        granule.run_directory(config, tmp_path / "py")
