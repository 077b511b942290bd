// Polar binning of fluctuating velocities and the cumulative distribution function of thesis
// §5.2: h(v, θ) (5.11), its angle-averaged part φ(v) (5.18) and its periodic part ψ(θ, v) (5.19).
// Speeds are in units of a scale s (the analysis uses s = √(2T)); θ is measured from the
// streamwise (x) direction, in [0, 2π).
#pragma once

#include <Eigen/Core>

namespace granule::distribution {

struct PolarGrid {
  int speed_bins = 64;
  int angle_bins = 64;    // a multiple of 8, so that θ = nπ/4 (Fig 5.1) are edges
  double speed_max = 1.0;  // scaled speed of the last edge

  double speed_edge(int k) const { return speed_max * k / speed_bins; }
  double angle_edge(int l) const;
};

// counts(k, l): samples with speed in [u_k, u_{k+1}) and angle in [θ_l, θ_{l+1}).  Speeds at or
// beyond speed_max are not binned; they still count in the normalisation (h(∞, 2π) = 1).
Eigen::MatrixXd polar_counts(const double* speed, const double* angle, std::size_t samples, const PolarGrid& grid);

struct CumulativeFunction {
  PolarGrid grid;
  double total = 0.0;    // number of samples N_{ρ,T}
  Eigen::MatrixXd counts;  // speed_bins × angle_bins, as given
  Eigen::MatrixXd h;     // (speed_bins+1) × (angle_bins+1): h(u_k, θ_l), (5.11)
  Eigen::VectorXd phi;   // (speed_bins+1): φ(u_k) = h(u_k, 2π)/2π, (5.18)
  Eigen::MatrixXd psi;   // (speed_bins+1) × angle_bins: ψ(θ_l, u_k), l < angle_bins, (5.19)
};

// h by counting (the fraction of samples with speed < u_k and angle < θ_l), then φ and ψ.  Counts
// are whole numbers (samples times bootstrap multiplicities), so h is exactly non-decreasing in u
// and θ, and h(u_max, 2π) = 1 exactly when every sample lies below u_max.
CumulativeFunction cumulative_function(const Eigen::MatrixXd& counts, double total, const PolarGrid& grid);

}  // namespace granule::distribution
