#include "spectra/fast_mode_sums.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unsupported/Eigen/FFT>

#include "spectra/gridding_kernel.hpp"

namespace granule::spectra {

namespace {

using Complex = std::complex<double>;

bool has_only_small_factors(int n) {
  for (const int p : {2, 3, 5}) {
    while (n % p == 0) n /= p;
  }
  return n == 1;
}

// Fractional position in [0, 1) of a periodic coordinate, times the grid size.
double grid_coordinate(double coordinate, double period, int n) {
  const double t = coordinate / period;
  return (t - std::floor(t)) * n;
}

// Deposit every particle's weights with the window onto a padded grid (grid point i stored at i + w, so
// that windows crossing the edges need no wrapping in the inner loop), fields interleaved per point.
std::vector<double> deposit(const WeightedPoints& points, const ReciprocalLattice& lattice, const GriddingKernel& kernel,
                            int n) {
  const int w = kernel.width();
  const double half = kernel.half_width();
  const std::size_t fields = points.weights.size();
  const std::size_t stride = static_cast<std::size_t>(n + 2 * w);
  std::vector<double> padded(stride * stride * fields, 0.0);
  std::vector<double> window_x(static_cast<std::size_t>(w)), window_y(static_cast<std::size_t>(w)), weight(fields);
  for (std::size_t j = 0; j < points.size(); ++j) {
    const double ux = grid_coordinate(lattice.sheared_abscissa(points.x[j], points.y[j]), lattice.length_x, n);
    const double uy = grid_coordinate(points.y[j], lattice.length_y, n);
    const int ix0 = static_cast<int>(std::ceil(ux - half));
    const int iy0 = static_cast<int>(std::ceil(uy - half));
    for (int a = 0; a < w; ++a) {
      window_x[static_cast<std::size_t>(a)] = kernel.value((ix0 + a - ux) / half);
      window_y[static_cast<std::size_t>(a)] = kernel.value((iy0 + a - uy) / half);
    }
    for (std::size_t f = 0; f < fields; ++f) weight[f] = points.weight(f, j);
    for (int a = 0; a < w; ++a) {
      double* row = &padded[(static_cast<std::size_t>(iy0 + a + w) * stride + static_cast<std::size_t>(ix0 + w)) * fields];
      const double wy = window_y[static_cast<std::size_t>(a)];
      for (std::size_t b = 0; b < static_cast<std::size_t>(w); ++b) {
        const double v = wy * window_x[b];
        for (std::size_t f = 0; f < fields; ++f) row[b * fields + f] += v * weight[f];
      }
    }
  }
  return padded;
}

// Fold the padding back (periodic images) into complex n × n grids, two real fields per grid
// (field 2g in the real part, 2g+1 in the imaginary part), separated again after the FFT by the
// symmetry S(−k) = S(k)* of sums with real weights.
std::vector<std::vector<Complex>> fold_into_complex_grids(const std::vector<double>& padded, std::size_t fields, int n,
                                                          int w) {
  const std::size_t stride = static_cast<std::size_t>(n + 2 * w);
  const std::size_t cells = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  std::vector<std::vector<Complex>> grids((fields + 1) / 2, std::vector<Complex>(cells));
  for (std::size_t py = 0; py < stride; ++py) {
    const int iy = ((static_cast<int>(py) - w) % n + n) % n;
    for (std::size_t px = 0; px < stride; ++px) {
      const int ix = ((static_cast<int>(px) - w) % n + n) % n;
      const std::size_t cell = static_cast<std::size_t>(iy) * static_cast<std::size_t>(n) + static_cast<std::size_t>(ix);
      const double* values = &padded[(py * stride + px) * fields];
      for (std::size_t f = 0; f < fields; ++f) {
        grids[f / 2][cell] += f % 2 == 0 ? Complex(values[f], 0.0) : Complex(0.0, values[f]);
      }
    }
  }
  return grids;
}

// B(l, m) = Σ_grid b e^{+i(l gx + m gy) 2π/n} for |l|, |m| ≤ M: rows first, then only the 2M+1
// columns that are kept.
ModeValues transform_grid(std::vector<Complex>& grid, int n, int max_mode) {
  Eigen::FFT<double> fft;
  fft.SetFlag(Eigen::FFT<double>::Unscaled);
  std::vector<Complex> buffer(static_cast<std::size_t>(n)), column(static_cast<std::size_t>(n));
  for (int row = 0; row < n; ++row) {
    Complex* data = &grid[static_cast<std::size_t>(row) * static_cast<std::size_t>(n)];
    fft.inv(buffer.data(), data, n);
    std::copy(buffer.begin(), buffer.end(), data);
  }
  const ModeGrid modes{max_mode};
  ModeValues out(modes.count());
  for (int l = -max_mode; l <= max_mode; ++l) {
    const std::size_t c = static_cast<std::size_t>((l + n) % n);
    for (std::size_t row = 0; row < static_cast<std::size_t>(n); ++row) buffer[row] = grid[row * static_cast<std::size_t>(n) + c];
    fft.inv(column.data(), buffer.data(), n);
    for (int m = -max_mode; m <= max_mode; ++m) out[modes.index(l, m)] = column[static_cast<std::size_t>((m + n) % n)];
  }
  return out;
}

}  // namespace

int fft_grid_size(int max_mode, const GriddingOptions& options) {
  int n = std::max(static_cast<int>(std::ceil(options.upsampling * (2 * max_mode + 1))), 2 * options.kernel_width);
  while (!has_only_small_factors(n)) ++n;
  return n;
}

std::vector<ModeValues> fast_mode_sums(const WeightedPoints& points, const ReciprocalLattice& lattice, int max_mode,
                                       const GriddingOptions& options) {
  const GriddingKernel kernel(options.kernel_width);
  const int n = fft_grid_size(max_mode, options);
  const std::size_t fields = points.weights.size();
  std::vector<std::vector<Complex>> grids =
      fold_into_complex_grids(deposit(points, lattice, kernel, n), fields, n, kernel.width());

  // The window multiplied mode (l, m) by Φ(2πl/n) Φ(2πm/n): divide it out.
  const ModeGrid modes{max_mode};
  std::vector<double> window(static_cast<std::size_t>(modes.side()));
  for (int l = -max_mode; l <= max_mode; ++l) {
    window[static_cast<std::size_t>(l + max_mode)] = kernel.fourier(2.0 * std::numbers::pi * l / n);
  }
  std::vector<ModeValues> sums(fields, ModeValues(modes.count()));
  for (std::size_t g = 0; g < grids.size(); ++g) {
    const ModeValues packed = transform_grid(grids[g], n, max_mode);
    for (int m = -max_mode; m <= max_mode; ++m) {
      for (int l = -max_mode; l <= max_mode; ++l) {
        const std::size_t i = modes.index(l, m);
        const Complex b = packed[i];
        const Complex b_mirror = std::conj(packed[modes.index(-l, -m)]);
        const double scale = 1.0 / (window[static_cast<std::size_t>(l + max_mode)] * window[static_cast<std::size_t>(m + max_mode)]);
        sums[2 * g][i] = 0.5 * (b + b_mirror) * scale;
        if (2 * g + 1 < fields) sums[2 * g + 1][i] = Complex(0.0, -0.5) * (b - b_mirror) * scale;
      }
    }
  }
  return sums;
}

}  // namespace granule::spectra
