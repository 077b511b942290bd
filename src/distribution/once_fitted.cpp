#include "distribution/once_fitted.hpp"

#include <algorithm>
#include <cmath>

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

double OnceFitted::density(double u, double theta) const {
  // φ*_u / u = J'/u e^{−J} / 2π;  ψ*_θu / u = Σ 2p α_p (Q_p'/u) e^{−Q_p} cos 2p(θ + β).
  double value = speed.j_prime_over_u(u) * std::exp(-speed.j(u)) / (2.0 * M_PI);
  for (int p = 1; p <= AngularFit::kHarmonics; ++p)
    value += 2.0 * p * angular.alpha[p - 1] * angular.q_prime_over_u(p, u) * std::exp(-angular.q(p, u)) *
             std::cos(2.0 * p * (theta + angular.beta));
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

// The harmonics p of (5.21) that take part in the ψ fit; the others have α_p = 0.
using HarmonicSet = std::array<bool, AngularFit::kHarmonics>;

int parameter_count(const HarmonicSet& active) {
  int count = 1;
  for (const bool a : active) count += a ? 1 + AngularFit::kPowers : 0;
  return count;
}

// x = (β, then per active harmonic α_p, d_p2 … d_p6).
void unpack(const Eigen::VectorXd& x, const HarmonicSet& active, AngularFit& fit) {
  fit.beta = x[0];
  int next = 1;
  for (int p = 0; p < AngularFit::kHarmonics; ++p) {
    fit.alpha[p] = 0.0;
    fit.d[p].fill(0.0);
    if (!active[p]) continue;
    fit.alpha[p] = x[next++];
    for (int m = 0; m < AngularFit::kPowers; ++m) fit.d[p][m] = x[next++];
  }
}

Eigen::VectorXd pack(const AngularFit& fit, const HarmonicSet& active) {
  Eigen::VectorXd x(parameter_count(active));
  x[0] = fit.beta;
  int next = 1;
  for (int p = 0; p < AngularFit::kHarmonics; ++p) {
    if (!active[p]) continue;
    x[next++] = fit.alpha[p];
    for (int m = 0; m < AngularFit::kPowers; ++m) x[next++] = fit.d[p][m];
  }
  return x;
}

// Starting point: the phase β from the 2θ Fourier component of ψ summed over speeds, the
// amplitudes A_p(u_k) by projection, then α_p, d_pm by a separate fit of each A_p(u).
AngularFit initial_angular(const CumulativeFunction& c, const Eigen::VectorXd& sigma) {
  const int nv = c.grid.speed_bins, nt = c.grid.angle_bins;
  AngularFit fit;
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

AngularFit fit_angular(const CumulativeFunction& c, const Eigen::VectorXd& sigma, const AngularFit& start,
                       const HarmonicSet& active) {
  const int nv = c.grid.speed_bins, nt = c.grid.angle_bins;
  AngularFit fit;
  Eigen::VectorXd x = pack(start, active);
  const auto residual = [&](const Eigen::VectorXd& y, Eigen::VectorXd& r) {
    AngularFit trial;
    unpack(y, active, trial);
    Eigen::MatrixXd amplitude(nv, AngularFit::kHarmonics), sine(AngularFit::kHarmonics, nt);
    for (int p = 1; p <= AngularFit::kHarmonics; ++p) {
      for (int k = 1; k <= nv; ++k) amplitude(k - 1, p - 1) = trial.amplitude(p, c.grid.speed_edge(k));
      for (int l = 0; l < nt; ++l) sine(p - 1, l) = std::sin(2.0 * p * (c.grid.angle_edge(l) + trial.beta));
    }
    const Eigen::MatrixXd model = amplitude * sine;
    for (int k = 1; k <= nv; ++k)
      for (int l = 0; l < nt; ++l) r[(k - 1) * nt + l] = (model(k - 1, l) - c.psi(k, l)) / sigma[k];
  };
  const Eigen::Index residuals = static_cast<Eigen::Index>(nv) * nt;
  if (x.size() > 1) {
    fit.report = levenberg_marquardt(residual, residuals, x);
  } else {  // no harmonic left: ψ* = 0, nothing to minimise
    Eigen::VectorXd r(residuals);
    residual(x, r);
    fit.report = {true, "no harmonic resolved", 1, r.norm(), r.norm() / std::sqrt(static_cast<double>(residuals))};
  }
  unpack(x, active, fit);
  return fit;
}

// A_p = α_p(1 − e^{−Q_p}) rises from 0 to its asymptote α_p (5.23).  Fitted noise can make it dip
// a little past 0 (Q_p slightly negative: down to −0.2 for the weakest harmonic of an anisotropic
// Gaussian, resolved at ~6σ); a dip by more than half the asymptote, Q_p < −log(3/2), means that
// Q_p is not determined by the data.
constexpr double kLowestQ = -0.4054651081081644;  // −log(3/2)

// The harmonics whose Q_p falls below kLowestQ at speeds up to `speed_limit`, on a grid finer
// than the bins (Q_p can dip between two edges).
HarmonicSet undetermined_harmonics(const AngularFit& fit, const HarmonicSet& active, int speed_bins, double speed_limit) {
  const int speeds = 4 * speed_bins;
  HarmonicSet undetermined{};
  for (int p = 1; p <= AngularFit::kHarmonics; ++p)
    for (int k = 1; k <= speeds && active[p - 1] && !undetermined[p - 1]; ++k)
      undetermined[p - 1] = !(fit.q(p, speed_limit * k / speeds) >= kLowestQ);
  return undetermined;
}

}  // namespace

// A harmonic that the data do not resolve leaves its (α_p, Q_p) undetermined (only the product
// A_p ≈ 0 is fitted), and Q_p can wander to huge coefficients whose derivative ψ*_θu spikes
// between the bin edges or below the first one, so that f̃* is distorted or no density at all
// (seen on isotropic Maxwellian samples: −log f̃* then gives coefficients off by 6–10⁴ σ, or NaN).
// The thesis chooses the number of harmonics in (5.21) by the quality of the fit; here all four
// are fitted, and while some are undetermined those are dropped and the rest refitted.  Fits
// whose harmonics are all determined are unchanged.
OnceFitted fit_once(const CumulativeFunction& c, double speed_limit) {
  OnceFitted once;
  once.speed = fit_speed(c);
  const Eigen::VectorXd sigma = psi_sigma(c);
  const AngularFit start = initial_angular(c, sigma);
  HarmonicSet active;
  active.fill(true);
  while (true) {
    once.angular = fit_angular(c, sigma, start, active);
    const HarmonicSet drop = undetermined_harmonics(once.angular, active, c.grid.speed_bins, speed_limit);
    if (std::none_of(drop.begin(), drop.end(), [](bool d) { return d; })) break;
    for (int p = 0; p < AngularFit::kHarmonics; ++p) active[p] = active[p] && !drop[p];
  }
  return once;
}

}  // namespace granule::distribution
