"""The verdict rule of docs/reproduce.md ("The verdict"), written anew from its words, for the tests
that check `granule reproduce`'s verdicts against their own numbers."""
import csv
import math

from harness import check

VERDICTS = {"agrees", "disagrees", "not resolvable at this scale"}


def verdict(claim):
    """The rule of docs/reproduce.md, written anew from its words."""
    e, m, s, t, kind = claim["expected"], claim["measured"], claim["error"], claim["tolerance"], claim["tolerance_kind"]
    if claim["unresolvable"] or m is None or e is None:
        return "not resolvable at this scale"
    two_sigma = 2 * abs(s) if s is not None else 0.0  # no error: the mean alone is judged
    if kind == "sign":
        if e == 0:
            return "not resolvable at this scale"
        low, high = m - two_sigma, m + two_sigma
        if (low > 0 and e > 0) or (high < 0 and e < 0):
            return "agrees"
        if (high < 0 and e > 0) or (low > 0 and e < 0):
            return "disagrees"
        return "not resolvable at this scale"
    if kind == "relative":
        low, high = e - t * abs(e), e + t * abs(e)
    elif kind == "absolute":
        low, high = e - t, e + t
    else:
        low, high = sorted((e / t, e * t))
    if low <= m <= high:
        return "not resolvable at this scale" if two_sigma > high - low else "agrees"
    reaches = m + two_sigma >= low if m < low else m - two_sigma <= high
    return "not resolvable at this scale" if reaches else "disagrees"


def number(field):
    """A number of claims.csv (17 digits, "nan" when missing) as claims.json has it (None when missing)."""
    x = float(field)
    return None if math.isnan(x) else x


def check_csv_verdicts(path):
    """Every row of a claims.csv: its verdict recomputed from its own mean, error and band, and a
    reason given exactly when it is not resolvable.  Returns the rows."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        claim = {k: number(r[k]) for k in ("expected", "measured", "error", "tolerance")}
        claim.update(tolerance_kind=r["tolerance_kind"], unresolvable=r["unresolvable"])
        check(r["verdict"] == verdict(claim), f"{path.parent.name}/{r['id']}: csv verdict {r['verdict']} but its numbers "
              f"give {verdict(claim)}")
        check(bool(r["verdict_reason"]) == (r["verdict"] == "not resolvable at this scale"),
              f"{r['id']}: verdict {r['verdict']} with the reason {r['verdict_reason']!r}")
    return rows
