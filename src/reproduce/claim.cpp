#include "reproduce/claim.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace granule::reproduce {

std::string verdict_text(Verdict verdict) {
  switch (verdict) {
    case Verdict::agrees:
      return "agrees";
    case Verdict::disagrees:
      return "disagrees";
    case Verdict::not_resolvable:
      return "not resolvable at this scale";
  }
  return "";
}

const char* tolerance_kind_name(ToleranceKind kind) {
  switch (kind) {
    case ToleranceKind::relative:
      return "relative";
    case ToleranceKind::absolute:
      return "absolute";
    case ToleranceKind::factor:
      return "factor";
    case ToleranceKind::sign:
      return "sign";
  }
  return "";
}

namespace {

// The tolerance band [low, high] around the expected number (not for sign claims).
struct Band {
  double low, high;
};

Band tolerance_band(const Claim& c) {
  switch (c.tolerance_kind) {
    case ToleranceKind::relative:
      return {c.expected - c.tolerance * std::abs(c.expected), c.expected + c.tolerance * std::abs(c.expected)};
    case ToleranceKind::absolute:
      return {c.expected - c.tolerance, c.expected + c.tolerance};
    case ToleranceKind::factor: {
      const double a = c.expected / c.tolerance, b = c.expected * c.tolerance;
      return {std::min(a, b), std::max(a, b)};
    }
    case ToleranceKind::sign:
      break;
  }
  return {c.expected, c.expected};
}

// The sign is the claim: only an interval ±2σ that excludes 0 says which side the mean is on.
Judgement judge_sign(const Claim& c, double two_sigma) {
  if (c.expected == 0.0) return {Verdict::not_resolvable, "the claimed number has no sign"};
  const double on_claimed_side = c.expected > 0.0 ? c.measured : -c.measured;
  if (on_claimed_side - two_sigma > 0.0) return {Verdict::agrees, ""};
  if (on_claimed_side + two_sigma < 0.0) return {Verdict::disagrees, ""};
  return {Verdict::not_resolvable,
          two_sigma > 0.0 ? "zero lies within 2σ of the mean: the sign is not resolved, more statistics are needed"
                          : "the mean is zero and has no error: no sign to judge"};
}

Judgement judge_band(const Claim& c, double two_sigma) {
  const Band band = tolerance_band(c);
  if (c.measured >= band.low && c.measured <= band.high) {
    if (two_sigma > band.high - band.low)
      return {Verdict::not_resolvable, "2σ alone is wider than the band: an agreement would mean nothing at this scale"};
    return {Verdict::agrees, ""};
  }
  // Outside: how far the mean lies from the nearest edge of the band.
  const double gap = c.measured < band.low ? band.low - c.measured : c.measured - band.high;
  if (gap > two_sigma) return {Verdict::disagrees, ""};  // even the nearest end of ±2σ misses the band
  return {Verdict::not_resolvable,
          "the mean lies outside the band but within 2σ of it: more statistics are needed to decide"};
}

}  // namespace

Judgement judgement(const Claim& c) {
  if (!c.unresolvable.empty()) return {Verdict::not_resolvable, c.unresolvable};
  if (!std::isfinite(c.measured)) return {Verdict::not_resolvable, "no measured number"};
  if (!std::isfinite(c.expected)) return {Verdict::not_resolvable, "no expected number"};
  // A single seed has no error: the mean is then judged on the tolerance alone.
  const double two_sigma = std::isfinite(c.error) ? 2.0 * std::abs(c.error) : 0.0;
  return c.tolerance_kind == ToleranceKind::sign ? judge_sign(c, two_sigma) : judge_band(c, two_sigma);
}

Verdict judge(const Claim& c) { return judgement(c).verdict; }

std::string tolerance_text(const Claim& c) {
  switch (c.tolerance_kind) {
    case ToleranceKind::relative:
      return fmt::format("±{:g} %", 100.0 * c.tolerance);
    case ToleranceKind::absolute:
      return fmt::format("±{:g}", c.tolerance);
    case ToleranceKind::factor:
      return fmt::format("within a factor {:g}", c.tolerance);
    case ToleranceKind::sign:
      return c.expected < 0.0 ? "its sign (< 0)" : "its sign (> 0)";
  }
  return "";
}

}  // namespace granule::reproduce
