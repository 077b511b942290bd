#include "reproduce/claim.hpp"

#include <fmt/format.h>

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

namespace {

// The tolerance band [low, high] around the expected number.
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
  }
  return {c.expected, c.expected};
}

}  // namespace

Verdict judge(const Claim& c) {
  if (!c.unresolvable.empty() || !std::isfinite(c.measured) || !std::isfinite(c.expected)) return Verdict::not_resolvable;
  const double two_sigma = std::isfinite(c.error) ? 2.0 * std::abs(c.error) : 0.0;
  const Band band = tolerance_band(c);
  const bool overlaps = c.measured >= band.low - two_sigma && c.measured <= band.high + two_sigma;
  if (!overlaps) return Verdict::disagrees;  // even the nearest end of ±2σ lies outside the band
  return two_sigma > band.high - band.low ? Verdict::not_resolvable : Verdict::agrees;
}

std::string tolerance_text(const Claim& c) {
  switch (c.tolerance_kind) {
    case ToleranceKind::relative:
      return fmt::format("±{:g} %", 100.0 * c.tolerance);
    case ToleranceKind::absolute:
      return fmt::format("±{:g}", c.tolerance);
    case ToleranceKind::factor:
      return fmt::format("within a factor {:g}", c.tolerance);
  }
  return "";
}

}  // namespace granule::reproduce
