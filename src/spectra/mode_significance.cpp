#include "spectra/mode_significance.hpp"

#include <algorithm>
#include <cmath>

namespace granule::spectra {

namespace {

// Shares closer than this (relative) are spread apart: the partial-fraction form of the
// hypoexponential survival below needs distinct rates; moving a share by 1e-5 of itself changes Q by
// about s·1e-5 (relative), far below any statistical question asked of it, while the cancellation
// between the terms (weights up to 1e10 for three equal shares) still leaves six exact digits.
constexpr double kSmallestRelativeGap = 1e-5;

std::vector<double> distinct_positive_shares(std::span<const double> shares) {
  std::vector<double> kept;
  for (const double share : shares) {
    if (share > 0.0) kept.push_back(share);
  }
  std::sort(kept.begin(), kept.end(), std::greater<>());
  for (std::size_t i = 1; i < kept.size(); ++i) {
    kept[i] = std::min(kept[i], kept[i - 1] * (1.0 - kSmallestRelativeGap));
  }
  return kept;
}

}  // namespace

double single_mode_survival(double s, std::span<const double> shares) {
  if (!(s > 0.0)) return 1.0;
  const std::vector<double> lambda = distinct_positive_shares(shares);
  if (lambda.empty()) return 0.0;
  // Σ λ_i E_i with distinct λ_i: Q(s) = Σ_i [Π_{j≠i} λ_i/(λ_i − λ_j)] e^{−s/λ_i}.
  double survival = 0.0;
  for (std::size_t i = 0; i < lambda.size(); ++i) {
    double weight = 1.0;
    for (std::size_t j = 0; j < lambda.size(); ++j) {
      if (j != i) weight *= lambda[i] / (lambda[i] - lambda[j]);
    }
    survival += weight * std::exp(-s / lambda[i]);
  }
  return std::clamp(survival, 0.0, 1.0);
}

double false_alarm_probability(double q, double independent_modes) {
  if (q >= 1.0) return 1.0;
  return -std::expm1(independent_modes * std::log1p(-q));
}

double noise_threshold(double false_alarm, double independent_modes, std::span<const double> shares) {
  // p(s) falls from 1 at s = 0: bisect on s, doubling the bracket until p < false_alarm.
  double low = 0.0, high = 1.0;
  const auto p = [&](double s) { return false_alarm_probability(single_mode_survival(s, shares), independent_modes); };
  while (p(high) > false_alarm && high < 1e6) high *= 2.0;
  for (int step = 0; step < 100 && high - low > 1e-12 * high; ++step) {
    const double middle = 0.5 * (low + high);
    (p(middle) > false_alarm ? low : high) = middle;
  }
  return high;
}

}  // namespace granule::spectra
