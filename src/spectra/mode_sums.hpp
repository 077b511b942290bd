// Sums S(k) = Σ_j w_j exp(i k·r_j) over particles, at the lattice modes k = l k1 + m k2 with
// |l|, |m| ≤ M (the raw sums behind (3.4)–(3.5); the thesis's 1/2π and m = 1 are applied in
// thesis_transforms.hpp).  Several weight arrays share one pass over the positions.
#pragma once

#include <complex>
#include <cstddef>
#include <span>
#include <vector>

namespace granule::spectra {

// The (2M+1)² modes |l|, |m| ≤ M, stored row by row in m: index = (m + M)(2M + 1) + (l + M).
struct ModeGrid {
  int max_mode = 0;  // M

  int side() const { return 2 * max_mode + 1; }
  std::size_t count() const { return static_cast<std::size_t>(side()) * static_cast<std::size_t>(side()); }
  std::size_t index(int l, int m) const {
    return static_cast<std::size_t>(m + max_mode) * static_cast<std::size_t>(side()) + static_cast<std::size_t>(l + max_mode);
  }
};

using ModeValues = std::vector<std::complex<double>>;  // one value per mode, ModeGrid order

// Positions inside the box (lab frame) and one weight array per transformed field; an empty weight
// span means unit weight (the mass density of unit-mass particles).
struct WeightedPoints {
  std::span<const double> x, y;
  std::vector<std::span<const double>> weights;

  std::size_t size() const { return x.size(); }
  double weight(std::size_t field, std::size_t j) const { return weights[field].empty() ? 1.0 : weights[field][j]; }
};

}  // namespace granule::spectra
