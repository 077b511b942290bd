#include "spectra/gridding_kernel.hpp"

#include <cmath>
#include <numbers>

namespace granule::spectra {

namespace {

constexpr int kQuadratureNodes = 64;  // on [−1, 1]; Φ is converged to round-off for widths ≤ 16

// Gauss–Legendre nodes and weights on [−1, 1] by Newton iteration on P_n (Numerical Recipes, gauleg).
void gauss_legendre(int n, std::vector<double>& nodes, std::vector<double>& weights) {
  nodes.assign(static_cast<std::size_t>(n), 0.0);
  weights.assign(static_cast<std::size_t>(n), 0.0);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double z = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double derivative = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = 0.0;
      for (int k = 1; k <= n; ++k) {
        const double p2 = p1;
        p1 = p0;
        p0 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p2) / k;
      }
      derivative = n * (z * p0 - p1) / (z * z - 1.0);
      const double step = p0 / derivative;
      z -= step;
      if (std::abs(step) < 1e-16) break;
    }
    const double w = 2.0 / ((1.0 - z * z) * derivative * derivative);
    nodes[static_cast<std::size_t>(i)] = -z;
    nodes[static_cast<std::size_t>(n - 1 - i)] = z;
    weights[static_cast<std::size_t>(i)] = w;
    weights[static_cast<std::size_t>(n - 1 - i)] = w;
  }
}

}  // namespace

GriddingKernel::GriddingKernel(int width) : width_(width), beta_(2.30 * width) {
  gauss_legendre(kQuadratureNodes, nodes_, weights_);
}

double GriddingKernel::value(double z) const {
  const double s = 1.0 - z * z;
  return s > 0.0 ? std::exp(beta_ * (std::sqrt(s) - 1.0)) : 0.0;
}

double GriddingKernel::fourier(double omega) const {
  double sum = 0.0;
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    sum += weights_[i] * value(nodes_[i]) * std::cos(omega * half_width() * nodes_[i]);
  }
  return half_width() * sum;
}

}  // namespace granule::spectra
