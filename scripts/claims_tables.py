#!/usr/bin/env python3
"""The tables of `granule reproduce`'s verdicts in a Markdown page, generated from a report's
claims.csv, never typed by hand.

A page marks each generated block with a pair of comments; the first names the claims.csv (relative
to the page) and, optionally, one study:

    <!-- claims-table report/small/claims.csv study=chapter4 -->
    ... generated ...
    <!-- end claims-table -->

    <!-- claims-tally report/small/claims.csv -->
    ... generated ...
    <!-- end claims-tally -->

    scripts/claims_tables.py docs/reproduce.md          # exit 1 if a block differs from its claims.csv
    scripts/claims_tables.py --write docs/reproduce.md  # regenerate the blocks in place

Only the standard library: it runs wherever the tests run.
"""
import argparse
import csv
import math
import re
import sys
from pathlib import Path

BLOCK = re.compile(r"(<!-- claims-(table|tally) (\S+)((?: \w+=\S+)*) -->\n)(.*?)(<!-- end claims-\2 -->)", re.S)
VERDICTS = ("agrees", "disagrees", "not resolvable at this scale")


def number(text):
    """A number of claims.csv ("nan" when missing) as the tables show it: 4 significant digits."""
    x = float(text)
    return "—" if not math.isfinite(x) else f"{x:.4g}"


def band(row):
    """The band the verdict judges the measured mean against (src/reproduce/claim.hpp)."""
    e, t, kind = float(row["expected"]), float(row["tolerance"]), row["tolerance_kind"]
    if kind == "sign":
        return "> 0" if e > 0 else "< 0"
    if kind == "relative":
        low, high = e - t * abs(e), e + t * abs(e)
    elif kind == "absolute":
        low, high = e - t, e + t
    elif kind == "factor":
        low, high = sorted((e / t, e * t))
    else:
        raise ValueError(f"claim {row['id']}: unknown tolerance_kind {kind!r}")
    return f"[{low:.4g}, {high:.4g}]"


def measured(row):
    m, err = float(row["measured"]), float(row["error"])
    if not math.isfinite(m):
        return "—"
    return f"{m:.4g} ± {err:.2g}" if math.isfinite(err) else f"{m:.4g}"


def cell(text):
    return text.replace("|", "\\|").replace("\n", " ")


def read_claims(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        if r["verdict"] not in VERDICTS:
            raise ValueError(f"{path}: claim {r['id']} has the verdict {r['verdict']!r}")
    return rows


def table(rows):
    lines = ["| claim | where | expected | measured | band | verdict |", "|---|---|---|---|---|---|"]
    for r in rows:
        verdict = f"**{r['verdict']}**" if r["verdict"] == "disagrees" else r["verdict"]
        lines.append(f"| {cell(r['statement'])} (`{r['id']}`) | {cell(r['location'])} | {number(r['expected'])} | "
                     f"{measured(r)} | {band(r)} | {verdict} |")
    return "\n".join(lines) + "\n"


def tally(rows):
    def counts(subset):
        return [sum(r["verdict"] == v for r in subset) for v in VERDICTS]

    studies = list(dict.fromkeys(r["study"] for r in rows))
    a, d, u = counts(rows)
    per_study = ", ".join(f"{s} {'/'.join(map(str, counts([r for r in rows if r['study'] == s])))}" for s in studies)
    return (f"{len(rows)} claims: {a} agree, {d} disagree, {u} not resolvable at this scale "
            f"(per study, agree/disagree/not resolvable: {per_study}).\n")


def generate(page, match):
    kind, source, options = match.group(2), page.parent / match.group(3), match.group(4)
    rows = read_claims(source)
    selected = dict(o.split("=", 1) for o in options.split())
    if "study" in selected:
        rows = [r for r in rows if r["study"] == selected["study"]]
        if not rows:
            raise ValueError(f"{page}: {source} has no claims of study {selected['study']!r}")
    return table(rows) if kind == "table" else tally(rows)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("pages", nargs="+", type=Path, help="Markdown pages with claims-table/claims-tally blocks")
    parser.add_argument("--write", action="store_true", help="regenerate the blocks in place")
    args = parser.parse_args()
    stale = []
    for page in args.pages:
        text = page.read_text()
        blocks = list(BLOCK.finditer(text))
        if not blocks:
            sys.exit(f"{page}: no claims-table or claims-tally block")
        out, at = [], 0
        for m in blocks:
            fresh = generate(page, m)
            if m.group(5) != fresh:
                stale.append(f"{page}: the {m.group(2)} block of {m.group(3)}{m.group(4)}")
            out += [text[at:m.start(5)], fresh]
            at = m.end(5)
        out.append(text[at:])
        if args.write:  # whole or not at all
            scratch = page.with_name(page.name + ".tmp")
            scratch.write_text("".join(out))
            scratch.replace(page)
    if stale and not args.write:
        print("differs from its claims.csv (regenerate with scripts/claims_tables.py --write):", *stale, sep="\n  ")
        sys.exit(1)


if __name__ == "__main__":
    main()
