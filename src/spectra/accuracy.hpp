// How the fast method's accuracy is measured (docs/spectra.md): the error of a mode relative to the
// larger of the mode's own magnitude and the ideal-gas (√N-level) magnitude √(Σ_j w_j²), the rms of
// |S(k)| for uncorrelated positions.  Modes far above the noise are thus held to a relative error;
// modes at or below the noise level, whose relative error is meaningless near a zero of S, are held to
// an error relative to the noise level.
#pragma once

#include <algorithm>
#include <cmath>
#include <span>

#include "spectra/mode_sums.hpp"

namespace granule::spectra {

// √(Σ_j w_j²); N for unit weights is handled by passing an empty span with the particle count.
inline double ideal_gas_magnitude(std::span<const double> weights, std::size_t particles) {
  if (weights.empty()) return std::sqrt(static_cast<double>(particles));
  double sum = 0.0;
  for (const double w : weights) sum += w * w;
  return std::sqrt(sum);
}

// max over modes of |approx − reference| / max(|reference|, ideal_gas).
inline double max_relative_error(const ModeValues& approx, const ModeValues& reference, double ideal_gas) {
  double worst = 0.0;
  for (std::size_t i = 0; i < reference.size(); ++i) {
    worst = std::max(worst, std::abs(approx[i] - reference[i]) / std::max(std::abs(reference[i]), ideal_gas));
  }
  return worst;
}

}  // namespace granule::spectra
