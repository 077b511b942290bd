"""Snapshots as a HOOMD-blue GSD trajectory, the file OVITO opens directly (`granule plot export --format gsd`).

Run by `granule plot export` with Debian's /usr/bin/python3, and installed as granule.gsd_export
(granule.write_gsd) with the Python module.  Written with python3-gsd's gsd.hoomd.Snapshot API
(gsd 2.7): Debian packages no GSD C library, and the Python one writes the published format itself.

Each snapshot frame becomes one GSD frame, in HOOMD's conventions:
- configuration/step: the run's collision count at the frame (HOOMD's steps are integers and
  increase); configuration/dimensions: 2 or 3; configuration/box: [L_x, L_y, L_z, 0, 0, 0], L_z = 0
  for disks (HOOMD's 2D box).  The box is HOOMD's, centred on the origin: positions are Granule's
  minus L/2, with z = 0 for disks.  A Lees–Edwards box stays rectangular (tilt 0): its image offset
  Δ is logged (log/shear_offset), not encoded as a tilt.
- particles/N, position, velocity (z = 0 for disks), diameter, mass, typeid 0 of type "A".  HOOMD's
  schema stores them as float32, so positions keep about 7 digits (snapshots.h5 keeps float64).
- rough grains: log/particles/spin (ω_z of disks as N × 1, (ω_x, ω_y, ω_z) of spheres as N × 3) and
  particles/moment_inertia I = q m σ²/4 about each spin axis (0 about x, y for disks).  HOOMD's
  angmom is a quaternion of the body frame, which hard grains without orientation do not have.
- log/time, log/collisions_per_particle, log/shear_velocity, log/shear_offset: t, c, U(t), Δ(t).
"""
import argparse
import os
import sys

import h5py
import numpy as np


def _frame(f, k, attrs, sizes):
    import gsd.hoomd

    d = int(attrs.get("dimension", 2))
    box = [float(v) for v in attrs["box"]]
    lengths = np.array(box + [0.0] * (3 - d))
    n = int(attrs["particles"])
    positions = np.zeros((n, 3))
    velocities = np.zeros((n, 3))
    positions[:, :d] = f["positions"][k] - lengths[:d] / 2
    velocities[:, :d] = f["velocities"][k]
    diameters, masses = sizes
    s = gsd.hoomd.Snapshot()
    s.configuration.step = int(f["collisions"][k])
    s.configuration.dimensions = d
    s.configuration.box = [lengths[0], lengths[1], lengths[2] if d == 3 else 0.0, 0.0, 0.0, 0.0]
    s.particles.N = n
    s.particles.types = ["A"]
    s.particles.typeid = np.zeros(n, dtype=np.uint32)
    s.particles.position = positions
    s.particles.velocity = velocities
    s.particles.diameter = diameters
    s.particles.mass = masses
    if "spins" in f:
        spins = np.asarray(f["spins"][k]).reshape(n, -1)
        s.log["particles/spin"] = spins
        inertia = 0.25 * float(attrs["inertia_factor"]) * masses * diameters**2
        s.particles.moment_inertia = np.outer(inertia, [1.0, 1.0, 1.0] if d == 3 else [0.0, 0.0, 1.0])
    for name in ("time", "collisions_per_particle", "shear_velocity", "shear_offset"):
        if name in f:
            s.log[name] = np.array([f[name][k]], dtype=np.float64)
    return s


def write_gsd(snapshots, out, frames=None):
    """Write frames (indices, negative from the end; default all) of a snapshots.h5 file as the GSD file `out`.

    Returns the number of frames written."""
    import gsd.hoomd

    with h5py.File(snapshots, "r") as f:
        attrs = dict(f.attrs)
        total = f["time"].shape[0]
        chosen = range(total) if frames is None else [k + total if k < 0 else k for k in frames]
        for k in chosen:
            if not 0 <= k < total:
                raise IndexError(f"frame {k} is not in 0..{total - 1}")
        n = int(attrs["particles"])
        sizes = (np.asarray(f["diameters"]) if "diameters" in f else np.full(n, float(attrs["diameter"])),
                 np.asarray(f["masses"]) if "masses" in f else np.ones(n))
        partial = f"{out}.partial"  # published under its name only once complete
        with gsd.hoomd.open(partial, mode="wb") as trajectory:
            for k in chosen:
                trajectory.append(_frame(f, k, attrs, sizes))
        os.replace(partial, out)
    return len(chosen)


def main():
    p = argparse.ArgumentParser(prog="granule plot export --format gsd", description=__doc__.splitlines()[0])
    p.add_argument("input", help="snapshots.h5")
    p.add_argument("--out", required=True)
    p.add_argument("--frames", required=True, help="comma-separated frame indices")
    a = p.parse_args()
    try:
        import gsd.hoomd  # noqa: F401
    except ImportError:
        print("granule plot export: error: --format gsd needs python3-gsd (apt-get install python3-gsd)", file=sys.stderr)
        return 2
    count = write_gsd(a.input, a.out, [int(k) for k in a.frames.split(",")])
    print(f"wrote {a.out} ({count} frames)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
