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
  // Harmonic p was resolved by the samples and has its own Q_p; otherwise Q_p = J (5.22), the
  // speed dependence of φ*, and only α_p was fitted.
  std::array<bool, kHarmonics> resolved{};
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
  // Its angle average φ*_u/u = (J'/u) e^{−J}/2π, and the amplitude of its harmonic
  // cos 2p(θ + β), 2p α_p (Q_p'/u) e^{−Q_p}.
  double isotropic_density(double u) const;
  double harmonic_density(int p, double u) const;
  // h*(u, θ) = θ φ*(u) + ψ*(θ, u) − ψ*(0, u): the fitted counterpart of (5.11), using (5.15).
  double cumulative(double u, double theta) const;
};

// Which harmonics p = 1 … 4 of (5.21) get their own Q_p (element p − 1).
using HarmonicSet = std::array<bool, AngularFit::kHarmonics>;

// The harmonics the samples resolve (harmonic_significance.hpp).
HarmonicSet resolved_harmonics(const CumulativeFunction& c);

// Fits φ* to φ and ψ* to ψ by Levenberg–Marquardt, each residual weighted by the binomial
// standard deviation of the counted fraction it comes from.  All four harmonics of (5.21) are
// fitted; those in `resolved` with their own Q_p, unless the fit leaves Q_p below −log(3/2) or the
// harmonic of f̃* above twice what a density allows at speeds up to `speed_limit` (the range the
// twice fit uses), or does not converge (then the weakest loses it), the others with Q_p = J.  A φ* that does not rise up to `speed_limit` is
// reported as not converged.
OnceFitted fit_once(const CumulativeFunction& c, double speed_limit, HarmonicSet resolved);

}  // namespace granule::distribution
