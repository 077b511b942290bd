"""granule.spin_correlation on arrays (thesis Fig C.4): equal to `granule analyze spins` on a sheared run
of rough disks, −1 at contact for a checkerboard of meshing gears, and its inputs refused by name."""
import h5py
import numpy as np
import pytest

import granule


def test_equals_granule_analyze_spins_on_a_sheared_rough_run(tmp_path, granule_cli):
    sim = granule.Simulation({"seed": 3, "system": {"particles": 600, "area_fraction": 0.08, "restitution": 0.6,
                                                    "tangential_restitution": -0.8},
                              "boundary": {"kind": "lees-edwards", "shear_velocity": 20.0},
                              "run": {"until_collisions_per_particle": 4}})
    sim.run()
    path = tmp_path / "snapshots.h5"
    sim.write_snapshot(path)
    result = granule_cli("analyze", "spins", path, "--out", tmp_path / "spins.h5")
    assert result.returncode == 0, result.stderr
    found = granule.spin_correlation(sim.positions, sim.spins, sim.box, diameter=float(sim.diameters[0]),
                                     shear_offset=sim.shear_offset)
    with h5py.File(tmp_path / "spins.h5") as f:
        assert f["contact_pairs"][0] == found["contact_pairs"] > 0
        assert found["C_contact"] == pytest.approx(f["C_contact"][0], abs=1e-12)
        for name in ("C", "C_flow", "C_gradient"):
            assert np.allclose(found[name], f[name][0], atol=1e-12, equal_nan=True), name
        assert np.array_equal(found["pairs"], f["pairs"][0])
    assert found["mean_spin"] == pytest.approx(sim.spins.mean())


def test_checkerboard_of_meshing_gears_is_minus_one_at_contact():
    i, j = np.meshgrid(np.arange(12), np.arange(12), indexing="ij")
    positions = np.column_stack([(i.ravel() + 0.5) * 0.1, (j.ravel() + 0.5) * 0.1])
    spins = np.where((i + j).ravel() % 2 == 0, 1.0, -1.0) - 5.0  # a mean spin, removed
    found = granule.spin_correlation(positions, spins, (1.2, 1.2), diameter=0.1)
    assert found["contact_pairs"] == 2 * 144
    assert found["C_contact"] == pytest.approx(-1.0)
    assert found["C_flow"][0] == pytest.approx(-1.0) and found["C_gradient"][0] == pytest.approx(-1.0)
    assert found["mean_spin"] == pytest.approx(-5.0)
    # Walls along x: the pairs across x = 0 are no longer neighbours.
    walled = granule.spin_correlation(positions, spins, (1.2, 1.2), diameter=0.1, walls=(True, False))
    assert walled["contact_pairs"] == 2 * 144 - 12


@pytest.mark.parametrize("change, message", [
    ({"spins": np.zeros(5)}, "spins must have N = 10"),
    ({"spins": np.full(10, np.nan)}, "spins[0] = nan"),
    ({"box": (0.5, 1.0)}, "shorter than twice"),
    ({"max_distance": 1.05}, "largest distance"),
    ({"diameters": -np.ones(10)}, "diameters[0]"),
    ({"walls": (True,)}, "walls must hold 2"),
])
def test_inputs_are_refused_by_name(change, message):
    rng = np.random.default_rng(2)
    arguments = {"positions": rng.random((10, 2)) * 0.5, "spins": rng.normal(size=10), "box": (1.0, 1.0), "diameter": 0.1}
    arguments.update(change)
    with pytest.raises(ValueError, match=message.replace("[", r"\[")):
        granule.spin_correlation(**arguments)
