// What the thesis reads off the collision statistics: the cumulative impact-parameter
// distribution minus the uniform law, B(b) − b/σ (3.21, Fig 3.31); and for free paths the
// cumulative L(l, α) (3.23), its fit (3.24) (α₀ of the angular part, l̄ of the radial part), and
// the magnitude distribution 𝒫(l) against the matched form (3.36) and the plain exponential.
//
// Normalised, (3.36) is 𝒫(l) = exp(−l/l₀)/√(π l₀ l): a Gamma distribution of shape ½ and scale l₀,
// whose cumulative is exactly the radial factor erf(√(l/l̄)) of (3.24) with l̄ = l₀.  Its maximum-
// likelihood l₀ is 2⟨l⟩; the exponential's is ⟨l⟩.  Both are compared with the data by the
// Kolmogorov distance of the cumulative forms at the bin edges.
//
// In 3D (spheres) the impact-parameter variable is (b/σ)², uniform under molecular chaos, so the
// same B − uniform applies; the free-path angle is cos θ (free_paths.hpp), whose isotropic law is
// uniform on [−1, 1]: no α₀ is fitted, the angular cumulative is compared with (1 + cos θ)/2.
#pragma once

#include <vector>

#include "observers/free_paths.hpp"
#include "analysis/histogram.hpp"

namespace granule {

struct ImpactParameterSummary {
  double samples = 0.0;
  std::vector<double> density;                   // β(b/σ), normalised to unit integral over [0, 1]
  std::vector<double> cumulative_minus_uniform;  // B(b) − b/σ at the upper bin edges
  double ks_uniform = 0.0;                       // max |B(b) − b/σ| over the bin edges
};

ImpactParameterSummary summarize_impact_parameters(const std::vector<double>& counts, const UniformBins& bins);

struct FreePathSummary {
  double paths = 0.0;
  double mean_length = 0.0;  // ⟨l⟩ over all paths (exact sums, not binned)
  double mean_speed = 0.0;
  // (3.24), angular part: α₀ fitted to L(l_max, α) (normalised to 0 at α = 0 and 1 at 2π) over
  // [10⁻⁴, 10⁴] (10⁴: isotropic); NaN when no path is shorter than l_max.
  double alpha0 = 0.0;
  double alpha0_rms = 0.0;  // rms residual of that fit
  // Kolmogorov distance of L(l_max, angle), normalised, from the isotropic law: α/2π in 2D,
  // (1 + cos θ)/2 in 3D; NaN when no path is shorter than l_max.
  double ks_isotropic = 0.0;
  // (3.24), radial part: l̄ fitted to L(l, 2π) = erf(√(l/l̄)) by least squares (the thesis's way);
  // NaN when the best l̄ lies at an end of the searched range [10⁻³, 10³] ⟨l⟩ (no scale fits).
  double lbar = 0.0;
  double lbar_rms = 0.0;
  double l0_matched = 0.0;          // maximum-likelihood l₀ of (3.36): 2⟨l⟩
  double lambda_exponential = 0.0;  // maximum-likelihood decay length of exp(−l/λ)/λ: ⟨l⟩
  double ks_matched = 0.0;
  double ks_exponential = 0.0;
  std::vector<double> magnitude_density;    // 𝒫(l) per length bin (normalised over all paths)
  std::vector<double> matched_density;      // (3.36) with l₀_matched, averaged over each bin
  std::vector<double> exponential_density;  // exp(−l/λ)/λ, averaged over each bin
  std::vector<double> length_cumulative;    // L(l, 2π) at the upper length-bin edges
  std::vector<double> angular_cumulative;   // L(l_max, α) at the upper angle-bin edges, normalised
  std::vector<double> angular_fit;          // 2D: the fitted angular part of (3.24) there; 3D: (1 + cos θ)/2
  std::vector<double> cumulative;           // L(l, α) of (3.23): length_bins × angle_bins, upper edges
};

// `dimension` 2: the thesis's (3.24) fit of α₀; 3: α₀ and its rms are NaN (header).
FreePathSummary summarize_free_paths(const PathHistogram& histogram, const UniformBins& length_bins,
                                     const UniformBins& angle_bins, int dimension = 2);

// The angular part of (3.24), normalised to run from 0 at α = 0 to 1 at α = 2π.
double free_path_angular_cumulative(double alpha, double alpha0);

}  // namespace granule
