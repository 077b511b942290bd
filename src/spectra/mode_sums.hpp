// Sums S(k) = Σ_j w_j exp(i k·r_j) over particles, at the lattice modes k = l k1 + m k2 (+ n k3 in
// 3D) with |l|, |m| (, |n|) ≤ M (the raw sums behind (3.4)–(3.5); the thesis's 1/2π is applied in
// spectral_transforms.hpp).  Several weight arrays share one pass over the positions.
#pragma once

#include <complex>
#include <cstddef>
#include <span>
#include <vector>

namespace granule::spectra {

// The (2M+1)^d modes |l|, |m| (, |n|) ≤ M, l fastest: index = ((n + M_z)(2M + 1) + m + M)(2M + 1) + l + M
// with M_z = M in 3D and 0 in 2D (where n = 0 and the index is (m + M)(2M + 1) + l + M).
struct ModeGrid {
  int max_mode = 0;   // M
  int dimension = 2;  // d: 2 or 3

  int side() const { return 2 * max_mode + 1; }
  int max_mode_z() const { return dimension == 3 ? max_mode : 0; }
  int side_z() const { return 2 * max_mode_z() + 1; }
  std::size_t plane_count() const { return static_cast<std::size_t>(side()) * static_cast<std::size_t>(side()); }
  std::size_t count() const { return plane_count() * static_cast<std::size_t>(side_z()); }
  std::size_t index(int l, int m, int n = 0) const {
    return (static_cast<std::size_t>(n + max_mode_z()) * static_cast<std::size_t>(side()) +
            static_cast<std::size_t>(m + max_mode)) * static_cast<std::size_t>(side()) + static_cast<std::size_t>(l + max_mode);
  }
};

using ModeValues = std::vector<std::complex<double>>;  // one value per mode, ModeGrid order

// Positions inside the box (lab frame) and one weight array per transformed field; an empty weight
// span means unit weight (the mass density of unit-mass particles).  z is read only in 3D.
struct WeightedPoints {
  std::span<const double> x, y;
  std::vector<std::span<const double>> weights;
  std::span<const double> z = {};

  std::size_t size() const { return x.size(); }
  double weight(std::size_t field, std::size_t j) const { return weights[field].empty() ? 1.0 : weights[field][j]; }
};

}  // namespace granule::spectra
