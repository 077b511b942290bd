#include "distribution/harmonic_significance.hpp"

#include <Eigen/Cholesky>
#include <cmath>

namespace granule::distribution {

std::vector<double> harmonic_chi_square(const CumulativeFunction& c, int harmonics) {
  const int nv = c.grid.speed_bins, nt = c.grid.angle_bins;
  const double du = c.grid.speed_max / nv, dtheta = 2.0 * M_PI / nt;
  std::vector<double> chi_square(static_cast<std::size_t>(harmonics), 0.0);
  for (int p = 1; p <= harmonics; ++p) {
    Eigen::Matrix<double, 6, 1> score = Eigen::Matrix<double, 6, 1>::Zero();
    Eigen::Matrix<double, 6, 6> covariance = Eigen::Matrix<double, 6, 6>::Zero();
    for (int l = 0; l < nt; ++l) {
      const double angle = 2.0 * p * (l + 0.5) * dtheta;
      const double cosine = std::cos(angle), sine = std::sin(angle);
      for (int k = 0; k < nv; ++k) {
        const double n = c.counts(k, l);
        if (n == 0.0) continue;
        const double u = (k + 0.5) * du;
        Eigen::Matrix<double, 6, 1> x;
        x << cosine, u * cosine, u * u * cosine, sine, u * sine, u * u * sine;
        score += n * x;
        covariance.selfadjointView<Eigen::Lower>().rankUpdate(x, n);
      }
    }
    covariance = covariance.selfadjointView<Eigen::Lower>();
    const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> solver(covariance);
    chi_square[static_cast<std::size_t>(p - 1)] = solver.info() == Eigen::Success ? score.dot(solver.solve(score)) : 0.0;
  }
  return chi_square;
}

}  // namespace granule::distribution
