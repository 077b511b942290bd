"""`granule plot export --format gsd` and granule.write_gsd: GSD files read back with python3-gsd's
gsd.hoomd API carry the arrays of snapshots.h5 in HOOMD's conventions."""
import gsd.hoomd
import h5py
import numpy as np

import granule


def run_dir(granule_cli, tmp_path, *settings):
    out = tmp_path / "run"
    result = granule_cli("run", "--out", out, "--set", "system.particles=300",
                         "--set", "run.until_collisions_per_particle=3",
                         "--set", "output.snapshot_every_collisions_per_particle=1", *settings)
    assert result.returncode == 0, result.stderr
    return out


def assert_frames_match(gsd_path, snapshots, frames):
    with h5py.File(snapshots) as f, gsd.hoomd.open(str(gsd_path), "rb") as trajectory:
        assert len(trajectory) == len(frames)
        d = int(f.attrs["dimension"])
        box = np.array(f.attrs["box"], dtype=float)
        n = int(f.attrs["particles"])
        for frame, k in zip(trajectory, frames):
            assert frame.particles.N == n
            assert frame.configuration.dimensions == d
            assert frame.configuration.step == f["collisions"][k]
            expected_box = list(box) + [0.0] * (3 - d) + [0.0, 0.0, 0.0]
            assert np.array_equal(frame.configuration.box, np.float32(expected_box))
            position = frame.particles.position
            assert np.array_equal(position[:, :d], np.float32(f["positions"][k] - box / 2))
            assert np.array_equal(frame.particles.velocity[:, :d], np.float32(f["velocities"][k]))
            if d == 2:
                assert np.all(position[:, 2] == 0) and np.all(frame.particles.velocity[:, 2] == 0)
            diameters = f["diameters"][()] if "diameters" in f else np.full(n, f.attrs["diameter"])
            assert np.array_equal(frame.particles.diameter, np.float32(diameters))
            masses = f["masses"][()] if "masses" in f else np.ones(n)
            assert np.array_equal(frame.particles.mass, np.float32(masses))
            assert frame.log["time"][0] == f["time"][k]
            if "spins" in f:
                assert np.array_equal(frame.log["particles/spin"].reshape(n, -1), np.asarray(f["spins"][k]).reshape(n, -1))


def test_all_frames_of_rough_disks(tmp_path, granule_cli):
    out = run_dir(granule_cli, tmp_path, "--set", "system.tangential_restitution=0.3")
    result = granule_cli("plot", "export", out, "--format", "gsd", "--all-frames")
    assert result.returncode == 0, result.stderr
    with h5py.File(out / "snapshots.h5") as f:
        frames = list(range(f["time"].shape[0]))
    assert len(frames) == 4
    assert_frames_match(out / "particles.gsd", out / "snapshots.h5", frames)


def test_one_frame_of_a_sphere_mixture_by_default_name(tmp_path, granule_cli):
    out = run_dir(granule_cli, tmp_path, "--set", "system.dimension=3", "--set", "system.box=[1, 1, 1]",
                  "--set", "system.packing_fraction=0.05",
                  "--set", 'system.diameters={distribution="bidisperse", ratio=2.0, fraction=0.5}')
    result = granule_cli("plot", "export", out, "--format", "gsd", "--frame", "-2")
    assert result.returncode == 0, result.stderr
    assert_frames_match(out / "particles_2.gsd", out / "snapshots.h5", [2])


def test_python_writer_is_the_cli_writer(tmp_path, granule_cli):
    out = run_dir(granule_cli, tmp_path)
    assert granule.write_gsd(out / "snapshots.h5", tmp_path / "all.gsd") == 4
    assert_frames_match(tmp_path / "all.gsd", out / "snapshots.h5", [0, 1, 2, 3])


def test_fields_cannot_be_gsd(tmp_path, granule_cli):
    out = run_dir(granule_cli, tmp_path)
    result = granule_cli("plot", "export", out, "--format", "gsd", "--what", "fields")
    assert result.returncode == 2 and "--format vtk" in result.stderr
