"""granule reproduce: `validation --scale tiny` writes report.md, a self-contained report.html (every
picture inline, no external resource), claims.csv and claims.json that agree with each other; every
verdict, in claims.json and in every row of claims.csv, follows from its numbers by the documented
rule (recomputed here independently), with a reason exactly when it is not resolvable; a second
call skips the finished runs; a damaged or incomplete summary.json is refused by name; an unknown study is refused with a clear
message and nothing written."""
import csv
import json
import math
import os
import re
import shutil
import subprocess

from claim_rule import VERDICTS, check_csv_verdicts, verdict
from harness import GRANULE, WORK, check, finish, granule

out = WORK / "report"
first = granule("reproduce", "validation", "--scale", "tiny", "--out", out, "--jobs", "2")
check(first.returncode == 0, f"reproduce validation exited {first.returncode}: {first.stderr[-2000:]}")
for name in ("report.md", "report.html", "claims.csv", "claims.json"):
    check((out / name).is_file(), f"{name} missing")
check("claims (tiny scale):" in first.stdout, "no claim summary on the terminal")

document = json.loads((out / "claims.json").read_text())
claims = [c for s in document["studies"] for c in s["claims"]]
check(len(claims) >= 8, f"only {len(claims)} claims")
check(len({c["id"] for c in claims}) == len(claims), "claim ids are not unique")
for c in claims:
    check(c["verdict"] in VERDICTS, f"{c['id']}: verdict {c['verdict']!r}")
    check(c["verdict"] == verdict(c), f"{c['id']}: verdict {c['verdict']} but the numbers give {verdict(c)}")
    check(c["statement"] and c["location"] and c["tolerance_reason"] and c["checked"], f"{c['id']}: an empty text field")
    check(c["measured"] is not None or c["verdict"] != "agrees", f"{c['id']}: agrees without a number")

rows = check_csv_verdicts(out / "claims.csv")
check([r["id"] for r in rows] == [c["id"] for c in claims], "claims.csv and claims.json list different claims")
for r, c in zip(rows, claims):
    check(r["verdict"] == c["verdict"], f"{r['id']}: csv verdict {r['verdict']} vs json {c['verdict']}")
    expected = float(r["expected"])
    check(math.isclose(expected, c["expected"], rel_tol=1e-12), f"{r['id']}: csv expected {expected} vs json {c['expected']}")

page = (out / "report.html").read_text()
images = re.findall(r'<img[^>]*src="([^"]*)"', page)
check(len(images) >= 2, f"{len(images)} pictures in report.html")
check(all(src.startswith("data:image/png;base64,") for src in images), "a picture of report.html is not inline")
check(not re.search(r'(src|href)="(https?:|//|file:)', page), "report.html refers to an external resource")
check("agree" in page and "Henderson" in page, "report.html lacks the claims table")
markdown = (out / "report.md").read_text()
check(all(c["id"].split(".")[0] in markdown or c["statement"][:20] in markdown for c in claims), "report.md lacks claims")

again = granule("reproduce", "validation", "--scale", "tiny", "--out", out)
check(again.returncode == 0, f"second call exited {again.returncode}")
check(again.stdout.count("skipped") >= 5 and "finished in" not in again.stdout, "second call ran points again")

# A finished run's summary.json is read as untrusted input: one cut short, and one without a number a
# claim reads, are refused by file and key (exit 2) rather than judged as NaN.
summaries = sorted(out.glob("runs/validation/*/runs/*/summary.json"))
check(len(summaries) >= 5, f"{len(summaries)} summaries of the tiny runs")
kept = summaries[0].read_text()
summaries[0].write_text(kept[: len(kept) // 2])
cut = granule("reproduce", "validation", "--scale", "tiny", "--out", out)
check(cut.returncode == 2 and str(summaries[0]) in cut.stderr and "delete" in cut.stderr,
      f"a summary.json cut short is refused by name: {cut.returncode} {cut.stderr[-400:]}")
without = json.loads(kept)
del without["diameter"]
summaries[0].write_text(json.dumps(without))
missing = granule("reproduce", "validation", "--scale", "tiny", "--out", out)
check(missing.returncode == 2 and '"diameter" is missing' in missing.stderr and str(summaries[0].parent) in missing.stderr,
      f"a summary.json without a number a claim reads is refused by key: {missing.returncode} {missing.stderr[-400:]}")
summaries[0].write_text(kept)

# Over MPI ranks (three: rank 0 hands out, two run): the same runs, hence the same numbers.
mpi_out = WORK / "report_mpi"
probe = granule("reproduce", "validation", "--scale", "tiny", "--out", WORK / "probe", "--mpi")
if "built without MPI" in probe.stderr or shutil.which("mpirun") is None:
    print("SKIPPED: reproduce --mpi (granule built without MPI or no mpirun)")
else:
    shutil.rmtree(WORK / "probe", ignore_errors=True)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    mpi = subprocess.run(["mpirun", "--oversubscribe", "-n", "3", GRANULE, "reproduce", "validation", "--scale", "tiny", "--out",
                          str(mpi_out), "--mpi"], capture_output=True, text=True, timeout=300, env=env)
    check(mpi.returncode == 0, f"reproduce --mpi exited {mpi.returncode}: {mpi.stderr[-2000:]}")
    if mpi.returncode == 0:
        with open(mpi_out / "claims.csv", newline="") as f:
            mpi_rows = list(csv.DictReader(f))
        numbers = ("id", "expected", "measured", "error", "verdict")
        check([[r[k] for k in numbers] for r in mpi_rows] == [[r[k] for k in numbers] for r in rows],
              "reproduce --mpi gives other numbers than --jobs 2")

def tiny_study_claims(study):
    """Runs one study at tiny scale; returns its claims (in order) and report.md, or None if it failed."""
    target = WORK / study
    run = granule("reproduce", study, "--scale", "tiny", "--out", target, "--jobs", "2")
    check(run.returncode == 0, f"reproduce {study} exited {run.returncode}: {run.stderr[-2000:]}")
    if run.returncode != 0:
        return None
    sections = [s for s in json.loads((target / "claims.json").read_text())["studies"] if s["name"] == study]
    check(len(sections) == 1, f"{study}: not one section in claims.json")
    found = [c for s in sections for c in s["claims"]]
    check_csv_verdicts(target / "claims.csv")
    for c in found:
        check(c["verdict"] == verdict(c), f"{c['id']}: verdict {c['verdict']} but the numbers give {verdict(c)}")
        check(c["statement"] and c["location"] and c["tolerance_reason"] and c["checked"], f"{c['id']}: an empty text field")
    return found, (target / "report.md").read_text()


# Chapters 4 and 5: every claim the studies promise is there, with a number (chapter 4's come from
# the time series and fields.h5 of every tiny run), a verdict that follows from it, and the figures
# with their thesis numbers in report.md.
CHAPTER_CLAIMS = {
    "chapter4": ["chapter4.cold_start.quasihomogeneous", "chapter4.cold_start.temperature_T0", "chapter4.hot_start.plugged",
                 "chapter4.ramp.plug", "chapter4.ramp.two_layers", "chapter4.ramp.plug_central", "chapter4.ramp.plug_colder",
                 "chapter4.ramp.heat_flux_to_plug", "chapter4.ramp.plug_persists", "chapter4.step.plug", "chapter4.step.plug_central",
                 "chapter4.kick.no_recovery", "chapter4.kick_small.no_recovery"],
    "chapter5": [f"chapter5.e={e}.{name}" for e in ("0.6", "0.9")
                 for name in ("linear_term", "ratio_fig5_9", "quadratic_anisotropy", "stress_once", "stress_twice",
                              "linear_term.literal_v", "ratio_fig5_9.literal_v")]
                + ["chapter5.ratio_falls_with_e"],
}
CHAPTER_FIGURES = {"chapter4": ["Figs 4.5–4.8", "Figs 4.7–4.8"], "chapter5": ["Fig 5.9", "Fig 5.10", "Fig 5.11"]}
for study, ids in CHAPTER_CLAIMS.items():
    result = tiny_study_claims(study)
    if result is None:
        continue
    found, markdown = result
    check([c["id"] for c in found] == ids, f"{study} claims {[c['id'] for c in found]}")
    for c in found:
        if study == "chapter4" or not c["unresolvable"]:
            check(c["measured"] is not None, f"{c['id']}: no measured number")
    for figure in CHAPTER_FIGURES[study]:
        check(figure in markdown, f"{study}: report.md lacks {figure}")
    # report.md escapes the | of a statement inside its table.
    check(all(c["statement"].replace("|", "\\|") in markdown for c in found), f"{study}: report.md lacks claims")

# The appendices at tiny scale (numbers meaningless, except the checks below that a broken pipeline fails):
# every claim of Appendix B and C appears in claims.json and report.md with a verdict that follows from its
# numbers, every figure with its thesis figure number and a drawn picture.
APPENDIX_CLAIMS = {
    "appendix-b": [f"appendix_b.e={e}.{k}" for e in ("0.6", "0.7", "0.8", "0.9")
                   for k in ("b1_magnitude", "b2_magnitude", "b1_density_trend", "b1_magnitude.profile_removed",
                             "b1_density_trend.profile_removed")],
    "appendix-c": ["appendix_c.fig_c1.early_decay", "appendix_c.fig_c1.onset_as_2d", "appendix_c.fig_c2.clusters_in_flow_plane",
                   "appendix_c.fig_c3.plug_is_streamwise", "appendix_c.fig_c3.plug_in_centre",
                   "appendix_c.fig_c4.neighbours_spin_opposite", "appendix_c.fig_c5.plug_is_streamwise",
                   "appendix_c.fig_c5.plug_in_centre", "appendix_c.fig_c5.static_start.plug_is_streamwise",
                   "appendix_c.fig_c5.static_start.plug_in_centre"],
}
APPENDIX_FIGURES = {"appendix-b": "Appendix B", "appendix-c": "Fig C."}
appendix = {}
for study, ids in APPENDIX_CLAIMS.items():
    result = tiny_study_claims(study)
    if result is None:
        continue
    target = WORK / study
    got = {c["id"]: c for c in result[0]}
    markdown = result[1]
    appendix.update(got)
    check(sorted(got) == sorted(ids), f"{study}: claims {sorted(got)}, expected {sorted(ids)}")
    for c in got.values():
        check(c["statement"] in markdown.replace("\\|", "|"), f"{c['id']}: not in report.md")
    figures = sorted((target / "figures").glob("*.json"))
    check(len(figures) >= 4, f"{study}: {len(figures)} figures")
    for f in figures:
        check(json.loads(f.read_text())["title"].startswith(APPENDIX_FIGURES[study]), f"{f.name}: no thesis figure number")
        check(f.with_suffix(".png").is_file(), f"{f.name}: not drawn")
# Numbers a broken pipeline would miss even at tiny scale: b0^(2) ≈ 1/2T is robust, so its ratio to the table
# mapped to the run's units (a = u = 10 at N = 2000) is near 1 where a wrong map is off by u² = 100; the
# spheres' early cooling follows the 3D Haff rate; the rough-disk spin claim is measured by `granule analyze
# spins` (a C_contact in [-1, 1] counted over pairs in contact) and its verdict follows from its numbers.
b2 = [appendix[f"appendix_b.e={e}.b2_magnitude"]["measured"] for e in ("0.6", "0.7", "0.8", "0.9")
      if f"appendix_b.e={e}.b2_magnitude" in appendix]
check(any(m is not None for m in b2), "appendix-b: no b0^(2) measured at all (granule analyze f1 did not run?)")
check(all(m is None or 1 / 3 < m < 3 for m in b2), f"appendix-b: b0^(2) ratios {b2} (the unit map?)")
decay = appendix.get("appendix_c.fig_c1.early_decay", {})
check(decay.get("measured") is not None and abs(decay["measured"] / decay["expected"] - 1) < 0.3,
      f"appendix-c: early decay {decay.get('measured')} against {decay.get('expected')}")
spin = appendix.get("appendix_c.fig_c4.neighbours_spin_opposite", {})
check(spin.get("measured") is not None and -1.0 <= spin["measured"] <= 1.0 and "pairs in contact" in spin.get("checked", ""),
      f"appendix-c: the spin claim {spin}")
check(spin.get("tolerance_kind") == "sign", f"appendix-c: the spin claim is not a sign claim: {spin}")
check(spin.get("verdict") in ("agrees", "disagrees") or spin.get("verdict_reason", ""), f"appendix-c: the spin claim {spin}")
trends = [appendix[f"appendix_b.e={e}.b1_density_trend"] for e in ("0.6", "0.7", "0.8", "0.9")
          if f"appendix_b.e={e}.b1_density_trend" in appendix]
check(all(c["tolerance_kind"] == "sign" for c in trends), f"appendix-b: a density trend that is not a sign claim: {trends}")

for study, message in (("chapter9", "unknown study"),):
    target = WORK / study
    refused = granule("reproduce", study, "--scale", "tiny", "--out", target)
    check(refused.returncode == 2, f"reproduce {study} exited {refused.returncode}")
    check(message in refused.stderr, f"reproduce {study}: {refused.stderr!r}")
    check(not target.exists(), f"reproduce {study} wrote {target}")
bad_scale = granule("reproduce", "validation", "--scale", "huge", "--out", WORK / "huge")
check(bad_scale.returncode == 2 and "--scale huge" in bad_scale.stderr, f"--scale huge: {bad_scale.stderr!r}")

finish()
