"""Shared fixtures: the granule command of this build and a small fast configuration."""
import os
import subprocess

import pytest


@pytest.fixture
def granule_cli():
    """Runs the build's `granule` command; returns the CompletedProcess."""
    executable = os.environ["GRANULE_EXECUTABLE"]

    def run(*args):
        return subprocess.run([executable, *map(str, args)], capture_output=True, text=True, timeout=120)

    return run


@pytest.fixture
def small_config():
    """Free cooling of 500 disks at ν = 0.1 (a fraction of a second per run)."""
    return {
        "seed": 7,
        "system": {"particles": 500, "packing_fraction": 0.1, "restitution": 0.8},
        "run": {"until_collisions_per_particle": 5},
        "output": {"snapshot_every_collisions_per_particle": 1},
    }
