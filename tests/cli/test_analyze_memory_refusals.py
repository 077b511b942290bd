"""End-to-end: analyses that would need more memory than the machine has are refused before they
allocate it — `analyze spectra --max-mode 256` of a small 3D run (an FFT grid of 1080³ complex values
and 513³ modes, ~33 GiB), `analyze fields --cells 16384,16384` of a 2D run (~80 GiB of cell moments
and fields) `analyze collisions --set fields.cells=[16384,16384]` and `analyze f1` of 250 frames binned on
4096 × 4096 speeds and angles (~34 GiB), and `run` with a fields grid whose 673 B per cell exceed the
memory, exit 5 at once with a message
that names the option and write nothing; the same commands with small grids still run.  The refusals
are checked only where the machine has less memory than they need (MemAvailable or the cgroup limit,
as Granule reads it)."""
import math
import time

from harness import WORK, check, finish, granule

GiB = 2 ** 30


def available_memory_bytes():
    available = 0
    with open("/proc/meminfo") as meminfo:
        for line in meminfo:
            if line.startswith("MemAvailable:"):
                available = int(line.split()[1]) * 1024
    try:
        with open("/sys/fs/cgroup/memory.max") as limit:
            cgroup = int(limit.read())
        if cgroup > 0 and (available == 0 or cgroup < available):
            available = cgroup
    except (OSError, ValueError):  # no cgroup v2 limit, or "max"
        pass
    return available


def simulate(name, *settings):
    result = granule("run", "--out", str(WORK / name), "--set", "system.particles=400", "--set",
                     "run.until_collisions_per_particle=2", "--set", "output.snapshot_every_collisions_per_particle=1",
                     *settings)
    check(result.returncode == 0, f"run {name} failed: {result.stderr}")
    return WORK / name


def refused(what, args, option, out):
    """`granule args` exits 5 within seconds, naming `option`, and leaves no `out` (nor its partial file)."""
    start = time.monotonic()
    result = granule(*args)
    seconds = time.monotonic() - start
    check(result.returncode == 5, f"{what}: exit {result.returncode}, expected 5: {result.stderr}")
    check(option in result.stderr and "GiB" in result.stderr and "available" in result.stderr,
          f"{what}: the message names {option} and the memory: {result.stderr!r}")
    check(seconds < 30, f"{what}: refused after {seconds:.1f} s, not before the work")
    leftovers = [p.name for p in out.parent.glob(out.name + "*")]
    check(not leftovers, f"{what}: wrote {leftovers}")


def ran(what, args, out):
    result = granule(*args)
    check(result.returncode == 0, f"{what}: exit {result.returncode}: {result.stderr}")
    check(out.exists(), f"{what}: no {out.name}")


available = available_memory_bytes()
spheres = simulate("spheres", "--set", "system.dimension=3", "--set", "system.box=[1, 1, 1]", "--set",
                   "system.packing_fraction=0.05")
disks = simulate("disks", "--set", "system.area_fraction=0.05")

if 0 < available < 30 * GiB:
    out = WORK / "spectra_256.h5"
    refused("analyze spectra --max-mode 256 (3D)",
            ["analyze", "spectra", spheres / "snapshots.h5", "--max-mode", "256", "--out", out], "--max-mode 256", out)
else:
    print(f"skipped the 3D spectra refusal: {available / GiB:.0f} GiB available")
if 0 < available < 75 * GiB:
    out = WORK / "fields_16384.h5"
    refused("analyze fields --cells 16384,16384 (2D)",
            ["analyze", "fields", disks / "snapshots.h5", "--cells", "16384,16384", "--out", out], "--cells 16384,16384",
            out)
    out = WORK / "replay_16384"
    refused("analyze collisions --set fields.cells=[16384,16384]",
            ["analyze", "collisions", disks, "--set", "fields.cells=[16384,16384]", "--out", out], "fields.cells = [16384, 16384]", out)
    # A run whose fields grid alone needs more than the machine has (673 B per 2D cell, measured),
    # though half as much per cell would fit: refused before it writes, naming the grid.
    side = math.ceil(math.sqrt(available / 500))
    out = WORK / "run_fields"
    refused(f"run --set fields.cells=[{side},{side}]",
            ["run", "--out", out, "--set", "system.particles=400", "--set", f"fields.cells=[{side}, {side}]"],
            f"fields.cells = [{side}, {side}]", out)
else:
    print(f"skipped the field grid refusals: {available / GiB:.0f} GiB available")
if 0 < available < 30 * GiB:
    # 250 frames, each binned on 4096 × 4096 speeds and angles for the bootstrap: ~34 GiB.
    frames = simulate("frames", "--set", "system.area_fraction=0.05", "--set", "output.snapshot_every_collisions_per_particle=0.01",
                      "--set", "run.until_collisions_per_particle=2.5")
    out = WORK / "f1_4096.h5"
    refused("analyze f1 --speed-bins 4096 --angle-bins 4096",
            ["analyze", "f1", frames / "snapshots.h5", "--density-window", "400±400", "--temperature-window", "1e6±1e6",
             "--speed-bins", "4096", "--angle-bins", "4096", "--out", out], "--speed-bins 4096 --angle-bins 4096", out)
else:
    print(f"skipped the f1 refusal: {available / GiB:.0f} GiB available")

# Grids the machine holds are analysed as before.
out = WORK / "spectra_small.h5"
ran("analyze spectra --max-mode 8 (3D)", ["analyze", "spectra", spheres / "snapshots.h5", "--max-mode", "8", "--out", out],
    out)
out = WORK / "fields_small.h5"
ran("analyze fields --cells 8,8", ["analyze", "fields", disks / "snapshots.h5", "--cells", "8,8", "--out", out], out)

finish()
