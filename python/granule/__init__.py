"""Granule from Python: event-driven MD of inelastic hard disks and spheres (M.-L. Tan 1995).

The API follows HOOMD-blue's shape::

    import granule
    sim = granule.Simulation({"system": {"particles": 2000, "restitution": 0.8}, "seed": 3})
    sim.run(until_collisions_per_particle=20)
    xy, v = sim.positions, sim.velocities          # N × d NumPy arrays at the current time
    fields = granule.cell_fields(xy, v, sim.box, cells=(10, 10))
    T_haff = granule.theory.haff_temperature(t, T0, t0)

Everything is computed by the same C++ libraries as the `granule` command (src/bindings calls
src/driver, src/io, src/analysis, src/spectra and src/theory): a Simulation follows the
trajectory `granule run` follows for the same configuration and seed, bit for bit.
"""
from granule._granule import ConfigError, Simulation, __version__, cell_fields, spectra, theory
from granule.gsd_export import write_gsd

__all__ = ["ConfigError", "Simulation", "cell_fields", "spectra", "theory", "write_gsd", "__version__"]
