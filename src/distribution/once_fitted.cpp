#include "distribution/once_fitted.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "distribution/harmonic_significance.hpp"

namespace granule::distribution {

double SpeedFit::phi(double u) const { return -std::expm1(-j(u)) / (2.0 * M_PI); }

double AngularFit::q(int p, double u) const {
  double sum = 0.0;
  for (int m = kPowers - 1; m >= 0; --m) sum = sum * u + d[p - 1][m];
  return sum * u * u;
}

double AngularFit::q_prime_over_u(int p, double u) const {
  double sum = 0.0;
  for (int m = kPowers - 1; m >= 0; --m) sum = sum * u + (m + 2) * d[p - 1][m];
  return sum;
}

double AngularFit::amplitude(int p, double u) const { return -alpha[p - 1] * std::expm1(-q(p, u)); }

double AngularFit::psi(double theta, double u) const {
  double sum = 0.0;
  for (int p = 1; p <= kHarmonics; ++p) sum += amplitude(p, u) * std::sin(2.0 * p * (theta + beta));
  return sum;
}

double OnceFitted::isotropic_density(double u) const { return speed.j_prime_over_u(u) * std::exp(-speed.j(u)) / (2.0 * M_PI); }

double OnceFitted::harmonic_density(int p, double u) const {
  return 2.0 * p * angular.alpha[p - 1] * angular.q_prime_over_u(p, u) * std::exp(-angular.q(p, u));
}

double OnceFitted::density(double u, double theta) const {
  // φ*_u / u plus ψ*_θu / u = Σ 2p α_p (Q_p'/u) e^{−Q_p} cos 2p(θ + β).
  double value = isotropic_density(u);
  for (int p = 1; p <= AngularFit::kHarmonics; ++p) value += harmonic_density(p, u) * std::cos(2.0 * p * (theta + angular.beta));
  return value;
}

double OnceFitted::cumulative(double u, double theta) const {
  return theta * speed.phi(u) + angular.psi(theta, u) - angular.psi(0.0, u);
}

namespace {

// Binomial standard deviations of the counted fractions, floored at one count: for φ the
// fraction H_k = h(u_k, 2π) itself; for ψ a fraction h(u_k, θ) ≈ H_k/2 at mid-angle.
Eigen::VectorXd phi_sigma(const CumulativeFunction& c) {
  const Eigen::ArrayXd big_h = c.h.col(c.grid.angle_bins).array();
  return ((big_h * (1.0 - big_h) / c.total + 1.0 / (c.total * c.total)).sqrt() / (2.0 * M_PI)).matrix();
}

Eigen::VectorXd psi_sigma(const CumulativeFunction& c) {
  const Eigen::ArrayXd half = 0.5 * c.h.col(c.grid.angle_bins).array();
  return (half * (1.0 - half) / c.total + 1.0 / (c.total * c.total)).sqrt().matrix();
}

SpeedFit fit_speed(const CumulativeFunction& c) {
  const int nv = c.grid.speed_bins;
  const Eigen::VectorXd sigma = phi_sigma(c);
  SpeedFit fit;  // a_2 = 1: the Maxwellian in units of √(2T)
  Eigen::VectorXd p(3);
  p << 1.0, 0.0, 0.0;
  const auto residual = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r) {
    SpeedFit trial;
    trial.a = {x[0], x[1], x[2]};
    for (int k = 1; k <= nv; ++k) r[k - 1] = (trial.phi(c.grid.speed_edge(k)) - c.phi[k]) / sigma[k];
  };
  fit.report = levenberg_marquardt(residual, nv, p);
  fit.a = {p[0], p[1], p[2]};
  return fit;
}

// x = (β, then per harmonic α_p and, for a resolved one, d_p2 … d_p6).  An unresolved harmonic
// has the speed dependence of φ*: Q_p = J, i.e. d_p = (a_2, a_3, a_4, 0, 0), a case of (5.24).
int parameter_count(const AngularFit& shape) {
  int count = 1;
  for (const bool resolved : shape.resolved) count += resolved ? 1 + AngularFit::kPowers : 1;
  return count;
}

void unpack(const Eigen::VectorXd& x, const SpeedFit& speed, AngularFit& fit) {
  fit.beta = x[0];
  int next = 1;
  for (int p = 0; p < AngularFit::kHarmonics; ++p) {
    fit.alpha[p] = x[next++];
    fit.d[p] = {speed.a[0], speed.a[1], speed.a[2], 0.0, 0.0};
    if (fit.resolved[p])
      for (int m = 0; m < AngularFit::kPowers; ++m) fit.d[p][m] = x[next++];
  }
}

Eigen::VectorXd pack(const AngularFit& fit) {
  Eigen::VectorXd x(parameter_count(fit));
  x[0] = fit.beta;
  int next = 1;
  for (int p = 0; p < AngularFit::kHarmonics; ++p) {
    x[next++] = fit.alpha[p];
    if (fit.resolved[p])
      for (int m = 0; m < AngularFit::kPowers; ++m) x[next++] = fit.d[p][m];
  }
  return x;
}

// Starting point: the phase β from the 2θ Fourier component of ψ summed over speeds, the
// amplitudes A_p(u_k) by projection, then α_p (and d_pm of a resolved harmonic) by a separate fit
// of each A_p(u).  `fit.resolved` says which harmonics have their own Q_p.
AngularFit initial_angular(const CumulativeFunction& c, const Eigen::VectorXd& sigma, const SpeedFit& speed,
                           AngularFit fit) {
  const int nv = c.grid.speed_bins, nt = c.grid.angle_bins;
  Eigen::MatrixXd sine(nv + 1, AngularFit::kHarmonics), cosine(nv + 1, AngularFit::kHarmonics);
  for (int k = 0; k <= nv; ++k)
    for (int p = 1; p <= AngularFit::kHarmonics; ++p) {
      double s = 0.0, co = 0.0;
      for (int l = 0; l < nt; ++l) {
        s += c.psi(k, l) * std::sin(2.0 * p * c.grid.angle_edge(l));
        co += c.psi(k, l) * std::cos(2.0 * p * c.grid.angle_edge(l));
      }
      sine(k, p - 1) = 2.0 * s / nt;  // = A_p cos 2pβ
      cosine(k, p - 1) = 2.0 * co / nt;  // = A_p sin 2pβ
    }
  fit.beta = 0.5 * std::atan2(cosine.col(0).sum(), sine.col(0).sum());
  for (int p = 1; p <= AngularFit::kHarmonics; ++p) {
    Eigen::VectorXd amplitude(nv + 1);
    for (int k = 0; k <= nv; ++k)
      amplitude[k] = sine(k, p - 1) * std::cos(2.0 * p * fit.beta) + cosine(k, p - 1) * std::sin(2.0 * p * fit.beta);
    fit.d[p - 1] = {speed.a[0], speed.a[1], speed.a[2], 0.0, 0.0};
    if (!fit.resolved[p - 1]) {  // A_p = α_p · 2πφ*: linear least squares for α_p
      double shape_shape = 0.0, shape_data = 0.0;
      for (int k = 1; k <= nv; ++k) {
        const double shape = 2.0 * M_PI * speed.phi(c.grid.speed_edge(k)) / sigma[k];
        shape_shape += shape * shape;
        shape_data += shape * amplitude[k] / sigma[k];
      }
      fit.alpha[p - 1] = shape_shape > 0.0 ? shape_data / shape_shape : 0.0;
      continue;
    }
    Eigen::VectorXd x(1 + AngularFit::kPowers);
    x.setZero();
    x[0] = amplitude.tail(std::max(1, nv / 4)).mean();
    x[1] = 1.0;
    const auto residual = [&](const Eigen::VectorXd& y, Eigen::VectorXd& r) {
      for (int k = 1; k <= nv; ++k) {
        const double u = c.grid.speed_edge(k);
        double q = 0.0;
        for (int m = AngularFit::kPowers - 1; m >= 0; --m) q = q * u + y[1 + m];
        r[k - 1] = (-y[0] * std::expm1(-q * u * u) - amplitude[k]) / sigma[k];
      }
    };
    levenberg_marquardt(residual, nv, x);
    if (!x.allFinite()) {
      x.setZero();
      x[1] = 1.0;
    }
    fit.alpha[p - 1] = x[0];
    for (int m = 0; m < AngularFit::kPowers; ++m) fit.d[p - 1][m] = x[1 + m];
  }
  return fit;
}

AngularFit fit_angular(const CumulativeFunction& c, const Eigen::VectorXd& sigma, const SpeedFit& speed,
                       const AngularFit& start) {
  const int nv = c.grid.speed_bins, nt = c.grid.angle_bins;
  AngularFit fit = start;
  Eigen::VectorXd x = pack(start);
  const auto residual = [&](const Eigen::VectorXd& y, Eigen::VectorXd& r) {
    AngularFit trial = start;
    unpack(y, speed, trial);
    Eigen::MatrixXd amplitude(nv, AngularFit::kHarmonics), sine(AngularFit::kHarmonics, nt);
    for (int p = 1; p <= AngularFit::kHarmonics; ++p) {
      for (int k = 1; k <= nv; ++k) amplitude(k - 1, p - 1) = trial.amplitude(p, c.grid.speed_edge(k));
      for (int l = 0; l < nt; ++l) sine(p - 1, l) = std::sin(2.0 * p * (c.grid.angle_edge(l) + trial.beta));
    }
    const Eigen::MatrixXd model = amplitude * sine;
    for (int k = 1; k <= nv; ++k)
      for (int l = 0; l < nt; ++l) r[(k - 1) * nt + l] = (model(k - 1, l) - c.psi(k, l)) / sigma[k];
  };
  fit.report = levenberg_marquardt(residual, static_cast<Eigen::Index>(nv) * nt, x);
  unpack(x, speed, fit);
  return fit;
}

// Signs that a harmonic's own Q_p is not determined by the data.  (1) A_p = α_p(1 − e^{−Q_p})
// rises from 0 to its asymptote α_p (5.23); fitted noise can make it dip a little past 0 (Q_p
// down to −0.2 for the weakest harmonic of an anisotropic Gaussian, resolved at ~6σ), a dip by more
// than half the asymptote, Q_p < −log(3/2), cannot be read from the data.  (2) A harmonic of a
// density f ≥ 0 is at most twice its angle average, |∫f cos 2pθ dθ| ≤ ∫f dθ: fitted ones reach
// 1.1 times that bound in the tail of an anisotropic Gaussian, a Q_p that wanders to steep
// coefficients makes a spike of 4 times it, so more than twice the bound is not a harmonic of data.
constexpr double kLowestQ = -0.4054651081081644;  // −log(3/2)
constexpr double kLargestHarmonic = 2.0 * 2.0;    // |harmonic| / angle average

// Speeds up to `speed_limit` on a grid four times finer than the bins (Q_p can dip between two edges).
template <typename Test>
bool everywhere_on_fit_range(int speed_bins, double speed_limit, Test test) {
  const int speeds = 4 * speed_bins;
  for (int k = 1; k <= speeds; ++k)
    if (!test(speed_limit * k / speeds)) return false;
  return true;
}

}  // namespace

HarmonicSet resolved_harmonics(const CumulativeFunction& c) {
  const std::vector<double> chi_square = harmonic_chi_square(c, AngularFit::kHarmonics);
  HarmonicSet resolved;
  for (int p = 0; p < AngularFit::kHarmonics; ++p) resolved[p] = chi_square[static_cast<std::size_t>(p)] > kResolvedChiSquare;
  return resolved;
}

// The thesis chooses the number of harmonics in (5.21) by the quality of the fit; its form has
// four.  A harmonic that the samples do not resolve leaves (α_p, Q_p) undetermined if both are
// fitted (only the product A_p ≈ 0 is): Q_p wanders to coefficients of 10³–10⁶ whose derivative
// ψ*_θu spikes between the bin edges or below the first one, so that f̃* is distorted or no density
// at all (seen on isotropic Maxwellian samples: −log f̃* then gives coefficients off by 5–10 σ,
// which made single bootstrap replicates outliers, or NaN).  So a harmonic gets its own Q_p only
// when the samples resolve it and the fit then determines Q_p (kLowestQ, kLargestHarmonic, and
// the fit converges); otherwise Q_p = J, the speed dependence of φ*, and the data fix only its
// amplitude α_p.  Keeping every harmonic, rather than dropping the unresolved ones, keeps their
// statistical spread in the bootstrap errors of the harmonics of (5.29).  A φ* that does not rise
// on the twice fit's speed range makes f̃* negative at every angle: that fit has failed and is
// reported so.
OnceFitted fit_once(const CumulativeFunction& c, double speed_limit, HarmonicSet resolved) {
  OnceFitted once;
  once.speed = fit_speed(c);
  if (!everywhere_on_fit_range(c.grid.speed_bins, speed_limit, [&](double u) { return once.speed.j_prime_over_u(u) > 0.0; })) {
    once.speed.report.converged = false;
    once.speed.report.status = "phi* does not rise on the fit range (J' <= 0)";
  }
  const Eigen::VectorXd sigma = psi_sigma(c);
  AngularFit shape;
  shape.resolved = resolved;
  while (true) {
    once.angular = fit_angular(c, sigma, once.speed, initial_angular(c, sigma, once.speed, shape));
    bool changed = false;
    for (int p = 1; p <= AngularFit::kHarmonics; ++p)
      if (shape.resolved[p - 1] && !everywhere_on_fit_range(c.grid.speed_bins, speed_limit, [&](double u) {
            return once.angular.q(p, u) >= kLowestQ &&
                   std::abs(once.harmonic_density(p, u)) <= kLargestHarmonic * once.isotropic_density(u);
          })) {
        shape.resolved[p - 1] = false;
        changed = true;
      }
    // A fit that crawls to its evaluation limit has a direction the data do not fix: the weakest
    // harmonic's own Q_p (a marginal harmonic in a bootstrap replicate of few snapshots, say).
    int weakest = -1;
    for (int p = 0; p < AngularFit::kHarmonics && !changed && !once.angular.report.converged; ++p)
      if (shape.resolved[p] && (weakest < 0 || std::abs(once.angular.alpha[p]) < std::abs(once.angular.alpha[weakest]))) weakest = p;
    if (weakest >= 0) {
      shape.resolved[weakest] = false;
      changed = true;
    }
    if (!changed) break;
  }
  return once;
}

}  // namespace granule::distribution
