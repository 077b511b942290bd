"""docs/reproduce.md's verdict tables and tally are those of the committed report's claims.csv
(docs/report/small/): scripts/claims_tables.py finds no block that differs from it; every committed
verdict follows from its own numbers by the documented rule (tests/cli/claim_rule.py); and a page
whose table or tally no longer matches its claims.csv is caught (a copy of the page with one measured
number changed in its claims.csv, one with a verdict changed in its text), so the check can fail."""
import csv
import shutil
import subprocess
import sys
from pathlib import Path

from claim_rule import check_csv_verdicts
from harness import WORK, check, finish

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "scripts" / "claims_tables.py"
PAGE = ROOT / "docs" / "reproduce.md"
CLAIMS = ROOT / "docs" / "report" / "small" / "claims.csv"


def tables(page):
    return subprocess.run([sys.executable, SCRIPT, page], capture_output=True, text=True, timeout=60)


result = tables(PAGE)
check(result.returncode == 0, f"docs/reproduce.md's tables are its claims.csv's: {result.stdout}{result.stderr}")

rows = check_csv_verdicts(CLAIMS)
check(len(rows) >= 60 and len({r["study"] for r in rows}) == 7, f"the committed report has every study: {len(rows)} claims")

# A copy of the page and its report, one measured number changed: the table no longer matches.
copy = WORK / "docs"
shutil.copytree(ROOT / "docs" / "report", copy / "report")
shutil.copy(PAGE, copy / "reproduce.md")
with open(copy / "report" / "small" / "claims.csv", newline="") as f:
    changed = list(csv.DictReader(f))
changed[0]["measured"] = str(float(changed[0]["measured"]) * 1.5)
with open(copy / "report" / "small" / "claims.csv", "w", newline="") as f:
    writer = csv.DictWriter(f, fieldnames=list(changed[0]))
    writer.writeheader()
    writer.writerows(changed)
result = tables(copy / "reproduce.md")
check(result.returncode == 1 and f"study={changed[0]['study']}" in result.stdout,
      f"a changed number in claims.csv is caught: {result.returncode} {result.stdout}")

# The page's text changed by hand (one verdict): caught, and --write restores it.
shutil.copy(CLAIMS, copy / "report" / "small" / "claims.csv")
text = PAGE.read_text()
(copy / "reproduce.md").write_text(text.replace("| **disagrees** |", "| agrees |", 1))
result = tables(copy / "reproduce.md")
check(result.returncode == 1, f"a verdict typed by hand is caught: {result.returncode} {result.stdout}")
subprocess.run([sys.executable, SCRIPT, "--write", copy / "reproduce.md"], check=True, timeout=60)
check((copy / "reproduce.md").read_text() == text, "--write regenerates the page as committed")
finish()
