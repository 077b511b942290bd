#include "distribution/cumulative_function.hpp"

#include <cmath>

namespace granule::distribution {

double PolarGrid::angle_edge(int l) const { return 2.0 * M_PI * l / angle_bins; }

Eigen::MatrixXd polar_counts(const double* speed, const double* angle, std::size_t samples, const PolarGrid& grid) {
  Eigen::MatrixXd counts = Eigen::MatrixXd::Zero(grid.speed_bins, grid.angle_bins);
  for (std::size_t i = 0; i < samples; ++i) {
    if (!(speed[i] < grid.speed_max)) continue;
    const int k = static_cast<int>(speed[i] / grid.speed_max * grid.speed_bins);
    int l = static_cast<int>(angle[i] / (2.0 * M_PI) * grid.angle_bins);
    l = l < 0 ? 0 : (l >= grid.angle_bins ? grid.angle_bins - 1 : l);
    counts(k < grid.speed_bins ? k : grid.speed_bins - 1, l) += 1.0;
  }
  return counts;
}

CumulativeFunction cumulative_function(const Eigen::MatrixXd& counts, double total, const PolarGrid& grid) {
  const int nv = grid.speed_bins, nt = grid.angle_bins;
  CumulativeFunction c;
  c.grid = grid;
  c.total = total;
  c.counts = counts;
  // (5.11) by counting: a two-dimensional running sum of the counts, exact in double precision
  // (whole numbers below 2⁵³), then normalised by all samples (5.12).  Dividing exact sums keeps h
  // monotone to the last bit; running sums of the fractions would not (round-off of 1e-17).
  Eigen::MatrixXd below = Eigen::MatrixXd::Zero(nv + 1, nt + 1);
  for (int k = 1; k <= nv; ++k)
    for (int l = 1; l <= nt; ++l)
      below(k, l) = below(k - 1, l) + below(k, l - 1) - below(k - 1, l - 1) + counts(k - 1, l - 1);
  c.h = below / total;
  c.phi = c.h.col(nt) / (2.0 * M_PI);
  // (5.19): ψ = h − (1/2π)∫h dθ + (π − θ)φ, i.e. the zero-mean part of the periodic function
  // h − θφ.  Its θ-average over the uniform edges θ_0 … θ_{n−1} is exact for a trigonometric
  // polynomial of degree < n (the trapezoid rule on a period).
  c.psi.resize(nv + 1, nt);
  for (int k = 0; k <= nv; ++k) {
    double mean = 0.0;
    for (int l = 0; l < nt; ++l) {
      c.psi(k, l) = c.h(k, l) - grid.angle_edge(l) * c.phi(k);
      mean += c.psi(k, l);
    }
    c.psi.row(k).array() -= mean / nt;
  }
  return c;
}

}  // namespace granule::distribution
