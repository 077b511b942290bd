"""The figure scripts against the mutants Granule's reading layer accepted: the second half of the
file fuzz of the measurement files that only figure scripts read (collisions.h5, spectra.h5, f1.h5,
spins.h5).

    figure_fuzz.py FUZZER SCRIPT ORIGINAL SEED ACCEPTED WORK [SCRIPT OPTIONS...]

ACCEPTED lists the indices of the mutants of ORIGINAL that `granule_file_fuzz SCRIPT` found to hold
what the file's schema says (the check `granule plot` makes before it starts a script); with
GRANULE_FUZZ_FIGURE_MUTANTS=N, N of them spread evenly over the list (a figure takes a second or
two, a schema check a millisecond).  Each is
written again (`FUZZER mutate`) and drawn by the script's main in a child process forked after the
script and matplotlib were imported once (a figure costs its drawing, not an interpreter), as
`granule plot` runs it: the child must exit with 0 (a figure) or 2 (refused) within the time limit,
never crash, raise past the script's guard, or write anything but its figure.  Prints
"plot SCRIPT: N mutants, C drawn, R refused, F failed" and exits 1 when F > 0.
"""
import importlib
import os
import shutil
import signal
import subprocess
import sys
from pathlib import Path

SECONDS_PER_MUTANT = 60
PLOTS = Path(__file__).resolve().parents[2] / "python" / "granule_plots"


def files_under(path):
    return {p for p in path.rglob("*") if p.is_file()}


def draw_in_child(module, common, arguments, out, log):
    """Runs the script's main as `granule plot` would, in a child printing to `log`; returns its wait status."""
    pid = os.fork()
    if pid == 0:
        code = 70
        try:
            printed = os.open(log, os.O_WRONLY | os.O_TRUNC)
            os.dup2(printed, 1)
            os.dup2(printed, 2)
            os.chdir(out)
            signal.alarm(SECONDS_PER_MUTANT)
            sys.argv = [f"{module.__name__}.py", *arguments]
            common.run(module.main)
            code = 0
        except SystemExit as done:  # sys.exit(None), a main that returned nothing, is success
            code = 0 if done.code is None else done.code if isinstance(done.code, int) else 1
        except BaseException:  # past the script's guard: a failure, reported by its exit code
            import traceback

            traceback.print_exc()
            code = 70
        os._exit(code)
    _, status = os.waitpid(pid, 0)
    return status


def main():
    fuzzer, script, original, seed, accepted, work = sys.argv[1:7]
    options = sys.argv[7:]
    work = Path(work)
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    sys.path.insert(0, str(PLOTS))
    common = importlib.import_module("_common")
    module = importlib.import_module(script)
    indices = [int(line) for line in Path(accepted).read_text().split()]
    most = int(os.environ.get("GRANULE_FUZZ_FIGURE_MUTANTS", "0"))
    if 0 < most < len(indices):  # evenly over the list, every kind of edit the mutator makes kept in
        indices = [indices[k * len(indices) // most] for k in range(most)]
    drawn = refused = 0
    failures = []
    for index in indices:
        mutant, out, log = work / "mutant.h5", work / "out", work / "printed.txt"
        made = subprocess.run([fuzzer, "mutate", original, mutant, seed, str(index)], capture_output=True, text=True)
        if made.returncode != 0:
            failures.append(f"mutant {seed}/{index} could not be written again: {made.stderr.strip()}")
            continue
        shutil.rmtree(out, ignore_errors=True)
        out.mkdir()
        log.write_text("")
        before = files_under(work)
        status = draw_in_child(module, common, [str(mutant), "--out", str(out / "figure.png"), *options], out, log)
        label = f"plot {script} on mutant {seed}/{index} ({made.stdout.strip()})"
        if os.WIFSIGNALED(status):
            signal_number = os.WTERMSIG(status)
            failures.append(f"{label}: " + ("no result within the time limit" if signal_number == signal.SIGALRM
                                             else f"died of signal {signal_number}"))
        elif os.WEXITSTATUS(status) == 0:
            drawn += 1
        elif os.WEXITSTATUS(status) == 2:
            refused += 1
        else:
            failures.append(f"{label}: exit {os.WEXITSTATUS(status)}: {log.read_text()[-800:]}")
        stray = [p for p in files_under(work) - before if out not in p.parents]
        if stray:
            failures.append(f"{label}: wrote outside its output: {sorted(map(str, stray))[:3]}")
    for failure in failures:
        print("FAIL:", failure)
    print(f"plot {script}: {len(indices)} mutants, {drawn} drawn, {refused} refused, {len(failures)} failed")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
