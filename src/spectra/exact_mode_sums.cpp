#include "spectra/exact_mode_sums.hpp"

#include <cmath>
#include <stdexcept>

namespace granule::spectra {

std::vector<ModeValues> exact_mode_sums(const WeightedPoints& points, const ReciprocalLattice& lattice, int max_mode) {
  const ModeGrid modes{max_mode, lattice.dimension};
  const bool depth = lattice.dimension == 3;
  if (depth && points.z.size() != points.size()) throw std::invalid_argument("exact_mode_sums: 3D lattice without z");
  const std::size_t fields = points.weights.size();
  std::vector<ModeValues> sums(fields, ModeValues(modes.count()));
  for (std::size_t j = 0; j < points.size(); ++j) {
    for (int n = -modes.max_mode_z(); n <= modes.max_mode_z(); ++n) {
      for (int m = -max_mode; m <= max_mode; ++m) {
        for (int l = -max_mode; l <= max_mode; ++l) {
          const double phase = depth ? lattice.phase(l, m, n, points.x[j], points.y[j], points.z[j])
                                     : lattice.phase(l, m, points.x[j], points.y[j]);
          const std::complex<double> wave(std::cos(phase), std::sin(phase));
          const std::size_t i = modes.index(l, m, n);
          for (std::size_t f = 0; f < fields; ++f) sums[f][i] += points.weight(f, j) * wave;
        }
      }
    }
  }
  return sums;
}

}  // namespace granule::spectra
