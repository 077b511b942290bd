"""granule.cell_fields, granule.spectra and granule.theory on arrays, against `granule analyze` and
against what the formulas must give."""
import math

import h5py
import numpy as np
import pytest

import granule


@pytest.fixture
def cooled(small_config):
    sim = granule.Simulation(small_config)
    sim.run()
    return sim


def test_cell_fields_equal_granule_analyze_fields(tmp_path, granule_cli, cooled):
    path = tmp_path / "snapshots.h5"
    cooled.write_snapshot(path)
    result = granule_cli("analyze", "fields", path, "--cells", "8,5", "--out", tmp_path / "fields.h5")
    assert result.returncode == 0, result.stderr
    fields = granule.cell_fields(cooled.positions, cooled.velocities, cooled.box, cells=(8, 5))
    with h5py.File(tmp_path / "fields.h5") as f:
        for name in ("count", "density", "velocity_x", "temperature", "kinetic_xy", "vorticity"):
            assert fields[name].shape == (5, 8)
            assert np.array_equal(fields[name], f[f"instant/{name}"][0]), name
    assert fields["count"].sum() == cooled.particles


def test_cell_fields_of_a_uniform_flow_have_no_temperature():
    rng = np.random.default_rng(1)
    positions = rng.random((1000, 2))
    velocities = np.tile([0.3, -0.2], (1000, 1))
    fields = granule.cell_fields(positions, velocities, (1.0, 1.0), cells=(4, 4))
    assert np.allclose(fields["temperature"], 0.0, atol=1e-15)
    assert np.allclose(fields["velocity_x"], 0.3)


def test_spectra_fast_and_exact_agree_and_show_the_ideal_gas_level(cooled):
    fast = granule.spectra(cooled.positions, cooled.velocities, cooled.box, max_mode=8)
    exact = granule.spectra(cooled.positions, cooled.velocities, cooled.box, max_mode=8, method="exact")
    assert np.allclose(fast["density"], exact["density"], rtol=1e-6)
    assert fast["ideal_density"] == pytest.approx(cooled.particles / (4 * math.pi**2))
    assert fast["k"][0] == pytest.approx(2 * math.pi)
    assert fast["dominant_density_mode"]["length"] > 0
    with pytest.raises(ValueError):
        granule.spectra(cooled.positions, cooled.velocities, cooled.box, method="slow")


def test_theory_matches_its_formulas_and_takes_arrays():
    th = granule.theory
    t = np.array([0.0, 1.0, 3.0])
    assert np.allclose(th.haff_temperature(t, 2.0, 1.0), 2.0 / (1 + t) ** 2)
    e, sigma, nu = 0.8, 0.01, 0.05
    eps = 1 - e**2
    assert th.inelasticity(e) == pytest.approx(eps)
    t0 = th.haff_time_disks(1.0, e, sigma, nu)
    assert t0 == pytest.approx(math.sqrt(math.pi) * sigma / (2 * nu * eps))
    shear = th.steady_shear(restitution=e, shear_rate=10.0, diameter=sigma, area_fraction=nu)
    assert shear["tan_fit"] == pytest.approx(0.080 * (10 * sigma / nu) ** 2 * (1 / eps - 0.54))
    assert set(shear) == {"tan_fit", "jenkins_richman", "kinetic"}
    assert th.sonine_a2(1.0, 2) == pytest.approx(0.0, abs=1e-15)
    assert len(th.free_gas_eigenvalues(0.1, eps)) == 3
