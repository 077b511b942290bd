// The first tier of thesis §5.2: smooth fits of the cumulative function, φ*(v) (5.20, 5.22) and
// ψ*(θ, v) (5.21, 5.23, 5.24), and the 'once-fitted' distribution f̃^(1)* = h*_vθ / v (5.25,
// 5.26) obtained by differentiating them.  Speeds u in the units of the cumulative function's
// grid (u = v/s); f̃* is then a density in the (u_x, u_y) plane, normalised to 1 (5.12).
#pragma once

#include <array>

#include "distribution/cumulative_function.hpp"
#include "distribution/least_squares.hpp"

namespace granule::distribution {

// φ*(u) = (1 − exp(−J(u)))/2π, J(u) = a_2 u² + a_3 u³ + a_4 u⁴ (5.20, 5.22).
struct SpeedFit {
  std::array<double, 3> a{1.0, 0.0, 0.0};  // a_2, a_3, a_4
  FitReport report;

  double j(double u) const { return u * u * (a[0] + u * (a[1] + u * a[2])); }
  double j_prime_over_u(double u) const { return 2.0 * a[0] + u * (3.0 * a[1] + u * 4.0 * a[2]); }
  double phi(double u) const;
};

// ψ*(θ, u) = Σ_{p=1}^{4} A_p(u) sin[2p(θ + β)], A_p = α_p (1 − exp(−Q_p)),
// Q_p(u) = Σ_{m=2}^{6} d_pm u^m (5.21, 5.23, 5.24).  Only even harmonics: rotation by π symmetry.
struct AngularFit {
  static constexpr int kHarmonics = 4;
  static constexpr int kPowers = 5;  // m = 2 … 6
  double beta = 0.0;
  std::array<double, kHarmonics> alpha{};
  std::array<std::array<double, kPowers>, kHarmonics> d{};  // d[p−1][m−2]
  FitReport report;

  double q(int p, double u) const;              // Q_p(u)
  double q_prime_over_u(int p, double u) const;  // Q_p'(u)/u
  double amplitude(int p, double u) const;       // A_p(u)
  double psi(double theta, double u) const;
};

struct OnceFitted {
  SpeedFit speed;
  AngularFit angular;

  // f̃^(1)*(u, θ) = [φ*_u + ψ*_θu]/u (5.25, 5.26); finite at u → 0 since J, Q_p start at u².
  double density(double u, double theta) const;
  // h*(u, θ) = θ φ*(u) + ψ*(θ, u) − ψ*(0, u): the fitted counterpart of (5.11), using (5.15).
  double cumulative(double u, double theta) const;
};

// Fits φ* to φ and ψ* to ψ by Levenberg–Marquardt, each residual weighted by the binomial
// standard deviation of the counted fraction it comes from.  A harmonic of (5.21) whose A_p dips
// below 0 by more than half its asymptote α_p at speeds up to `speed_limit` (the range the twice
// fit uses) is not determined by the data: it is dropped (α_p = 0, Q_p = 0) and the rest refitted.
OnceFitted fit_once(const CumulativeFunction& c, double speed_limit);

}  // namespace granule::distribution
