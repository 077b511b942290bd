// The second tier of thesis §5.2: at each angle θ, −log f̃^(1)* is fitted by
// b^(0)(θ) + b^(1)(θ) v + b^(2)(θ) v² (the 'twice-fitted' f̃^(1)**, 5.27–5.28), and each b^(i)(θ)
// by a sine series of six harmonics 2j with phases ε_2j shared by i = 0, 1, 2 (5.29).
#pragma once

#include <array>

#include "distribution/least_squares.hpp"
#include "distribution/once_fitted.hpp"

namespace granule::distribution {

// b^(i)(θ_l) of (5.27) on a uniform angle grid.
struct AngularCoefficients {
  Eigen::VectorXd theta;     // θ_l = 2πl/n
  Eigen::MatrixXd b;         // n × 3: b^(0), b^(1), b^(2) at θ_l
  Eigen::VectorXd rms;       // unweighted residual rms of the fit of −log f̃* at θ_l
  double max_relative_deviation = 0.0;  // max |f** − f*|/f* over the fitted points
  int skipped_points = 0;    // points where f̃* ≤ 0 (no logarithm), left out of the fits
};

// Weighted linear least squares (Eigen's QR) of −log f̃*(u, θ_l) on `speeds` uniform points in
// (0, speed_max] at each of `angles` angles, each point weighted by √(u f̃*) (its counting
// statistics).  An angle with fewer than 3 points where f̃* > 0 has b = NaN (no fit), which makes
// the sine series fail.
AngularCoefficients fit_quadratic_exponent(const OnceFitted& once, int angles, int speeds, double speed_max);

// (5.29): b^(i)(θ) = b_0^(i) + Σ_{j=1}^{6} b_2j^(i) sin[2j(θ + ε_2j)].
struct SineSeries {
  static constexpr int kHarmonics = 6;
  std::array<double, 3> mean{};                                // b_0^(i)
  std::array<std::array<double, 3>, kHarmonics> amplitude{};  // [j−1][i]: b_2j^(i)
  std::array<double, kHarmonics> phase{};                      // ε_2j
  FitReport report;

  double value(int i, double theta) const;
};

// Fourier projection, a rank-one (shared phase) SVD per harmonic as the start, then
// Levenberg–Marquardt on all 27 parameters.  Conventions (the series is unchanged by them):
// ε_2j ∈ [0, π/j) and the b_2j^(i) of largest magnitude (in the units the b^(i) are given) is
// positive, since (b, ε) and (−b, ε + π/2j) describe the same term.
SineSeries fit_sine_series(const AngularCoefficients& b);

// The 27 numbers of a series as one vector (b_0^(0..2), then per j: b_2j^(0..2), ε_2j) and back.
Eigen::VectorXd series_parameters(const SineSeries& series);
SineSeries series_from_parameters(const Eigen::VectorXd& parameters);

// Moves (amplitudes, phase) of harmonic j to the representation whose phase is nearest to
// `reference_phase` (mod π/j): used to compare bootstrap replicates with the estimate.
void align_phase(SineSeries& series, int j, double reference_phase);

// Coefficients for speeds v = s u from those for u: b^(0) += 2 log s (f̃ is a density in the
// velocity plane), b^(1) /= s, b^(2) /= s².
SineSeries rescale_speed(const SineSeries& series, double scale);

}  // namespace granule::distribution
