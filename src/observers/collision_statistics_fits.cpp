#include "observers/collision_statistics_fits.hpp"

#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <limits>
#include <numbers>

namespace granule {

namespace {

struct ScaleFit {
  double value;
  bool at_range_end;  // the scan's best point was `low` or `high`: no minimum inside the range
};

// Minimise a one-parameter least-squares objective over a positive scale between `low` and
// `high`: a coarse scan in log space finds the basin (the objectives here need not be unimodal
// over many decades), then Brent's method (Boost.Math) refines within the neighbouring points.
template <typename Objective>
ScaleFit fit_scale(Objective&& objective, double low, double high) {
  const auto in_log = [&](double u) { return objective(std::exp(u)); };
  constexpr int kScan = 96;
  const double a = std::log(low), step = (std::log(high) - a) / kScan;
  int best = 0;
  double best_value = in_log(a);
  for (int k = 1; k <= kScan; ++k) {
    const double value = in_log(a + k * step);
    if (value < best_value) {
      best_value = value;
      best = k;
    }
  }
  const auto refined = boost::math::tools::brent_find_minima(in_log, a + std::max(0, best - 1) * step,
                                                             a + std::min(kScan, best + 1) * step, 40);
  return {std::exp(refined.first), best == 0 || best == kScan};
}

}  // namespace

ImpactParameterSummary summarize_impact_parameters(const std::vector<double>& counts, const UniformBins& bins) {
  ImpactParameterSummary s;
  for (double c : counts) s.samples += c;
  double running = 0.0;
  for (int k = 0; k < bins.bins; ++k) {
    const double c = counts[static_cast<std::size_t>(k)];
    running += c;
    s.density.push_back(s.samples > 0.0 ? c / (s.samples * bins.width()) : 0.0);
    const double deviation = s.samples > 0.0 ? running / s.samples - bins.edge(k + 1) : 0.0;
    s.cumulative_minus_uniform.push_back(deviation);
    s.ks_uniform = std::max(s.ks_uniform, std::abs(deviation));
  }
  return s;
}

double free_path_angular_cumulative(double alpha, double alpha0) {
  const double pi = std::numbers::pi;
  const auto f = [&](double a) { return std::atan(a / alpha0) + std::atan((a - pi) / alpha0) + std::atan((a - 2.0 * pi) / alpha0); };
  return (f(alpha) - f(0.0)) / (f(2.0 * pi) - f(0.0));
}

FreePathSummary summarize_free_paths(const PathHistogram& h, const UniformBins& lengths, const UniformBins& angles,
                                     int dimension) {
  FreePathSummary s;
  s.paths = h.paths;
  const auto nl = static_cast<std::size_t>(lengths.bins), na = static_cast<std::size_t>(angles.bins);
  if (h.paths <= 0.0) {
    // No path recorded (a run stopped before its first window closed): every quantity is NaN, in
    // arrays of the histogram's shape, so that writers never read past an empty vector.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    s.mean_length = s.mean_speed = s.l0_matched = s.lambda_exponential = nan;
    s.lbar = s.lbar_rms = s.alpha0 = s.alpha0_rms = s.ks_isotropic = s.ks_matched = s.ks_exponential = nan;
    s.cumulative.assign(nl * na, nan);
    for (auto* v : {&s.magnitude_density, &s.matched_density, &s.exponential_density, &s.length_cumulative}) v->assign(nl, nan);
    for (auto* v : {&s.angular_cumulative, &s.angular_fit}) v->assign(na, nan);
    return s;
  }
  s.mean_length = h.sum_length / h.paths;
  s.mean_speed = h.sum_speed / h.paths;
  s.l0_matched = 2.0 * s.mean_length;
  s.lambda_exponential = s.mean_length;

  // L(l, α) (3.23): the fraction of all paths (overflow included in the total) shorter than l
  // with angle below α.
  s.cumulative.assign(nl * na, 0.0);
  std::vector<double> column(na, 0.0);
  for (std::size_t l = 0; l < nl; ++l) {
    double row = 0.0, in_bin = 0.0;
    for (std::size_t a = 0; a < na; ++a) {
      in_bin += h.counts[l * na + a];
      column[a] += h.counts[l * na + a];
      row += column[a];
      s.cumulative[l * na + a] = row / h.paths;
    }
    s.length_cumulative.push_back(s.cumulative[l * na + na - 1]);
    s.magnitude_density.push_back(in_bin / (h.paths * lengths.width()));
  }

  // Magnitude: the matched form (3.36) and the exponential, bin-averaged from their cumulatives.
  const auto matched_cdf = [&](double l, double l0) { return std::erf(std::sqrt(l / l0)); };
  const auto exponential_cdf = [&](double l) { return 1.0 - std::exp(-l / s.lambda_exponential); };
  for (int k = 0; k < lengths.bins; ++k) {
    const double lo = lengths.edge(k), hi = lengths.edge(k + 1);
    s.matched_density.push_back((matched_cdf(hi, s.l0_matched) - matched_cdf(lo, s.l0_matched)) / lengths.width());
    s.exponential_density.push_back((exponential_cdf(hi) - exponential_cdf(lo)) / lengths.width());
    const double empirical = s.length_cumulative[static_cast<std::size_t>(k)];
    s.ks_matched = std::max(s.ks_matched, std::abs(empirical - matched_cdf(hi, s.l0_matched)));
    s.ks_exponential = std::max(s.ks_exponential, std::abs(empirical - exponential_cdf(hi)));
  }

  // Radial part of (3.24): least-squares l̄ of erf(√(l/l̄)) against L(l, 2π).
  const auto radial_error = [&](double lbar) {
    double sum = 0.0;
    for (int k = 0; k < lengths.bins; ++k) {
      const double d = s.length_cumulative[static_cast<std::size_t>(k)] - matched_cdf(lengths.edge(k + 1), lbar);
      sum += d * d;
    }
    return sum;
  };
  // A best l̄ at an end of the range (10⁻³ to 10³ mean lengths) means the paths lie almost all
  // beyond the histogram's range or inside its first bin: no l̄ is measured (NaN).
  const ScaleFit radial = fit_scale(radial_error, 1e-3 * s.mean_length, 1e3 * s.mean_length);
  s.lbar = radial.at_range_end ? std::numeric_limits<double>::quiet_NaN() : radial.value;
  s.lbar_rms = std::sqrt(radial_error(s.lbar) / lengths.bins);

  // Angular part of (3.24): α₀ against L(l_max, α) normalised to its value at 2π.  With no path
  // shorter than l_max there is no angular distribution to fit (NaN).  α₀ at the upper end of its
  // range (10⁴) is the isotropic limit of (3.24), at the lower end (10⁻⁴) paths exactly along x.
  const double below_max = s.length_cumulative.back();
  if (!(below_max > 0.0)) {
    s.alpha0 = s.alpha0_rms = s.ks_isotropic = std::numeric_limits<double>::quiet_NaN();
    s.angular_cumulative.assign(na, s.alpha0);
    s.angular_fit.assign(na, s.alpha0);
    return s;
  }
  for (std::size_t a = 0; a < na; ++a) s.angular_cumulative.push_back(s.cumulative[(nl - 1) * na + a] / below_max);
  for (int a = 0; a < angles.bins; ++a) {
    const double isotropic = static_cast<double>(a + 1) / angles.bins;  // the uniform law at the upper edge
    s.ks_isotropic = std::max(s.ks_isotropic, std::abs(s.angular_cumulative[static_cast<std::size_t>(a)] - isotropic));
  }
  if (dimension == 3) {
    // No thesis form to fit for spheres: the isotropic law is the reference.
    s.alpha0 = s.alpha0_rms = std::numeric_limits<double>::quiet_NaN();
    for (int a = 0; a < angles.bins; ++a) s.angular_fit.push_back(static_cast<double>(a + 1) / angles.bins);
    return s;
  }
  const auto angular_error = [&](double alpha0) {
    double sum = 0.0;
    for (int a = 0; a < angles.bins; ++a) {
      const double d = s.angular_cumulative[static_cast<std::size_t>(a)] - free_path_angular_cumulative(angles.edge(a + 1), alpha0);
      sum += d * d;
    }
    return sum;
  };
  s.alpha0 = fit_scale(angular_error, 1e-4, 1e4).value;
  s.alpha0_rms = std::sqrt(angular_error(s.alpha0) / angles.bins);
  for (int a = 0; a < angles.bins; ++a) s.angular_fit.push_back(free_path_angular_cumulative(angles.edge(a + 1), s.alpha0));
  return s;
}

}  // namespace granule
