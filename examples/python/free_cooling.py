"""Free cooling of inelastic disks from Python: run, take the arrays, coarse-grain, Fourier-analyse,
and compare the temperature with Haff's law (thesis §2.1, §2.4.2).  A few seconds.

    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/free_cooling.py [--figure out.png]
"""
import argparse

import numpy as np

import granule

parser = argparse.ArgumentParser()
parser.add_argument("--figure", help="save T(t) against Haff's law and the density field here (PNG)")
figure = parser.parse_args().figure

# %% A freely cooling gas: 10 000 disks at area fraction 0.05, ẽ = 0.9 (a config dict has the keys
# of a `granule run` TOML file; every key not given takes the default of README.md).
config = {
    "seed": 11,
    "system": {"particles": 10000, "packing_fraction": 0.05, "restitution": 0.9},
    "output": {"every_collisions_per_particle": 2},
}
sim = granule.Simulation(config)
print(f"granule {granule.__version__}: N = {sim.particles}, box {sim.box}, σ = {sim.diameters[0]:.5g}")

# %% Run in two legs (the trajectory does not depend on where it stops): the homogeneous stage,
# then on into clustering.
sim.run(until_collisions_per_particle=20)
print(f"after c = {sim.collisions_per_particle:g}: t = {sim.time:.4g}, T = {sim.timeseries_row['temperature_global']:.4g}")
sim.run(until_collisions_per_particle=60)
summary = sim.summary()
print(f"after c = {sim.collisions_per_particle:g}: t = {sim.time:.4g}, {summary['collisions_per_second']:.3g} collisions/s")

# %% Haff's law T(t) = T0/(1 + t/t0)² with the Boltzmann t0 of dilute disks, χ = Henderson's
# contact value at ν (granule.theory, the functions behind `granule theory haff`).
series = sim.timeseries
t, T = series["t"], series["temperature_global"]
e, nu, sigma = config["system"]["restitution"], summary["area_fraction"], sim.diameters[0]
chi = granule.theory.henderson_contact_value(nu)
t0 = granule.theory.haff_time_disks(T[0], e, sigma, nu, contact_value=chi)
T_haff = granule.theory.haff_temperature(t, T[0], t0)
T_of_c = granule.theory.haff_temperature_after_collisions(series["c"], T[0], e)
print(f"Haff time t0 = {t0:.4g} (χ = {chi:.4f})")
print("     c         t     T_sim/T_Haff(t)  T_sim/T(c)")
for k in range(0, len(t), 5):
    print(f"{series['c'][k]:6.0f} {t[k]:9.4g} {T[k] / T_haff[k]:12.4f} {T[k] / T_of_c[k]:12.4f}")

# %% The state now: arrays at the current time (computed from the engine's local times, read-only).
positions, velocities = sim.positions, sim.velocities
momentum = velocities.sum(axis=0)
print(f"total momentum {momentum[0]:+.2e}, {momentum[1]:+.2e} (zero up to round-off)")

# %% Coarse-grained fields (§1.4.3) on 20 × 20 cells: clusters show as density contrast.
fields = granule.cell_fields(positions, velocities, sim.box, cells=(20, 20))
rho = fields["density"]
print(f"cell density: mean {rho.mean():.4g}, max/mean {rho.max() / rho.mean():.3g}, "
      f"rms deviation {np.sqrt(((rho / rho.mean() - 1) ** 2).mean()):.3g}")

# %% Fourier spectrum of the density (docs/spectra.md): the dominant length against L0 = l/√ε (1.1).
spectrum = granule.spectra(positions, velocities, sim.box, max_mode=32)
mode = spectrum["dominant_density_mode"]
L0 = granule.theory.cluster_separation(e, sigma, nu)
print(f"dominant density mode: length {mode['length']:.3g} ({mode['power_over_ideal_gas']:.1f}× the ideal gas), "
      f"L0 = {L0:.3g}")

if figure:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.2))
    left.loglog(1 + t / t0, T, "o", label="granule")
    left.loglog(1 + t / t0, T_haff, "-", label="Haff (2.10)")
    left.set_xlabel("1 + t/t0")
    left.set_ylabel("T")
    left.legend()
    image = right.imshow(rho, origin="lower", extent=(0, sim.box[0], 0, sim.box[1]), cmap="magma")
    fig.colorbar(image, ax=right, label="density")
    right.set_title(f"c = {sim.collisions_per_particle:g}")
    fig.tight_layout()
    fig.savefig(figure, dpi=100)
    print(f"figure: {figure}")
