// The single-particle velocity distribution of one (ρ, T) window by the cumulative sampling
// algorithm of thesis §5.2, from the collected fluctuating velocities to the Appendix B
// coefficients, with statistical errors from a bootstrap over snapshots (each replicate redoes
// every fit on a resampled set of snapshots).
//
// Internally speeds are scaled by s = √(2T), T = ½⟨v'²⟩ of the window's samples, so that all
// fits see numbers of order one; results are reported in the units of the snapshots.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "distribution/cumulative_function.hpp"
#include "distribution/once_fitted.hpp"
#include "distribution/twice_fitted.hpp"
#include "distribution/velocity_moments.hpp"
#include "distribution/window_sampling.hpp"

namespace granule::distribution {

struct F1Options {
  int speed_bins = 64;
  int angle_bins = 64;           // multiple of 8
  double speed_max = 0.0;        // last speed edge of the polar bins; 0: the largest sampled speed
  double fit_quantile = 0.999;   // the twice fit (5.27) uses speeds up to this quantile of |v'|
  int fit_speeds = 64;           // points per angle in the twice fit
  int bootstrap = 20;            // replicates (0: no error estimate)
  std::uint64_t seed = 1;        // of the bootstrap
  std::size_t min_samples = 10000;  // fewer samples in a window: warn and skip
};

// The thesis's tolerances for the once-fitted cumulative function (§5.2): 5% at small speeds,
// 1% at large ones.  Deviations |h* − h| are relative to h(v, 2π), at points with at least
// kToleranceMinCount samples below v (fewer carry more than 5% counting noise); 'small' means
// v < √(2T).
inline constexpr double kToleranceSmallSpeed = 0.05;
inline constexpr double kToleranceLargeSpeed = 0.01;
inline constexpr double kToleranceMinCount = 400.0;

struct FitQuality {
  double max_deviation_small_speed = 0.0;
  double max_deviation_large_speed = 0.0;
  bool within_tolerance() const {
    return max_deviation_small_speed <= kToleranceSmallSpeed && max_deviation_large_speed <= kToleranceLargeSpeed;
  }
};

// One realisation of the whole procedure (the estimate, or one bootstrap replicate).
struct F1Estimate {
  CumulativeFunction cumulative;  // scaled speeds
  OnceFitted once;                // scaled speeds
  AngularCoefficients angular;    // b^(i)(θ) of (5.27), scaled speeds
  SineSeries series;              // (5.29) in the snapshots' units
  SecondMoment direct;            // (5.31) per particle
  PlaneIntegrals once_integrals;  // (5.30) with f̃* (speeds ≤ speed_max)
  PlaneIntegrals twice_integrals; // (5.30) with f̃** (speeds ≤ 2 speed_max)
  double ratio = 0.0;             // (b_0^(1))² / b_0^(2)  (Fig 5.9)
};

// The numbers of one converged bootstrap replicate that the errors summarise, kept so that plots can
// draw percentile intervals (robust to a few wild replicates) instead of standard deviations.
struct ReplicateNumbers {
  SineSeries series;
  double direct_trace = 0.0, once_trace = 0.0, twice_trace = 0.0, ratio = 0.0;
};

// Standard deviations over the bootstrap replicates, same layout as the estimate's numbers.
struct F1Errors {
  SineSeries series;  // mean, amplitude, phase hold standard deviations
  double direct_trace = 0.0, once_trace = 0.0, twice_trace = 0.0, ratio = 0.0;
  int replicates = 0;
  int converged_replicates = 0;  // replicates whose three fits all converged: the only ones used
  std::vector<ReplicateNumbers> replicate_numbers;  // one per converged replicate
};

struct WindowResult {
  bool analysed = false;
  std::string warning;             // why the window was skipped: too few samples or failed fits
  ValueWindow density_window, temperature_window;
  std::size_t samples = 0, snapshots = 0;
  double density = 0.0;            // ρ = N_{ρ,T}/Ω_{ρ,T} (§5.2, before (5.8))
  double temperature = 0.0;        // ½⟨v'²⟩ of the samples
  double cell_temperature = 0.0;   // mass-weighted mean T(cell) of the selected cells
  double speed_scale = 1.0;        // s = √(2T)
  double speed_max = 0.0;          // of the polar bins (snapshot units)
  double fit_speed_max = 0.0;      // of the twice fit (snapshot units)
  F1Estimate estimate;
  F1Errors errors;
  FitQuality quality;
  JenkinsRichman jenkins_richman;  // from the measured K = direct second moment

  // The distributions in the snapshots' units (speed v, angle θ): f̃*, f̃**.
  double once_density(double v, double theta) const;
  double twice_density(double v, double theta) const;
};

// Steps 3–8 of the procedure on given polar counts (speeds in units of `scale`, results in the
// snapshots' units): h, the once fit with the harmonics `resolved` (chosen from the counts when not
// given), the twice fit up to `fit_speed_max`, the sine series, the plane integrals.  `direct`
// needs the samples themselves and is left empty.  Counts need not be whole numbers: on exact bin
// probabilities times N this is the procedure's infinite-sample limit.
F1Estimate fit_counts(const Eigen::MatrixXd& counts, double total, const PolarGrid& grid, double fit_speed_max,
                      double scale, const F1Options& options, const std::optional<HarmonicSet>& resolved);

// Skips the window (analysed = false, a warning saying why) when it has too few samples or when a
// fit of the estimate fails: no number of a failed fit is reported.  The bootstrap errors come from
// the replicates whose fits all converged (errors.converged_replicates of errors.replicates).
WindowResult analyse_window(const WindowSamples& samples, const F1Options& options);

// The bytes an f1 analysis of `windows` windows over `snapshots` snapshots of `particles` grains
// holds at its peak, for the memory check made before it samples: every window's velocities (two
// doubles per sample; a grain is a sample of each window its cell falls in, at most once per
// snapshot and window) and, for the window analysed, its polar counts binned once per snapshot
// (speed_bins × angle_bins doubles each, kept for the bootstrap) and the cumulative function's
// few arrays of that size.
double f1_analysis_bytes(std::size_t particles, std::size_t snapshots, std::size_t windows, const F1Options& options);

}  // namespace granule::distribution
