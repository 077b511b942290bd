#include "spectra/spectral_transforms.hpp"

#include <Eigen/Eigenvalues>
#include <array>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "spectra/exact_mode_sums.hpp"

namespace granule::spectra {

DensityMomentumTransforms transform_fields(const ParticleState& state, const ShearFrame& frame,
                                           const ReciprocalLattice& lattice, const TransformOptions& options) {
  if (state.dimension != lattice.dimension) {
    throw std::invalid_argument("transform_fields: the configuration and the lattice differ in dimension");
  }
  const int d = state.dimension;
  DensityMomentumTransforms out{lattice, ModeGrid{options.max_mode, d}, {}, {}, {}};
  // Velocities of the momentum fields: v_x or v_x − u(y) (3.17), v_y (, v_z); times m_j when polydisperse.
  std::vector<std::vector<double>> velocity(static_cast<std::size_t>(d));
  for (int axis = 0; axis < d; ++axis) {
    const bool peculiar = axis == 0 && options.subtract_shear_profile;
    if (!peculiar && state.mass.empty()) continue;  // the state's own array serves
    auto& v = velocity[static_cast<std::size_t>(axis)];
    v = state.velocity(axis);
    for (std::size_t j = 0; j < state.size(); ++j) {
      if (peculiar) v[j] -= frame.mean_flow(state.y[j]);
      if (!state.mass.empty()) v[j] *= state.mass[j];
    }
  }
  WeightedPoints points{state.x, state.y, {state.mass}, d == 3 ? std::span<const double>(state.z) : std::span<const double>()};
  for (int axis = 0; axis < d; ++axis) {
    const auto& own = velocity[static_cast<std::size_t>(axis)];
    points.weights.push_back(own.empty() ? std::span<const double>(state.velocity(axis)) : std::span<const double>(own));
  }
  std::vector<ModeValues> sums = options.method == SpectralMethod::exact
                                     ? exact_mode_sums(points, out.lattice, options.max_mode)
                                     : fast_mode_sums(points, out.lattice, options.max_mode, options.gridding);
  // The thesis's prefactor 1/2π of (3.4)–(3.5).
  constexpr double kInverseFourPiSquared = 0.25 / (std::numbers::pi * std::numbers::pi);
  for (ModeValues& values : sums) {
    for (auto& value : values) value *= 0.5 / std::numbers::pi;
  }
  std::array<std::array<double, 3>, 3> covariance = {};
  for (std::size_t j = 0; j < state.size(); ++j) {
    const double w = points.weight(0, j);
    out.ideal_density += w * w * kInverseFourPiSquared;
    for (std::size_t a = 1; a < points.weights.size(); ++a) {
      for (std::size_t b = 1; b < points.weights.size(); ++b) {
        covariance[a - 1][b - 1] += points.weight(a, j) * points.weight(b, j) * kInverseFourPiSquared;
      }
    }
  }
  double trace = 0.0, squares = 0.0;
  for (std::size_t a = 0; a < 3; ++a) {
    out.ideal_momentum_axes[a] = covariance[a][a];
    trace += covariance[a][a];
    for (std::size_t b = 0; b < 3; ++b) squares += covariance[a][b] * covariance[a][b];
  }
  if (trace > 0.0) {
    out.ideal_momentum_spread = std::sqrt(squares) / trace;
    Eigen::Matrix3d normalized;
    for (std::size_t a = 0; a < 3; ++a) {
      for (std::size_t b = 0; b < 3; ++b) {
        normalized(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b)) = covariance[a][b] / trace;
      }
    }
    const Eigen::Vector3d shares = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(normalized, Eigen::EigenvaluesOnly).eigenvalues();
    for (std::size_t a = 0; a < 3; ++a) out.ideal_momentum_shares[a] = std::max(0.0, shares(static_cast<Eigen::Index>(a)));
  }
  out.density = std::move(sums[0]);
  out.momentum_x = std::move(sums[1]);
  out.momentum_y = std::move(sums[2]);
  if (d == 3) out.momentum_z = std::move(sums[3]);
  return out;
}

DensityMomentumTransforms transform_fields(const ParticleState& state, const ShearFrame& frame, double shear_offset,
                                           const TransformOptions& options) {
  return transform_fields(state, frame, lattice_for_frame(frame, shear_offset), options);
}

}  // namespace granule::spectra
