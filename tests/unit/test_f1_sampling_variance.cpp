// Unit tier: what the f1 analysis (src/distribution, thesis §5.2) estimates, against ANALYTIC
// sampling variances — not against the tool's own bootstrap.  Samples are drawn from known
// distributions many times over (Granule's Random, fixed seeds); every estimate becomes a z-score
// with a closed-form standard deviation, and the z-scores of all seeds are pooled into a
// chi-square.  The derivations:
//
// 1. Angular harmonics of ψ (5.19).  At the last speed edge every sample is counted, so
//    h(u_max, θ_l) is the fraction of angles below θ_l = 2πl/n_θ and φ(u_max) = 1/2π exactly; the
//    code's ψ there is ψ_l = h_l − l/n_θ − (its mean over l).  Its projections on the harmonics of
//    (5.21), S_p = (2/n_θ) Σ_l ψ_l sin 2pθ_l and C_p likewise with cos (p = 1 … 4), are linear in the
//    counts: a sample in angle bin m adds 1/n to h_l for every l > m, so S_p = (1/n) Σ_i W_p(m_i) +
//    const with W_p(m) = (2/n_θ) Σ_{l=m+1}^{n_θ−1} sin 2pθ_l (the mean over l projects to zero, as
//    Σ_l sin 2pθ_l = 0).  With q_m the probability of bin m:
//      E[S_p] = Σ_m q_m W_p(m) + const,   Cov(X_a, X_b) = [Σ_m q_m W_a W_b − (Σ_m q_m W_a)(Σ_m q_m W_b)]/n
//    exactly (multinomial counts).  Isotropic: q_m = 1/n_θ.  Centred Gaussian of covariance K: the
//    angle θ of v has density 1/(2π √det K êᵀAê), A = K⁻¹, and ∫dθ/(êᵀAê) = atan((A_yy tan θ +
//    A_xy)/√det A)/√det A, so its CDF is the polar angle of M ê(θ), M = [[√det A, 0], [A_xy, A_yy]]
//    (an orientation-preserving map, hence monotone), divided by 2π.  The 8 projections of one seed
//    have a Mahalanobis distance ~ χ²_8 (normal limit of n ≥ 2·10⁴ counts).
//
// 2. The direct second moment (5.31), K̂ = (1/n) Σ v v: for a Gaussian of covariance K,
//    Var tr K̂ = 2(K_xx² + K_yy² + 2K_xy²)/n — for a Maxwellian at T, (2T)²/n (v²/2T is exponential).
//
// 3. The means b_0^(i) of the fitted exponent (5.27, 5.29).  In units 2T = 1 the isotropic
//    Maxwellian is f = exp(−b0 − b1 u − b2 u²) per unit area of the velocity plane, b1 = 0, b2 = 1,
//    b0 = log π.  The family of (5.27) with its harmonics (5.29) is exponential, with sufficient
//    statistics u, u², u^i cos 2jθ, u^i sin 2jθ; its Fisher matrix is their covariance, and under
//    isotropy the harmonic statistics are uncorrelated with (u, u²) (θ is independent of u and
//    E cos 2jθ = 0), so for (b1, b2) the Cramér–Rao bound is Cov ≥ I⁻¹/n with
//      I = [[Var u, Cov(u, u²)], [Cov(u, u²), Var u²]] = [[1 − π/4, √π/4], [√π/4, 1]]
//    (Rayleigh moments ⟨u⟩ = √π/2, ⟨u²⟩ = 1, ⟨u³⟩ = 3√π/4, ⟨u⁴⟩ = 2): σ(√2T b_0^(1)) ≥ 7.40/√n,
//    σ(2T b_0^(2)) ≥ 3.43/√n.  b0 is the normalisation log ∫exp(−b1 u − b2 u²) d²u, whose gradient is
//    −(⟨u⟩, ⟨u²⟩), so Var b̂0 ≥ (⟨u⟩, ⟨u²⟩) I⁻¹ (⟨u⟩, ⟨u²⟩)ᵀ/n = [I⁻¹]_22/n (the other terms cancel
//    exactly): σ(b_0^(0)) ≥ 3.43/√n.  The pipeline is not the maximum-likelihood estimator, so its
//    spread may exceed the bound (measured: by 1.03–1.21 in variance over 100 seeds of 2·10⁵
//    samples), but never fall below it; we require the variance within 1.5 × the bound.
//    For a harmonic component the same argument gives Var ≥ 2[M⁻¹]_ii/n, M_ab = ⟨u^{a+b}⟩ (a, b =
//    0, 1, 2), since Cov(u^a cos 2jθ, u^b cos 2jθ) = ⟨u^{a+b}⟩/2.  The fitted amplitudes are not
//    unbiased estimators of those components (one phase per harmonic, the once-fitted form (5.21)
//    behind them, the speed dependence of unresolved harmonics tied to φ*'s), so the bound serves
//    only as a scale: no amplitude may exceed 5 of its σ.
//
// 4. Bootstrap errors.  The analysis resamples m snapshots with replacement B times; for iid
//    samples the ideal bootstrap variance is (m − 1)/m times the sampling variance.  The squared
//    error from B replicates scatters by 2/(B − 1) (relative variance) and the ideal bootstrap
//    variance itself by ≈ 2/(m − 1) from data set to data set, so ν s²/σ² ~ χ²_ν with
//    ν = 2/(2/(B − 1) + 2/(m − 1)) (Satterthwaite), summed over seeds.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "distribution/f1_analysis.hpp"
#include "init/random.hpp"
#include "unit/chi_square.hpp"
#include "unit/maxwellian_cramer_rao.hpp"

namespace granule::distribution {
namespace {

using granule::test_statistics::chi_square_quantile;
using granule::test_statistics::kNormal9995;
using granule::test_statistics::maxwellian_harmonic_bound_times_root_n;
using granule::test_statistics::maxwellian_means_bound_times_n;

constexpr double kT = 0.7;
constexpr int kHarmonics = AngularFit::kHarmonics;

// `snapshots` × `per_snapshot` samples of the centred Gaussian of covariance k.
WindowSamples gaussian_window(std::uint64_t seed, int snapshots, int per_snapshot, const SecondMoment& k) {
  const double lxx = std::sqrt(k.xx), lyx = k.xy / lxx, lyy = std::sqrt(k.yy - lyx * lyx);  // Cholesky
  Random random(seed);
  WindowSamples w;
  for (int s = 0; s < snapshots; ++s) {
    for (int i = 0; i < per_snapshot; ++i) {
      const double a = random.normal(), b = random.normal();
      w.vx.push_back(lxx * a);
      w.vy.push_back(lyx * a + lyy * b);
    }
    w.snapshot_end.push_back(w.vx.size());
    w.selected_area.push_back(1.0);
    w.temperature_weighted.push_back(0.0);
  }
  return w;
}

// ---- 1. angular harmonics of ψ -------------------------------------------------------------

// Probability of each of `bins` equal angle bins for a centred Gaussian of covariance k.
std::vector<double> gaussian_angle_bins(const SecondMoment& k, int bins) {
  const double det = k.xx * k.yy - k.xy * k.xy;
  const double a_xy = -k.xy / det, a_yy = k.xx / det, root_det_a = 1.0 / std::sqrt(det);
  const auto mapped_angle = [&](double theta) {
    return std::atan2(a_xy * std::cos(theta) + a_yy * std::sin(theta), root_det_a * std::cos(theta));
  };
  std::vector<double> q(static_cast<std::size_t>(bins));
  for (int m = 0; m < bins; ++m) {
    double increment = mapped_angle(2.0 * M_PI * (m + 1) / bins) - mapped_angle(2.0 * M_PI * m / bins);
    if (increment < 0.0) increment += 2.0 * M_PI;
    q[static_cast<std::size_t>(m)] = increment / (2.0 * M_PI);
  }
  return q;
}

// The weights W(m) of the 8 projections (S_1 … S_4, C_1 … C_4) and their constants.
struct ProjectionWeights {
  Eigen::MatrixXd w;         // bins × 8
  Eigen::VectorXd constant;  // 8
};

ProjectionWeights projection_weights(int bins) {
  ProjectionWeights out{Eigen::MatrixXd::Zero(bins, 2 * kHarmonics), Eigen::VectorXd::Zero(2 * kHarmonics)};
  for (int p = 1; p <= kHarmonics; ++p)
    for (int l = 0; l < bins; ++l) {
      const double theta = 2.0 * M_PI * l / bins;
      const double s = 2.0 / bins * std::sin(2.0 * p * theta), c = 2.0 / bins * std::cos(2.0 * p * theta);
      for (int m = 0; m < l; ++m) {  // samples of bin m < l lie below θ_l
        out.w(m, p - 1) += s;
        out.w(m, kHarmonics + p - 1) += c;
      }
      out.constant[p - 1] -= s * l / bins;
      out.constant[kHarmonics + p - 1] -= c * l / bins;
    }
  return out;
}

// The code's ψ at the last speed edge, projected as above.
Eigen::VectorXd measured_projections(const WindowSamples& w, int angle_bins) {
  std::vector<double> speed, angle;
  for (std::size_t i = 0; i < w.samples(); ++i) {
    speed.push_back(std::hypot(w.vx[i], w.vy[i]));
    const double a = std::atan2(w.vy[i], w.vx[i]);
    angle.push_back(a < 0.0 ? a + 2.0 * M_PI : a);
  }
  const PolarGrid grid{8, angle_bins, *std::max_element(speed.begin(), speed.end()) * (1.0 + 1e-9)};
  const CumulativeFunction c =
      cumulative_function(polar_counts(speed.data(), angle.data(), speed.size(), grid), static_cast<double>(speed.size()), grid);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(2 * kHarmonics);
  for (int p = 1; p <= kHarmonics; ++p)
    for (int l = 0; l < angle_bins; ++l) {
      const double theta = grid.angle_edge(l);
      x[p - 1] += 2.0 / angle_bins * c.psi(grid.speed_bins, l) * std::sin(2.0 * p * theta);
      x[kHarmonics + p - 1] += 2.0 / angle_bins * c.psi(grid.speed_bins, l) * std::cos(2.0 * p * theta);
    }
  return x;
}

TEST(F1SamplingVariance, AngularHarmonicsOfPsiHaveTheirExactMultinomialSpread) {
  constexpr int kSeeds = 100, kSamples = 20000, kAngleBins = 32;
  const ProjectionWeights weights = projection_weights(kAngleBins);
  struct Case {
    const char* name;
    SecondMoment k;
  };
  for (const Case c : {Case{"isotropic Maxwellian", {kT, 0.0, kT}}, Case{"anisotropic Gaussian", {1.3, -0.35, 0.8}}}) {
    const std::vector<double> q = gaussian_angle_bins(c.k, kAngleBins);
    const Eigen::Map<const Eigen::VectorXd> probability(q.data(), kAngleBins);
    const Eigen::VectorXd first = weights.w.transpose() * probability;
    const Eigen::VectorXd mean = first + weights.constant;
    const Eigen::MatrixXd covariance =
        (weights.w.transpose() * probability.asDiagonal() * weights.w - first * first.transpose()) / kSamples;
    const Eigen::LLT<Eigen::MatrixXd> cholesky(covariance);
    double pooled = 0.0, largest = 0.0;
    for (int seed = 1; seed <= kSeeds; ++seed) {
      const Eigen::VectorXd residual = measured_projections(gaussian_window(1000 + seed, 1, kSamples, c.k), kAngleBins) - mean;
      const double distance = residual.dot(cholesky.solve(residual));
      pooled += distance;
      largest = std::max(largest, distance);
    }
    const double dof = 2.0 * kHarmonics * kSeeds;
    const double low = chi_square_quantile(dof, -kNormal9995), high = chi_square_quantile(dof, kNormal9995);
    const double single = chi_square_quantile(2.0 * kHarmonics, 4.75);  // p = 1e-6 per seed
    std::printf("%s: ψ harmonics p = 1..4 at the last speed edge, %d seeds of %d samples: E|S_1| = %.5f ± %.5f; "
                "pooled χ² = %.1f for %g dof (99.9%% range %.1f–%.1f), largest per seed %.2f (limit %.1f)\n",
                c.name, kSeeds, kSamples, std::hypot(mean[0], mean[kHarmonics]), std::sqrt(covariance(0, 0)), pooled, dof,
                low, high, largest, single);
    EXPECT_GT(pooled, low) << c.name;
    EXPECT_LT(pooled, high) << c.name;
    EXPECT_LT(largest, single) << c.name;
  }
}

// ---- 2–4. the fitted means, the direct moment and the bootstrap ---------------------------------

// Each estimate costs ~0.05 s (32 × 32 bins); each test computes its own (ctest runs every test in
// a process of its own, so a shared cache would be computed twice anyway).
constexpr int kSnapshots = 40, kPerSnapshot = 2500;
constexpr double kSamples = kSnapshots * kPerSnapshot;
constexpr int kSeeds = 12;
constexpr int kBootstrapSeeds = 2, kReplicates = 6;

struct SeedResult {
  double b1 = 0, b2 = 0, b0 = 0, trace = 0;  // √2T b_0^(1), 2T b_0^(2), b_0^(0) − log 2πT, tr K̂/2T
  double b1_error = 0, b2_error = 0, b0_error = 0, trace_error = 0;  // bootstrap, same units
  double largest_harmonic_z = 0;  // max over j, i of |b_2j^(i)| (dimensionless) / Cramér–Rao σ
  double once_stress = 0, twice_stress = 0;  // Tr τ*/Tr τ, Tr τ**/Tr τ (Fig 5.7)
  bool converged = false;
};

// The analysis of `seeds` isotropic Maxwellian windows with `replicates` bootstrap replicates.
std::vector<SeedResult> maxwellian_results(int seeds, int replicates) {
  std::vector<SeedResult> out;
  const double s = std::sqrt(2.0 * kT);
  for (int seed = 1; seed <= seeds; ++seed) {
    F1Options options;
    options.speed_bins = options.angle_bins = 32;
    options.bootstrap = replicates;
    options.seed = static_cast<std::uint64_t>(seed);
    const WindowResult r = analyse_window(gaussian_window(static_cast<std::uint64_t>(seed), kSnapshots, kPerSnapshot, {kT, 0.0, kT}), options);
    EXPECT_TRUE(r.analysed) << r.warning;
    const SineSeries& b = r.estimate.series;
    const SineSeries& e = r.errors.series;
    SeedResult x{s * b.mean[1], 2.0 * kT * b.mean[2], b.mean[0] - std::log(2.0 * M_PI * kT),
                 r.estimate.direct.trace() / (2.0 * kT), s * e.mean[1], 2.0 * kT * e.mean[2], e.mean[0],
                 r.errors.direct_trace / (2.0 * kT)};
    const std::array<double, 3> unit = {1.0, s, 2.0 * kT}, bound = maxwellian_harmonic_bound_times_root_n();
    for (const auto& amplitude : b.amplitude)
      for (int i = 0; i < 3; ++i)
        x.largest_harmonic_z = std::max(x.largest_harmonic_z, std::abs(unit[i] * amplitude[i]) * std::sqrt(kSamples) / bound[i]);
    x.once_stress = r.estimate.once_integrals.moment.trace() / r.estimate.direct.trace();
    x.twice_stress = r.estimate.twice_integrals.moment.trace() / r.estimate.direct.trace();
    // Analysed: the three fits of the estimate converged (a failed fit skips the window); and so
    // did every replicate's, or the errors would come from fewer.
    x.converged = r.analysed && r.errors.converged_replicates == r.errors.replicates;
    out.push_back(x);
  }
  return out;
}

// The elastic reference of the thesis (§5.2 after (5.29)): 2T b_0^(2) = 1, √2T b_0^(1) = 0,
// b_0^(0) = log 2πT, no harmonics — within the analytic spread.
TEST(F1SamplingVariance, FittedMeansOfAMaxwellianSpreadAsTheCramerRaoBoundAllows) {
  const std::vector<SeedResult> results = maxwellian_results(kSeeds, 0);
  const Eigen::Matrix2d bound = maxwellian_means_bound_times_n() / kSamples;
  const Eigen::Matrix2d inverse = bound.inverse();
  const double sigma_b0 = std::sqrt(bound(1, 1)), sigma_trace = 1.0 / std::sqrt(kSamples);
  double pooled_b = 0, pooled_b0 = 0, pooled_trace = 0, largest_z = 0, largest_harmonic_z = 0;
  for (const SeedResult& r : results) {
    largest_harmonic_z = std::max(largest_harmonic_z, r.largest_harmonic_z);
    // Fig 5.7 on a Maxwellian: the stress of f̃* within 1% and of f̃** within 5% of the direct value.
    // (The thesis's 5%/1% tolerances on h* are not asserted: at the 400 samples below which they
    // are not checked, counting noise alone is 5%.)
    EXPECT_NEAR(r.once_stress, 1.0, 0.01);
    EXPECT_NEAR(r.twice_stress, 1.0, 0.05);
    EXPECT_TRUE(r.converged);
    const Eigen::Vector2d x{r.b1, r.b2 - 1.0};
    pooled_b += x.dot(inverse * x);
    pooled_b0 += r.b0 * r.b0 / (sigma_b0 * sigma_b0);
    pooled_trace += (r.trace - 1.0) * (r.trace - 1.0) / (sigma_trace * sigma_trace);
    for (const double z : {r.b1 / std::sqrt(bound(0, 0)), (r.b2 - 1.0) / std::sqrt(bound(1, 1)), r.b0 / sigma_b0,
                           (r.trace - 1.0) / sigma_trace})
      largest_z = std::max(largest_z, std::abs(z));
  }
  const double seeds = static_cast<double>(results.size());
  std::printf("isotropic Maxwellian, %g seeds of %g samples: Cramér–Rao σ(√2T b0^(1)) = %.5f, σ(2T b0^(2)) = σ(b0^(0)) = "
              "%.5f; variance / bound: (b0^(1), b0^(2)) %.3f, b0^(0) %.3f; direct tr K̂: variance / exact %.3f; largest |z| %.2f; "
              "largest harmonic amplitude %.2f σ\n",
              seeds, kSamples, std::sqrt(bound(0, 0)), sigma_b0, pooled_b / (2.0 * seeds), pooled_b0 / seeds,
              pooled_trace / seeds, largest_z, largest_harmonic_z);
  EXPECT_LT(largest_z, 4.5);
  EXPECT_LT(largest_harmonic_z, 5.0);
  // Never below the bound; within 1.5 times it.
  EXPECT_GT(pooled_b, chi_square_quantile(2.0 * seeds, -kNormal9995));
  EXPECT_LT(pooled_b, 1.5 * chi_square_quantile(2.0 * seeds, kNormal9995));
  EXPECT_GT(pooled_b0, chi_square_quantile(seeds, -kNormal9995));
  EXPECT_LT(pooled_b0, 1.5 * chi_square_quantile(seeds, kNormal9995));
  // The direct moment is a plain mean: exactly its variance.
  EXPECT_GT(pooled_trace, chi_square_quantile(seeds, -kNormal9995));
  EXPECT_LT(pooled_trace, chi_square_quantile(seeds, kNormal9995));
}

TEST(F1SamplingVariance, BootstrapErrorsAgreeWithTheAnalyticSpread) {
  const std::vector<SeedResult> results = maxwellian_results(kBootstrapSeeds, kReplicates);
  const Eigen::Matrix2d bound = maxwellian_means_bound_times_n() / kSamples;
  const double ideal = (kSnapshots - 1.0) / kSnapshots;  // bootstrap variance / sampling variance
  const double dof_per_seed = 2.0 / (2.0 / (kReplicates - 1.0) + 2.0 / (kSnapshots - 1.0));
  const double dof = dof_per_seed * kBootstrapSeeds;
  struct Quantity {
    const char* name;
    double variance;  // analytic: exact for the trace, the Cramér–Rao bound for the fitted means
    bool exact;
    double SeedResult::*error;
  };
  for (const Quantity q : {Quantity{"sqrt(2T) b0^(1)", bound(0, 0), false, &SeedResult::b1_error},
                           Quantity{"2T b0^(2)", bound(1, 1), false, &SeedResult::b2_error},
                           Quantity{"b0^(0)", bound(1, 1), false, &SeedResult::b0_error},
                           Quantity{"tr K/2T", 1.0 / kSamples, true, &SeedResult::trace_error}}) {
    double pooled = 0.0;
    for (int k = 0; k < kBootstrapSeeds; ++k) {
      const double error = results[static_cast<std::size_t>(k)].*q.error;
      pooled += dof_per_seed * error * error / (ideal * q.variance);
    }
    const double low = chi_square_quantile(dof, -kNormal9995), high = chi_square_quantile(dof, kNormal9995);
    std::printf("bootstrap (%d seeds × %d replicates, %.1f dof): %s error / analytic σ = %.3f (χ² %.1f, 99.9%% range %.1f–%.1f%s)\n",
                kBootstrapSeeds, kReplicates, dof, q.name, std::sqrt(pooled / dof * ideal), pooled, low, high,
                q.exact ? "" : ", bound ×1.5 above");
    EXPECT_GT(pooled, low) << q.name;
    EXPECT_LT(pooled, (q.exact ? 1.0 : 1.5) * high) << q.name;
  }
}

}  // namespace
}  // namespace granule::distribution
