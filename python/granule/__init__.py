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
from pathlib import Path

from granule import _granule
from granule._granule import ConfigError, Simulation, __version__, cell_fields, spectra, spin_correlation, theory
from granule.gsd_export import write_gsd

__all__ = ["ConfigError", "Simulation", "cell_fields", "spectra", "spin_correlation", "theory", "run_directory", "write_gsd", "__version__"]


def run_directory(config, out, overrides=()):
    """A whole `granule run` of `config` (a TOML path or a dict) into the directory `out`.

    It goes through the driver's RunSession, the library the command line uses: the same files
    (config.toml, timeseries.csv, snapshots.h5, fields.h5, collision statistics, checkpoint.h5,
    summary.json; not the picture configuration.png, which the command line draws), bit for bit
    but for wall times, and `granule run --resume OUT` continues it.  `out` must be empty or
    missing.  Ctrl-C stops the run after the current event, writes its checkpoint and outputs as
    the command line does, and raises KeyboardInterrupt.  Returns summary.json as a dict.

    Configurations are taken and refused as by Simulation (ConfigError, OSError for a path,
    MemoryError for a run larger than the available memory).  Calls from several threads run side
    by side, each into its own directory (one that another thread is writing raises RuntimeError);
    Ctrl-C stops all of them.
    """
    if isinstance(overrides, (str, bytes)):
        raise TypeError("overrides must be a list of 'section.key=value' strings, not one string")
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)  # its emptiness is checked as the run claims it
    return _granule._run_directory(config, out, list(overrides))
