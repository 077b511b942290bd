#include "distribution/twice_fitted.hpp"

#include <Eigen/QR>
#include <Eigen/SVD>
#include <cmath>
#include <limits>

namespace granule::distribution {

AngularCoefficients fit_quadratic_exponent(const OnceFitted& once, int angles, int speeds, double speed_max) {
  AngularCoefficients out;
  out.theta.resize(angles);
  out.b.resize(angles, 3);
  out.rms.resize(angles);
  for (int l = 0; l < angles; ++l) {
    const double theta = 2.0 * M_PI * l / angles;
    out.theta[l] = theta;
    Eigen::MatrixXd design(speeds, 3);
    Eigen::VectorXd target(speeds);
    int used = 0;
    for (int k = 0; k < speeds; ++k) {
      const double u = speed_max * (k + 1) / speeds;
      const double f = once.density(u, theta);
      if (!(f > 0.0)) {
        ++out.skipped_points;
        continue;
      }
      // Weight √(u f̃*): the counting error of log f̃ at (u, θ) is ∝ 1/√(samples there) ∝
      // 1/√(u f̃); without it the far tail, where f̃* is a derivative of a nearly flat h*,
      // would count as much as the bulk.
      const double weight = std::sqrt(u * f);
      design.row(used) << weight, weight * u, weight * u * u;
      target[used] = -weight * std::log(f);
      ++used;
    }
    if (used < 3) {  // no quadratic through fewer points: no b at this angle, and no series (5.29)
      out.b.row(l).setConstant(std::numeric_limits<double>::quiet_NaN());
      out.rms[l] = std::numeric_limits<double>::quiet_NaN();
      continue;
    }
    const Eigen::MatrixXd a = design.topRows(used);
    const Eigen::VectorXd y = target.head(used);
    const Eigen::Vector3d coefficients = a.colPivHouseholderQr().solve(y);
    out.b.row(l) = coefficients.transpose();
    // Unweighted residuals in log f̃ for the report.
    const Eigen::VectorXd weights = a.col(0);
    const Eigen::VectorXd r = ((a * coefficients - y).array() / weights.array()).matrix();
    out.rms[l] = r.norm() / std::sqrt(static_cast<double>(used));
    for (int k = 0; k < used; ++k)
      out.max_relative_deviation = std::max(out.max_relative_deviation, std::abs(std::expm1(-r[k])));
  }
  return out;
}

double SineSeries::value(int i, double theta) const {
  double sum = mean[i];
  for (int j = 1; j <= kHarmonics; ++j) sum += amplitude[j - 1][i] * std::sin(2.0 * j * (theta + phase[j - 1]));
  return sum;
}

namespace {

constexpr int kSeriesParameters = 3 + SineSeries::kHarmonics * 4;

}  // namespace

Eigen::VectorXd series_parameters(const SineSeries& s) {
  Eigen::VectorXd x(kSeriesParameters);
  for (int i = 0; i < 3; ++i) x[i] = s.mean[i];
  for (int j = 0; j < SineSeries::kHarmonics; ++j) {
    for (int i = 0; i < 3; ++i) x[3 + 4 * j + i] = s.amplitude[j][i];
    x[3 + 4 * j + 3] = s.phase[j];
  }
  return x;
}

SineSeries series_from_parameters(const Eigen::VectorXd& x) {
  SineSeries s;
  for (int i = 0; i < 3; ++i) s.mean[i] = x[i];
  for (int j = 0; j < SineSeries::kHarmonics; ++j) {
    for (int i = 0; i < 3; ++i) s.amplitude[j][i] = x[3 + 4 * j + i];
    s.phase[j] = x[3 + 4 * j + 3];
  }
  return s;
}

namespace {

void canonicalise(SineSeries& s, int j) {
  auto& a = s.amplitude[j - 1];
  int largest = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(a[i]) > std::abs(a[largest])) largest = i;
  double phase = s.phase[j - 1];
  if (a[largest] < 0.0) {
    for (double& value : a) value = -value;
    phase += M_PI / (2.0 * j);
  }
  const double period = M_PI / j;
  s.phase[j - 1] = phase - period * std::floor(phase / period);
}

}  // namespace

SineSeries fit_sine_series(const AngularCoefficients& b) {
  const auto n = b.theta.size();
  SineSeries s;
  // Start: Fourier projections (exact on the uniform grid); for harmonic j the three vectors
  // (S_ij, C_ij) = b_2j^(i) (cos 2jε, sin 2jε) share one direction, taken from the SVD.
  for (int i = 0; i < 3; ++i) s.mean[i] = b.b.col(i).mean();
  for (int j = 1; j <= SineSeries::kHarmonics; ++j) {
    Eigen::Matrix<double, 3, 2> projections;
    for (int i = 0; i < 3; ++i) {
      double sine = 0.0, cosine = 0.0;
      for (Eigen::Index l = 0; l < n; ++l) {
        sine += b.b(l, i) * std::sin(2.0 * j * b.theta[l]);
        cosine += b.b(l, i) * std::cos(2.0 * j * b.theta[l]);
      }
      projections(i, 0) = 2.0 * sine / static_cast<double>(n);
      projections(i, 1) = 2.0 * cosine / static_cast<double>(n);
    }
    Eigen::JacobiSVD<Eigen::Matrix<double, 3, 2>> svd(projections, Eigen::ComputeFullV);
    const Eigen::Vector2d direction = svd.matrixV().col(0);
    const Eigen::Vector3d amplitudes = projections * direction;
    for (int i = 0; i < 3; ++i) s.amplitude[j - 1][i] = amplitudes[i];
    s.phase[j - 1] = std::atan2(direction[1], direction[0]) / (2.0 * j);
  }
  Eigen::VectorXd x = series_parameters(s);
  const auto residual = [&](const Eigen::VectorXd& y, Eigen::VectorXd& r) {
    const SineSeries trial = series_from_parameters(y);
    for (Eigen::Index l = 0; l < n; ++l)
      for (int i = 0; i < 3; ++i) r[3 * l + i] = trial.value(i, b.theta[l]) - b.b(l, i);
  };
  const FitReport report = levenberg_marquardt(residual, 3 * n, x);
  s = series_from_parameters(x);
  s.report = report;
  for (int j = 1; j <= SineSeries::kHarmonics; ++j) canonicalise(s, j);
  return s;
}

void align_phase(SineSeries& s, int j, double reference_phase) {
  // Candidates ε + kπ/2j with amplitudes (−1)^k b: pick the one nearest the reference.
  const double step = M_PI / (2.0 * j);
  double best_distance = 1e300;
  int best = 0;
  for (int k = -4 * j; k <= 4 * j; ++k) {
    const double distance = std::abs(s.phase[j - 1] + k * step - reference_phase);
    if (distance < best_distance) {
      best_distance = distance;
      best = k;
    }
  }
  s.phase[j - 1] += best * step;
  if (best % 2 != 0)
    for (double& value : s.amplitude[j - 1]) value = -value;
}

SineSeries rescale_speed(const SineSeries& series, double scale) {
  SineSeries out = series;
  const double factor[3] = {1.0, 1.0 / scale, 1.0 / (scale * scale)};
  for (int i = 0; i < 3; ++i) {
    out.mean[i] *= factor[i];
    for (auto& a : out.amplitude) a[i] *= factor[i];
  }
  out.mean[0] += 2.0 * std::log(scale);
  return out;
}

}  // namespace granule::distribution
