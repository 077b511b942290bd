// One checked statement of the thesis or of the literature (a row of the report's claims table,
// docs/reproduce.md): what is claimed and where, the number claimed, Granule's number with its
// statistical error, the tolerance and why it is that wide, and the verdict.
#pragma once

#include <limits>
#include <string>

namespace granule::reproduce {

enum class Verdict { agrees, disagrees, not_resolvable };

// "agrees", "disagrees", "not resolvable at this scale".
std::string verdict_text(Verdict verdict);

// How the tolerance bounds the measured number around the expected one: relative, |m − e| ≤ t|e|;
// absolute, |m − e| ≤ t; factor, e/t ≤ m ≤ e·t (for order-of-magnitude estimates, t > 1); sign, the
// claim is the sign of e alone (the band is the half-line of e's sign, t unused).
enum class ToleranceKind { relative, absolute, factor, sign };

// "relative", "absolute", "factor", "sign": the tolerance_kind column of claims.csv/json.
const char* tolerance_kind_name(ToleranceKind kind);

struct Claim {
  std::string id;         // unique within the report: "validation.henderson_pressure.nu=0.30"
  std::string statement;  // what is claimed, in words
  std::string location;   // where: "thesis eq (3.1), Fig 3.2" or "Henderson, Mol. Phys. 30 (1975)"
  double expected = 0.0;  // the number claimed (from the thesis, or src/theory for literature)
  double measured = std::numeric_limits<double>::quiet_NaN();
  double error = std::numeric_limits<double>::quiet_NaN();  // one standard error of `measured`
  double tolerance = 0.0;
  ToleranceKind tolerance_kind = ToleranceKind::relative;
  std::string tolerance_reason;  // why the tolerance is that wide (fixed before the runs, never fitted)
  std::string checked;           // how Granule's number was measured: runs, columns, window, seeds
  std::string unresolvable;      // non-empty: why this scale (or a missing analysis) cannot decide
};

// A verdict and, when it is "not resolvable", why (empty otherwise).
struct Judgement {
  Verdict verdict;
  std::string reason;
};

// The verdict of a claim, from its numbers alone (σ its error; none, or 0, counts as 2σ = 0):
// - not resolvable when `unresolvable` says so or a number is missing (not finite);
// - a band claim (relative, absolute, factor) agrees when the mean lies in the closed band and 2σ is
//   not wider than the band; with the mean inside but 2σ wider it is not resolvable (an agreement
//   would mean nothing); with the mean outside it disagrees when the whole ±2σ interval misses the
//   band, and is not resolvable when ±2σ still reaches it (more statistics would decide);
// - a sign claim agrees when the whole ±2σ interval lies strictly on e's side of 0, disagrees when
//   it lies strictly on the other side, and is not resolvable when it holds 0.
// Without an error this is: mean in the band (on e's side of 0) agrees, outside it disagrees.
Judgement judgement(const Claim& claim);

// judgement(claim).verdict.
Verdict judge(const Claim& claim);

// The tolerance as a reader reads it: "±5 %", "±0.2", "within a factor 2", "its sign (< 0)".
std::string tolerance_text(const Claim& claim);

}  // namespace granule::reproduce
