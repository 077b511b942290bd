#include "spectra/spectra_memory.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

#include "spectra/fast_mode_sums.hpp"
#include "spectra/mode_sums.hpp"

namespace granule::spectra {

namespace {

constexpr double kReal = sizeof(double);
constexpr double kComplex = sizeof(std::complex<double>);

}  // namespace

double spectra_bytes(std::size_t particles, int dimension, const TransformOptions& options, double annuli) {
  const double d = dimension;
  const double fields = d + 1.0;  // ρ̃ and the d components of p̃
  const double modes = static_cast<double>(ModeGrid{options.max_mode, dimension}.count());
  const double side = 2.0 * options.max_mode + 1.0;  // modes along an axis
  // transform_fields' weighted velocities (times the masses, or less the shear profile): d arrays
  // of N, alive until the sums are done.
  const double weights = kReal * d * static_cast<double>(particles);
  // The mode sums, one complex value per mode and field, alive from the start of the sums to the
  // end of power_maps.
  const double sums = kComplex * fields * modes;
  double transform = sums;  // the exact method adds nothing to them
  if (options.method == SpectralMethod::fast) {
    const double n = fft_grid_size(options.max_mode, options.gridding);
    if (dimension == 3) {
      // A pair of fields at a time: the complex n³ grid, the kept modes of its n planes and the
      // pair's packed modes (fast_mode_sums.cpp, transform_grid_3d), all beside the sums.
      transform = sums + kComplex * (n * n * n + n * side * side + modes);
    } else {
      // The complex n² grids, one per pair of fields, live through the sums.  First the padded real
      // grid of every field is folded into them; then the sums and one pair's packed modes.
      const double padded = n + 2.0 * options.gridding.kernel_width;
      const double planes = kComplex * std::ceil(fields / 2.0) * n * n;
      transform = planes + std::max(kReal * fields * padded * padded, sums + kComplex * modes);
    }
  }
  // power_maps: beside the sums, the maps k_x, k_y (, k_z), R, P_x, P_y (, P_z) and P.
  const double maps = kReal * (2.0 * d + 2.0) * modes;
  // annulus_sums: beside the maps, per ring its centre, its two mode counts and the sums of R, P_x,
  // P_y (, P_z) and P; as much again for what the caller derives from them (NumPy copies, the shell
  // averages of the spectra file).
  const double rings = 2.0 * kReal * (d + 5.0) * annuli;
  return std::max({weights + transform, sums + maps, maps + rings});
}

}  // namespace granule::spectra
