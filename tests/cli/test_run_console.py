"""What `granule run` says: the collision model in force (including the TC model of the built-in
example), that the built-in example is in use, and as the last line every file the invocation wrote
— compared with the files actually in the directory."""
import time

from harness import WORK, check, finish, granule


def files_in(directory):
    return sorted(str(p.relative_to(directory)) for p in directory.rglob("*") if p.is_file())


# The built-in example (scaled down by --set): TC on with its t_c, said so.
out = WORK / "example"
r = granule("run", "--out", out, "--set", "system.particles=500", "--set", "run.until_collisions_per_particle=4",
            "--set", "output.snapshot_every_collisions_per_particle=2", "--set", "initial.equilibrate=1")
check(r.returncode == 0, f"example run failed: {r.stderr}")
lines = r.stdout.strip().splitlines()
model = [line for line in lines if line.startswith("collision model:")]
check(len(model) == 1 and "TC model" in model[0] and "t_c = 1e-07" in model[0], f"collision model line: {model}")
check(any(line.startswith("config: the built-in example") and "4 --set overrides" in line for line in lines),
      f"built-in example named: {lines}")
listed = lines[-1].split(": ", 1)[1].rsplit(" (", 1)[0].split(", ")
check(lines[-1].startswith(f"files written in {out}:") and listed == files_in(out),
      f"last line lists every file: {lines[-1]!r} vs {files_in(out)}")

# TC off: said so too; a resume lists what it rewrote, not the files it left alone.
out = WORK / "plain"
r = granule("run", "--out", out, "--set", "system.particles=500", "--set", "system.tc_duration=0", "--set",
            "run.until_collisions_per_particle=2", "--set", "output.snapshot_every_collisions_per_particle=1",
            "--set", "initial.equilibrate=1")
check(r.returncode == 0 and "TC model off" in r.stdout, f"TC off said: {r.stdout}")
(out / "notes.txt").write_text("kept by the user\n")
time.sleep(0.3)  # more than the 50 ms margin the run allows the file system's coarse clock
r = granule("run", "--resume", out, "--set", "run.until_collisions_per_particle=3")
last = r.stdout.strip().splitlines()[-1]
check(r.returncode == 0 and "notes.txt" not in last and "checkpoint.h5" in last, f"resume lists its own files: {last}")
finish()
