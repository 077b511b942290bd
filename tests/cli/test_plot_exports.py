"""End-to-end: `granule plot export` files read back by independent readers and compared with
snapshots.h5 read by h5py: extended XYZ parsed here in Python (every value exact), VTK PolyData,
ImageData and .pvd series read with VTK's Python module (Debian's python3-vtk9).  Fields computed
from snapshots are checked against a numpy histogram of the positions; fields from a fields file
round-trip exactly.  Bad input exits with code 2 and writes nothing."""
import shlex
import xml.etree.ElementTree as ElementTree
from pathlib import Path

import h5py
import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

from harness import WORK, check, finish, granule


def read_vtk(reader_class, path):
    reader = reader_class()
    reader.SetFileName(str(path))
    reader.Update()
    return reader.GetOutput()


# A Lees–Edwards run (so that the offset Δ is exported too): 1500 disks in a 1 × 1.5 box.
run = WORK / "run"
r = granule("run", "--out", run, "--set", "system.particles=1500", "--set", "system.box=[1.0, 1.5]",
            "--set", "boundary.kind=lees-edwards", "--set", "boundary.shear_velocity=20",
            "--set", "run.until_collisions_per_particle=4", "--set", "output.snapshot_every_collisions_per_particle=2")
check(r.returncode == 0, f"run failed: {r.stderr}")
with h5py.File(run / "snapshots.h5") as f:
    positions, velocities = f["positions"][:], f["velocities"][:]
    times, offsets, cs = f["time"][:], f["shear_offset"][:], f["collisions_per_particle"][:]
    sigma, (lx, ly), n = f.attrs["diameter"], f.attrs["box"], int(f.attrs["particles"])
frames = len(times)
check(frames >= 3, f"expected at least 3 snapshots, got {frames}")

# Extended XYZ, all frames in one file: parsed line by line.
r = granule("plot", "export", run, "--format", "xyz", "--all-frames")
check(r.returncode == 0, f"xyz export failed: {r.stderr}")
lines = (run / "particles.xyz").read_text().splitlines()
check(len(lines) == frames * (n + 2), f"particles.xyz has {len(lines)} lines")
for k in range(frames):
    block = lines[k * (n + 2):(k + 1) * (n + 2)]
    check(int(block[0]) == n, f"frame {k}: count line {block[0]}")
    comment = dict(item.split("=", 1) for item in shlex.split(block[1]))  # key=value, quoted values
    lattice = [float(v) for v in comment["Lattice"].split()]
    check(lattice == [lx, 0, 0, 0, ly, 0, 0, 0, 1], f"frame {k}: lattice {lattice}")
    check("species:S:1:pos:R:3:velo:R:3:radius:R:1" in block[1], "Properties column spec")
    check(float(comment["Time"]) == times[k] and float(comment["collisions_per_particle"]) == cs[k], f"frame {k}: time")
    check(comment["boundary"] == "lees-edwards" and float(comment["shear_offset"]) == offsets[k], f"frame {k}: offset")
    table = np.array([row.split()[1:] for row in block[2:]], dtype=float)
    check(all(row.startswith("D ") for row in block[2:]), f"frame {k}: species")
    check(np.array_equal(table[:, 0:2], positions[k]) and np.array_equal(table[:, 3:5], velocities[k]),
          f"frame {k}: positions or velocities differ from snapshots.h5")
    check(np.all(table[:, [2, 5]] == 0) and np.all(table[:, 6] == sigma / 2), f"frame {k}: z or radius")

# VTK particles, all frames: a .pvd series of .vtp files.
r = granule("plot", "export", run, "--format", "vtk", "--all-frames")
check(r.returncode == 0, f"vtk export failed: {r.stderr}")
datasets = ElementTree.parse(run / "particles.pvd").getroot().find("Collection").findall("DataSet")
check([float(d.get("timestep")) for d in datasets] == list(times), "pvd timesteps differ from the snapshot times")
for k, d in enumerate(datasets):
    poly = read_vtk(vtk.vtkXMLPolyDataReader, run / d.get("file"))
    points = vtk_to_numpy(poly.GetPoints().GetData())
    velocity = vtk_to_numpy(poly.GetPointData().GetArray("velocity"))
    radius = vtk_to_numpy(poly.GetPointData().GetArray("radius"))
    check(poly.GetNumberOfPoints() == n and poly.GetNumberOfVerts() == n, f"vtp {k}: {poly.GetNumberOfPoints()} points")
    check(np.array_equal(points[:, :2], positions[k]) and np.all(points[:, 2] == 0), f"vtp {k}: points differ")
    check(np.array_equal(velocity[:, :2], velocities[k]), f"vtp {k}: velocities differ")
    check(np.all(radius == sigma / 2), f"vtp {k}: radius")
    time_value = poly.GetFieldData().GetArray("TimeValue")
    check(time_value is not None and time_value.GetValue(0) == times[k], f"vtp {k}: TimeValue")

# VTK fields computed from the last snapshot on a 6 × 8 grid: counts against numpy's histogram.
r = granule("plot", "export", run / "snapshots.h5", "--format", "vtk", "--what", "fields", "--cells", 6, 8,
            "--out", WORK / "snapshot_fields.vti")
check(r.returncode == 0, f"vtk fields export failed: {r.stderr}")
image = read_vtk(vtk.vtkXMLImageDataReader, WORK / "snapshot_fields.vti")
check(image.GetDimensions() == (7, 9, 1), f"vti dimensions {image.GetDimensions()}")
check(np.allclose(image.GetSpacing(), (lx / 6, ly / 8, 1)), f"vti spacing {image.GetSpacing()}")
count = vtk_to_numpy(image.GetCellData().GetArray("instant_count")).reshape(8, 6)
expected, _, _ = np.histogram2d(positions[-1][:, 1], positions[-1][:, 0], bins=[8, 6], range=[[0, ly], [0, lx]])
check(np.array_equal(count, expected), "cell counts differ from a histogram of the positions")
density = vtk_to_numpy(image.GetCellData().GetArray("instant_density")).reshape(8, 6)
check(np.allclose(density, expected / (lx / 6 * ly / 8), rtol=1e-12), "density is not count / cell area")
vx = vtk_to_numpy(image.GetCellData().GetArray("instant_velocity_x")).reshape(8, 6)
iy = np.minimum((positions[-1][:, 1] / ly * 8).astype(int), 7)
ix = np.minimum((positions[-1][:, 0] / lx * 6).astype(int), 5)
mean_vx = np.zeros((8, 6))
np.add.at(mean_vx, (iy, ix), velocities[-1][:, 0])
check(np.allclose(vx, mean_vx / np.maximum(expected, 1), atol=1e-12), "V_x is not the cell mean of v_x")

# VTK fields from a fields file (made here with h5py): every map round-trips exactly.
fields = WORK / "fields.h5"
rng = np.random.default_rng(1)
maps = {f"{g}/{q}": rng.random((2, 3, 4)) for g in ("instant", "average") for q in ("density", "temperature")}
with h5py.File(fields, "w") as f:
    f.attrs.update(nx=4, ny=3, length_x=2.0, length_y=1.5)
    f["frames/t"], f["frames/c"] = np.array([0.5, 1.5]), np.array([1.0, 2.0])
    for name, values in maps.items():
        f[name] = values
r = granule("plot", "export", fields, "--format", "vtk", "--what", "fields", "--all-frames")
check(r.returncode == 0, f"vtk export of fields.h5 failed: {r.stderr}")
datasets = ElementTree.parse(WORK / "fields.pvd").getroot().find("Collection").findall("DataSet")
check([float(d.get("timestep")) for d in datasets] == [0.5, 1.5], "fields.pvd timesteps")
for k, d in enumerate(datasets):
    image = read_vtk(vtk.vtkXMLImageDataReader, WORK / d.get("file"))
    check(image.GetDimensions() == (5, 4, 1) and np.allclose(image.GetSpacing(), (0.5, 0.5, 1)), f"fields vti {k} grid")
    for name, values in maps.items():
        array = image.GetCellData().GetArray(name.replace("/", "_"))
        check(array is not None and np.array_equal(vtk_to_numpy(array).reshape(3, 4), values[k]), f"{name} frame {k}")

# Bad input: exit code 2, the option named, nothing written.
bad = {
    "format": (["--format", "pdb"], "--format"),
    "what": (["--format", "vtk", "--what", "atoms"], "--what"),
    "xyz_fields": (["--format", "xyz", "--what", "fields"], "--format vtk"),
    "frame": (["--format", "xyz", "--frame", 10], "--frame"),
    "cells": (["--format", "vtk", "--what", "fields", "--cells", 0, 4], "--cells"),
}
for name, (args, expected) in bad.items():
    target = WORK / f"bad_{name}.out"
    r = granule("plot", "export", run, "--out", target, *args)
    check(r.returncode == 2, f"{name}: exit code {r.returncode} ({r.stderr.strip()})")
    check(expected in r.stderr, f"{name}: message lacks '{expected}': {r.stderr.strip()}")
    check(not target.exists() and not Path(f"{target}.partial").exists(), f"{name}: output written")

finish()
