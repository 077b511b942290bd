#include "distribution/f1_analysis.hpp"

#include <algorithm>
#include <limits>
#include <cmath>
#include <random>

namespace granule::distribution {

double WindowResult::once_density(double v, double theta) const {
  return estimate.once.density(v / speed_scale, theta) / (speed_scale * speed_scale);
}

double WindowResult::twice_density(double v, double theta) const {
  const SineSeries& b = estimate.series;
  return std::exp(-(b.value(0, theta) + v * (b.value(1, theta) + v * b.value(2, theta))));
}

namespace {

// The window's samples binned once per snapshot, so that a bootstrap replicate is a weighted sum.
struct SnapshotBins {
  std::vector<Eigen::MatrixXd> counts;
  std::vector<double> samples;
  std::vector<SecondMoment> sums;  // Σ v'v'
};

SnapshotBins bin_snapshots(const WindowSamples& w, const PolarGrid& grid, double scale) {
  SnapshotBins out;
  std::size_t begin = 0;
  for (const std::size_t end : w.snapshot_end) {
    std::vector<double> speed, angle;
    SecondMoment sum;
    for (std::size_t i = begin; i < end; ++i) {
      speed.push_back(std::hypot(w.vx[i], w.vy[i]) / scale);
      const double a = std::atan2(w.vy[i], w.vx[i]);  // from the streamwise direction
      angle.push_back(a < 0.0 ? a + 2.0 * M_PI : a);
      sum.xx += w.vx[i] * w.vx[i];
      sum.xy += w.vx[i] * w.vy[i];
      sum.yy += w.vy[i] * w.vy[i];
    }
    out.counts.push_back(polar_counts(speed.data(), angle.data(), speed.size(), grid));
    out.samples.push_back(static_cast<double>(end - begin));
    out.sums.push_back(sum);
    begin = end;
  }
  return out;
}

PlaneIntegrals rescaled(PlaneIntegrals p, double scale) {
  const double s2 = scale * scale;
  p.moment = {p.moment.xx * s2, p.moment.xy * s2, p.moment.yy * s2};
  return p;
}

// The estimate from the snapshots counted `multiplicity` times each (all 1: the data; a bootstrap
// replicate otherwise).
F1Estimate estimate(const SnapshotBins& bins, const std::vector<double>& multiplicity, const PolarGrid& grid,
                    double fit_speed_max, double scale, const F1Options& options,
                    const std::optional<HarmonicSet>& resolved) {
  Eigen::MatrixXd counts = Eigen::MatrixXd::Zero(grid.speed_bins, grid.angle_bins);
  double total = 0.0;
  SecondMoment sum;
  for (std::size_t k = 0; k < bins.counts.size(); ++k) {
    if (multiplicity[k] == 0.0) continue;
    counts += multiplicity[k] * bins.counts[k];
    total += multiplicity[k] * bins.samples[k];
    sum.xx += multiplicity[k] * bins.sums[k].xx;
    sum.xy += multiplicity[k] * bins.sums[k].xy;
    sum.yy += multiplicity[k] * bins.sums[k].yy;
  }
  F1Estimate e = fit_counts(counts, total, grid, fit_speed_max, scale, options, resolved);
  e.direct = {sum.xx / total, sum.xy / total, sum.yy / total};
  return e;
}

FitQuality quality_of(const F1Estimate& e) {
  const CumulativeFunction& c = e.cumulative;
  FitQuality q;
  for (int k = 1; k <= c.grid.speed_bins; ++k) {
    const double big_h = c.h(k, c.grid.angle_bins);
    if (big_h * c.total < kToleranceMinCount) continue;
    const double u = c.grid.speed_edge(k);
    double& worst = u < 1.0 ? q.max_deviation_small_speed : q.max_deviation_large_speed;
    for (int l = 1; l <= c.grid.angle_bins; ++l)
      worst = std::max(worst, std::abs(e.once.cumulative(u, c.grid.angle_edge(l)) - c.h(k, l)) / big_h);
  }
  return q;
}

// Why the fits of an estimate failed (empty if all three converged): a failed fit gives no result.
std::string fit_failures(const F1Estimate& e) {
  std::string failures;
  for (const auto& [name, report] : {std::pair{"phi*", &e.once.speed.report}, std::pair{"psi*", &e.once.angular.report},
                                     std::pair{"sine series", &e.series.report}})
    if (!report->converged) failures += (failures.empty() ? "" : ", ") + std::string(name) + ": " + report->status;
  return failures;
}

std::string window_label(const WindowSamples& w) {
  return "window rho " + std::to_string(w.density.center) + " +- " + std::to_string(w.density.half_width) + ", T " +
         std::to_string(w.temperature.center) + " +- " + std::to_string(w.temperature.half_width);
}

// Accumulates mean and variance of a vector of numbers over replicates; a replicate whose
// value is not finite (e.g. a twice-fitted f̃** that does not decay at some angle) is left out
// of that number's spread only.
struct Spread {
  Eigen::ArrayXd sum, sum_squares, count;
  void add(const Eigen::VectorXd& x) {
    if (sum.size() == 0) {
      sum = sum_squares = count = Eigen::ArrayXd::Zero(x.size());
    }
    const Eigen::ArrayXd finite = x.array().isFinite().cast<double>();
    const Eigen::ArrayXd value = finite * x.array().isFinite().select(x.array(), 0.0);
    sum += value;
    sum_squares += value * value;
    count += finite;
  }
  // Sample standard deviation; NaN with fewer than two finite replicates.
  Eigen::VectorXd deviation() const {
    const Eigen::ArrayXd mean = sum / count;
    const Eigen::ArrayXd variance = ((sum_squares / count - mean * mean).max(0.0) * count / (count - 1.0));
    return (count > 1.0).select(variance.sqrt(), std::numeric_limits<double>::quiet_NaN()).matrix();
  }
};

Eigen::VectorXd error_quantities(const F1Estimate& e) {
  const Eigen::VectorXd series = series_parameters(e.series);
  Eigen::VectorXd x(series.size() + 4);
  x << series, e.direct.trace(), e.once_integrals.moment.trace(), e.twice_integrals.moment.trace(), e.ratio;
  return x;
}

}  // namespace

F1Estimate fit_counts(const Eigen::MatrixXd& counts, double total, const PolarGrid& grid, double fit_speed_max,
                      double scale, const F1Options& options, const std::optional<HarmonicSet>& resolved) {
  F1Estimate e;
  e.cumulative = cumulative_function(counts, total, grid);
  e.once = fit_once(e.cumulative, fit_speed_max, resolved ? *resolved : resolved_harmonics(e.cumulative));
  e.angular = fit_quadratic_exponent(e.once, grid.angle_bins, options.fit_speeds, fit_speed_max);
  const SineSeries dimensionless = fit_sine_series(e.angular);
  e.series = rescale_speed(dimensionless, scale);
  e.once_integrals = rescaled(
      plane_integrals([&](double u, double theta) { return e.once.density(u, theta); }, grid.speed_max), scale);
  e.twice_integrals = rescaled(plane_integrals(
                                   [&](double u, double theta) {
                                     return std::exp(-(dimensionless.value(0, theta) +
                                                       u * (dimensionless.value(1, theta) + u * dimensionless.value(2, theta))));
                                   },
                                   2.0 * grid.speed_max),
                               scale);
  e.ratio = e.series.mean[1] * e.series.mean[1] / e.series.mean[2];
  return e;
}

WindowResult analyse_window(const WindowSamples& w, const F1Options& options) {
  WindowResult r;
  r.density_window = w.density;
  r.temperature_window = w.temperature;
  r.samples = w.samples();
  r.snapshots = w.snapshots();
  double area = 0.0, weighted = 0.0;
  for (std::size_t k = 0; k < w.snapshots(); ++k) {
    area += w.selected_area[k];
    weighted += w.temperature_weighted[k];
  }
  if (r.samples < options.min_samples || r.snapshots < 2) {
    r.warning = window_label(w) + ": only " + std::to_string(r.samples) + " samples in " + std::to_string(r.snapshots) +
                " snapshots (at least " + std::to_string(options.min_samples) + " and 2 snapshots needed); skipped";
    return r;
  }
  r.density = static_cast<double>(r.samples) / area;
  r.cell_temperature = weighted / static_cast<double>(r.samples);
  std::vector<double> speed(r.samples);
  double squares = 0.0;
  for (std::size_t i = 0; i < r.samples; ++i) {
    speed[i] = std::hypot(w.vx[i], w.vy[i]);
    squares += speed[i] * speed[i];
  }
  r.temperature = 0.5 * squares / static_cast<double>(r.samples);
  r.speed_scale = std::sqrt(2.0 * r.temperature);
  const double largest = *std::max_element(speed.begin(), speed.end());
  r.speed_max = options.speed_max > 0.0 ? options.speed_max : largest * (1.0 + 1e-9);
  const auto quantile_index = static_cast<std::size_t>(options.fit_quantile * static_cast<double>(r.samples - 1));
  std::nth_element(speed.begin(), speed.begin() + static_cast<std::ptrdiff_t>(quantile_index), speed.end());
  r.fit_speed_max = std::min(speed[quantile_index], r.speed_max);

  const PolarGrid grid{options.speed_bins, options.angle_bins, r.speed_max / r.speed_scale};
  const SnapshotBins bins = bin_snapshots(w, grid, r.speed_scale);
  const double fit_u = r.fit_speed_max / r.speed_scale;
  r.estimate = estimate(bins, std::vector<double>(r.snapshots, 1.0), grid, fit_u, r.speed_scale, options, std::nullopt);
  if (const std::string failures = fit_failures(r.estimate); !failures.empty()) {
    r.warning = window_label(w) + ": the fits failed (" + failures + "); skipped";
    return r;
  }
  r.quality = quality_of(r.estimate);
  r.jenkins_richman = jenkins_richman(r.estimate.direct);

  // Bootstrap over snapshots: the snapshots are the ensemble of (5.7).  Every replicate fits the
  // harmonics of (5.21) with the shapes the whole sample chose, so the errors are those of that one
  // model: re-choosing per replicate would switch a marginal harmonic's Q_p on and off (duplicated
  // snapshots blur a replicate's harmonics) and spread the replicates over two models.
  std::mt19937_64 random(options.seed);
  std::uniform_int_distribution<std::size_t> pick(0, r.snapshots - 1);
  Spread spread;
  for (int b = 0; b < options.bootstrap; ++b) {
    std::vector<double> multiplicity(r.snapshots, 0.0);
    for (std::size_t k = 0; k < r.snapshots; ++k) multiplicity[pick(random)] += 1.0;
    F1Estimate replicate = estimate(bins, multiplicity, grid, fit_u, r.speed_scale, options, r.estimate.once.angular.resolved);
    for (int j = 1; j <= SineSeries::kHarmonics; ++j) align_phase(replicate.series, j, r.estimate.series.phase[j - 1]);
    if (!fit_failures(replicate).empty()) continue;  // a failed fit is no sample of the spread
    spread.add(error_quantities(replicate));
    ++r.errors.converged_replicates;
    r.errors.replicate_numbers.push_back({replicate.series, replicate.direct.trace(), replicate.once_integrals.moment.trace(),
                                          replicate.twice_integrals.moment.trace(), replicate.ratio});
  }
  r.errors.replicates = options.bootstrap;
  if (options.bootstrap > 0) {
    const Eigen::VectorXd d = spread.deviation();
    const auto n = d.size();
    r.errors.series = series_from_parameters(d.head(n - 4));
    r.errors.direct_trace = d[n - 4];
    r.errors.once_trace = d[n - 3];
    r.errors.twice_trace = d[n - 2];
    r.errors.ratio = d[n - 1];
  }
  r.analysed = true;
  return r;
}

double f1_analysis_bytes(std::size_t particles, std::size_t snapshots, std::size_t windows, const F1Options& options) {
  const double samples = static_cast<double>(particles) * static_cast<double>(snapshots) * static_cast<double>(windows);
  const double bins = (options.speed_bins + 1.0) * (options.angle_bins + 1.0);
  constexpr double kGridArrays = 8.0;  // counts, h, h*, ψ, ψ*, the fit's work arrays: a few of that size
  return 2.0 * 8.0 * samples + 8.0 * bins * (static_cast<double>(snapshots) + kGridArrays);
}

}  // namespace granule::distribution
