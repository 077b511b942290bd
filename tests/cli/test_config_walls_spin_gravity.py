"""Bad input of the keys of walls, gravity and rough grains through the real `granule run`:
each must exit 2 with a message that names the key and what is allowed, and write nothing (its
--out directory is not created)."""
from harness import GRANULE, WORK, check, finish, granule

SMALL = ["--set", "system.particles=50", "--set", "run.until_collisions_per_particle=1"]

CASES = {
    "z walls in 2D": (["--set", 'boundary.kind="walls"', "--set", 'boundary.wall_axes=["z"]'],
                      ["boundary.wall_axes", "z walls need system.dimension = 3"]),
    "beta 1.5": (["--set", "system.tangential_restitution=1.5"], ["system.tangential_restitution = 1.5", "[-1, 1]"]),
    "gravity along y with Lees-Edwards": (["--set", 'boundary.kind="lees-edwards"', "--set", "boundary.shear_velocity=10",
                                           "--set", "system.gravity=[0, -1]"],
                                          ["system.gravity = [0, -1]", "lees-edwards", "walls"]),
    "wall restitution 0": (["--set", 'boundary.kind="walls"', "--set", "boundary.wall_restitution=0"],
                           ["boundary.wall_restitution = 0", "(0, 1]"]),
    "inertia factor of smooth grains": (["--set", "system.inertia_factor=0.4"],
                                        ["system.inertia_factor", "system.tangential_restitution"]),
    "segmented walls": (["--set", 'boundary.kind="walls"', "--set", "boundary.shear_velocity=10", "--set",
                         "boundary.shear_tolerance=0.01"], ["boundary.shear_tolerance", "exactly ±U(t)/2"]),
    "wall moving beyond the box": (["--set", 'boundary.kind="walls"', "--set",
                                    'boundary.wall_motion={ wall = "y0", amplitude = 1e3, frequency = 1 }'],
                                   ["boundary.wall_motion.amplitude", "1000"]),
}

for name, (overrides, fragments) in CASES.items():
    out = WORK / name.replace(" ", "_")
    result = granule("run", "--out", out, *SMALL, *overrides)
    check(result.returncode == 2, f"{name}: exit {result.returncode}, expected 2 (bad input); stderr: {result.stderr}")
    for fragment in fragments:
        check(fragment in result.stderr, f"{name}: '{fragment}' missing from: {result.stderr}")
    check(not out.exists(), f"{name}: {out} was created")

finish()
