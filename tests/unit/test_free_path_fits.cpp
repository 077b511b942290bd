// Unit tier: the fits of the free-path distribution (thesis §3.2.3, src/analysis/
// collision_statistics_fits.*) on paths drawn from an INDEPENDENT sampler of the density (3.24) —
// not by inverting the code's own cumulative — histogrammed by the code's own observer
// (FreePathStatistics, fed synthetic collisions), with analytic sampling errors.
//
// The sampler.  (3.24) is a product: the angular factor has density ∝ Σ_{c=0,1,2} 1/(1 + ((α −
// cπ)/α₀)²) on [0, 2π), an equal mixture of three Cauchy (Lorentz) laws of scale α₀ centred at 0,
// π and 2π restricted to [0, 2π) — draw a centre, then cπ + α₀ tan(π(U − ½)), and reject values
// outside.  The radial factor erf(√(l/l̄)) is the cumulative of l = l̄ Z²/2, Z standard normal
// (P(l̄Z²/2 < l) = P(|Z| < √(2l/l̄)) = erf(√(l/l̄))), i.e. the Gamma law of shape ½ (3.36).
//
// The errors.  Both fits are unweighted least squares of an empirical cumulative F̂ at the bin
// edges x_k against a model G(x; s).  Linearised about the truth, ŝ − s = Σ_k g_k δF_k / Σ_k g_k²
// with g_k = ∂G(x_k)/∂s, and the empirical cumulative of N samples has Cov(δF_j, δF_k) =
// [min(F_j, F_k) − F_j F_k]/N, so Var ŝ = gᵀCg/(gᵀg)².  The angular cumulative is normalised by
// the N paths shorter than l_max, the radial one by all paths.  The residual of a correct model,
// δF − g(ŝ − s) = P δF with P = 1 − ggᵀ/gᵀg, has E Σ r² = tr(PCP) and, as a sum of eigenvalues λ
// times χ²₁, scatters like c χ²_ν with ν = (Σλ)²/Σλ² (Satterthwaite).  The maximum-likelihood
// l₀ = 2⟨l⟩ of (3.36) uses exact sums: Var = 4 Var(l)/N = 2 l̄²/N.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

#include "observers/collision_statistics_fits.hpp"
#include "observers/free_paths.hpp"
#include "init/random.hpp"
#include "unit/chi_square.hpp"

namespace granule {
namespace {

using test_statistics::chi_square_quantile;
using test_statistics::kNormal9995;

constexpr double kPi = std::numbers::pi;

double draw_angle(Random& random, double alpha0, double centre_offset) {
  for (;;) {
    const double centre = static_cast<double>(random.below(3)) * kPi + centre_offset;
    const double alpha = centre + alpha0 * std::tan(kPi * (random.uniform() - 0.5));
    if (alpha >= 0.0 && alpha < 2.0 * kPi) return alpha;
  }
}

double draw_length(Random& random, double lbar) {
  const double z = random.normal();
  return 0.5 * lbar * z * z;
}

// Paths fed to the code's observer as the flights between successive collisions of disks 0 and
// 1 at times 0, 1, 2, …: the velocity after each collision is the next path (flight time 1).
template <typename Draw>
PathHistogram observed_paths(int paths, const FreePathSettings& settings, Draw&& draw) {
  FreePathStatistics<2> statistics(2, settings, nullptr);
  statistics.start();
  const auto velocity = [&] {
    const auto [length, alpha] = draw();
    return Vec2{length * std::cos(alpha), length * std::sin(alpha)};
  };
  for (int k = 0; k <= paths / 2; ++k) {
    CollisionRecord<2> r;
    r.time = k;
    r.first = 0;
    r.second = 1;
    r.first_velocity_after = velocity();
    r.second_velocity_after = velocity();
    statistics.on_collision(r);
  }
  return statistics.total();
}

// The angular factor of (3.24), normalised to 0 at α = 0 and 1 at 2π (the reference law).
double angular_cumulative(double alpha, double alpha0) {
  const auto f = [&](double a) {
    return std::atan(a / alpha0) + std::atan((a - kPi) / alpha0) + std::atan((a - 2.0 * kPi) / alpha0);
  };
  return (f(alpha) - f(0.0)) / (f(2.0 * kPi) - f(0.0));
}

// Linearised least squares of an empirical cumulative: σ of the fitted scale, and the mean and
// Satterthwaite degrees of freedom of the residual sum of squares of a correct model.
struct LeastSquaresErrors {
  double sigma;
  double residual_mean;
  double residual_dof;
};

LeastSquaresErrors least_squares_errors(const Eigen::VectorXd& f, const Eigen::VectorXd& g, double samples) {
  const Eigen::Index n = f.size();
  Eigen::MatrixXd c(n, n);
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index k = 0; k < n; ++k) c(j, k) = (std::min(f[j], f[k]) - f[j] * f[k]) / samples;
  const double gg = g.squaredNorm();
  const Eigen::MatrixXd p = Eigen::MatrixXd::Identity(n, n) - g * g.transpose() / gg;
  const Eigen::MatrixXd projected = p * c * p;
  const double trace = projected.trace(), trace_squares = (projected * projected).trace();
  return {std::sqrt(g.dot(c * g)) / gg, trace, trace * trace / trace_squares};
}

FreePathSettings settings_for(double lbar) {
  FreePathSettings s;
  s.length_bins = 100;
  s.angle_bins = 72;
  s.max_length = 5.0 * lbar;  // ten mean lengths, as the run's default (⟨l⟩ = l̄/2)
  s.widen = false;            // the fits are tested on a histogram of known bins
  return s;
}

UniformBins angle_bins_of(const FreePathSettings& s) { return {0.0, 2.0 * kPi, s.angle_bins}; }
UniformBins length_bins_of(const FreePathSettings& s) { return {0.0, s.max_length, s.length_bins}; }

TEST(FreePathFits, AlphaZeroAndLbarAreRecoveredWithinTheirAnalyticErrors) {
  constexpr int kSeeds = 40, kPaths = 40000;
  const double lbar = 0.37;
  const FreePathSettings settings = settings_for(lbar);
  const UniformBins angles = angle_bins_of(settings), lengths = length_bins_of(settings);
  // Radial errors: the same for every α₀.
  Eigen::VectorXd f_radial(lengths.bins), g_radial(lengths.bins);
  for (int k = 0; k < lengths.bins; ++k) {
    const double l = lengths.edge(k + 1);
    f_radial[k] = std::erf(std::sqrt(l / lbar));
    g_radial[k] = -std::exp(-l / lbar) * std::sqrt(l) / (std::sqrt(kPi) * std::pow(lbar, 1.5));
  }
  const LeastSquaresErrors radial = least_squares_errors(f_radial, g_radial, kPaths);
  const double sigma_l0 = lbar * std::sqrt(2.0 / kPaths);
  for (const double alpha0 : {0.05, 0.2, 0.6}) {
    Eigen::VectorXd f_angle(angles.bins), g_angle(angles.bins);
    for (int a = 0; a < angles.bins; ++a) {
      const double alpha = angles.edge(a + 1), h = 1e-6 * alpha0;
      f_angle[a] = angular_cumulative(alpha, alpha0);
      g_angle[a] = (angular_cumulative(alpha, alpha0 + h) - angular_cumulative(alpha, alpha0 - h)) / (2.0 * h);
    }
    const double below = kPaths * std::erf(std::sqrt(settings.max_length / lbar));
    const LeastSquaresErrors angular = least_squares_errors(f_angle, g_angle, below);
    double z2_alpha = 0, z2_lbar = 0, z2_l0 = 0, largest = 0, rms2_alpha = 0, rms2_lbar = 0;
    for (int seed = 1; seed <= kSeeds; ++seed) {
      Random random(static_cast<std::uint64_t>(1000 * seed) + static_cast<std::uint64_t>(alpha0 * 100));
      const PathHistogram h = observed_paths(kPaths, settings, [&] {
        const double l = draw_length(random, lbar);
        return std::pair{l, draw_angle(random, alpha0, 0.0)};
      });
      const FreePathSummary s = summarize_free_paths(h, lengths, angles);
      const double z_alpha = (s.alpha0 - alpha0) / angular.sigma, z_lbar = (s.lbar - lbar) / radial.sigma,
                   z_l0 = (s.l0_matched - lbar) / sigma_l0;
      z2_alpha += z_alpha * z_alpha;
      z2_lbar += z_lbar * z_lbar;
      z2_l0 += z_l0 * z_l0;
      largest = std::max({largest, std::abs(z_alpha), std::abs(z_lbar), std::abs(z_l0)});
      rms2_alpha += s.alpha0_rms * s.alpha0_rms * angles.bins;
      rms2_lbar += s.lbar_rms * s.lbar_rms * lengths.bins;
    }
    const double low = chi_square_quantile(kSeeds, -kNormal9995), high = chi_square_quantile(kSeeds, kNormal9995);
    std::printf("α0 = %.2f, l̄ = %.2f, %d seeds of %d paths: σ(α0) = %.5f, σ(l̄) = %.5f, σ(l0 = 2<l>) = %.5f; "
                "Σz² (%d dof, 99.9%% range %.1f–%.1f): α0 %.1f, l̄ %.1f, l0 %.1f; largest |z| %.2f; "
                "residual Σr² / expected: angular %.3f, radial %.3f\n",
                alpha0, lbar, kSeeds, kPaths, angular.sigma, radial.sigma, sigma_l0, kSeeds, low, high, z2_alpha, z2_lbar,
                z2_l0, largest, rms2_alpha / (kSeeds * angular.residual_mean), rms2_lbar / (kSeeds * radial.residual_mean));
    EXPECT_LT(largest, 4.5);
    for (const double z2 : {z2_alpha, z2_lbar, z2_l0}) {
      EXPECT_GT(z2, low);
      EXPECT_LT(z2, high);
    }
    // The residuals of a correct model are counting noise, no more, no less.
    const struct {
      double sum;
      LeastSquaresErrors e;
    } residuals[] = {{rms2_alpha, angular}, {rms2_lbar, radial}};
    for (const auto& r : residuals) {
      const double dof = kSeeds * r.e.residual_dof, scale = r.e.residual_mean / r.e.residual_dof;
      EXPECT_GT(r.sum / scale, chi_square_quantile(dof, -kNormal9995));
      EXPECT_LT(r.sum / scale, chi_square_quantile(dof, kNormal9995));
    }
  }
}

// Distributions that (3.24) cannot describe must show in the residuals: paths across the flow
// (Lorentz peaks at π/2 and 3π/2) and exponential lengths (the conventional law (3.35) for all l).
TEST(FreePathFits, WrongLawsReportResidualsFarAboveCountingNoise) {
  constexpr int kPaths = 40000;
  const double lbar = 0.37, alpha0 = 0.2;
  const FreePathSettings settings = settings_for(lbar);
  const UniformBins angles = angle_bins_of(settings), lengths = length_bins_of(settings);
  Random random(3);
  const PathHistogram h = observed_paths(kPaths, settings, [&] {
    const double l = -0.5 * lbar * std::log(1.0 - random.uniform());  // exponential, mean l̄/2
    return std::pair{l, draw_angle(random, alpha0, 0.5 * kPi)};
  });
  const FreePathSummary s = summarize_free_paths(h, lengths, angles);
  // Counting noise of a cumulative: rms of √(F(1 − F)/N) ≤ 1/(2√N).
  const double noise = 0.5 / std::sqrt(static_cast<double>(kPaths));
  std::printf("paths across the flow, exponential lengths: α0 = %.4g (rms %.4f), l̄ = %.4g (rms %.4f); counting noise ≤ %.4f; "
              "KS distance to (3.36) %.4f, to the exponential %.4f\n",
              s.alpha0, s.alpha0_rms, s.lbar, s.lbar_rms, noise, s.ks_matched, s.ks_exponential);
  EXPECT_GT(s.alpha0_rms, 20.0 * noise);
  EXPECT_GT(s.lbar_rms, 5.0 * noise);
  EXPECT_GT(s.ks_matched, 10.0 * noise);
  EXPECT_LT(s.ks_exponential, 4.0 * noise);
}

// No fit where there is nothing to fit: every path beyond the histogram's range, or every path
// inside its first length bin, leaves no scale to measure.
TEST(FreePathFits, FitsFailWhenThePathsLieOutsideTheHistogram) {
  const double lbar = 0.37;
  const FreePathSettings settings = settings_for(lbar);
  const UniformBins angles = angle_bins_of(settings), lengths = length_bins_of(settings);
  Random random(4);
  for (const double scale : {100.0, 1e-4}) {
    const PathHistogram h = observed_paths(2000, settings, [&] {
      return std::pair{scale * settings.max_length * (1.0 + random.uniform()), draw_angle(random, 0.2, 0.0)};
    });
    const FreePathSummary s = summarize_free_paths(h, lengths, angles);
    std::printf("paths %g × l_max: α0 = %g (rms %g), l̄ = %g (rms %g)\n", scale, s.alpha0, s.alpha0_rms, s.lbar, s.lbar_rms);
    EXPECT_TRUE(std::isnan(s.lbar)) << s.lbar;
    if (scale > 1.0) {
      EXPECT_TRUE(std::isnan(s.alpha0)) << s.alpha0;
    }
  }
}

// A window that closed with no path (a run interrupted early): NaN everywhere, in arrays of the
// histogram's shape — the writers index them by bin (UBSan found them reading empty vectors).
TEST(FreePathSummary, NoPathsGiveNaNArraysOfTheHistogramsShape) {
  const UniformBins lengths{0.0, 2.0, 7}, angles{0.0, 2.0 * std::numbers::pi, 5};
  PathHistogram empty;
  empty.counts.assign(35, 0.0);
  empty.overflow.assign(5, 0.0);
  const FreePathSummary s = summarize_free_paths(empty, lengths, angles);
  EXPECT_EQ(s.paths, 0.0);
  EXPECT_EQ(s.cumulative.size(), 35u);
  for (const auto* v : {&s.magnitude_density, &s.matched_density, &s.exponential_density, &s.length_cumulative}) {
    ASSERT_EQ(v->size(), 7u);
    EXPECT_TRUE(std::all_of(v->begin(), v->end(), [](double x) { return std::isnan(x); }));
  }
  for (const auto* v : {&s.angular_cumulative, &s.angular_fit}) ASSERT_EQ(v->size(), 5u);
  EXPECT_TRUE(std::isnan(s.mean_length) && std::isnan(s.lbar) && std::isnan(s.alpha0));
}

}  // namespace
}  // namespace granule
