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
// absolute, |m − e| ≤ t; factor, e/t ≤ m ≤ e·t (for order-of-magnitude estimates, t > 1).
enum class ToleranceKind { relative, absolute, factor };

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

// The verdict of a claim, from its numbers alone:
// - not resolvable when `unresolvable` says so or the measurement is missing (not finite);
// - disagrees when the measured number lies outside the tolerance band widened by 2σ (the whole
//   interval ±2σ misses the band);
// - not resolvable when it lies inside but ±2σ alone is wider than the band, so that an agreement
//   would mean nothing;
// - agrees otherwise.
Verdict judge(const Claim& claim);

// The tolerance as a reader reads it: "±5 %", "±0.2", "within a factor 2".
std::string tolerance_text(const Claim& claim);

}  // namespace granule::reproduce
