#include "spectra/fast_mode_sums.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
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

// The window of one particle along one axis: the first grid point it covers and its w values there.
struct AxisWindow {
  int first = 0;
  std::vector<double> values;

  AxisWindow(const GriddingKernel& kernel, double u) : values(static_cast<std::size_t>(kernel.width())) {
    const double half = kernel.half_width();
    first = static_cast<int>(std::ceil(u - half));
    for (int a = 0; a < kernel.width(); ++a) values[static_cast<std::size_t>(a)] = kernel.value((first + a - u) / half);
  }
};

// Deposit every particle's weights with the window onto a padded grid (grid point i stored at i + w, so
// that windows crossing the edges need no wrapping in the inner loop), fields interleaved per point.
// 2D only: the padded grid of a 3D box would cost ((n + 2w)/n)³ times the grid itself.
std::vector<double> deposit(const WeightedPoints& points, const ReciprocalLattice& lattice, const GriddingKernel& kernel,
                            int n) {
  const int w = kernel.width();
  const std::size_t fields = points.weights.size();
  const std::size_t stride = static_cast<std::size_t>(n + 2 * w);
  std::vector<double> padded(stride * stride * fields, 0.0);
  std::vector<double> weight(fields);
  for (std::size_t j = 0; j < points.size(); ++j) {
    const AxisWindow along_x(kernel, grid_coordinate(lattice.sheared_abscissa(points.x[j], points.y[j]), lattice.length_x, n));
    const AxisWindow along_y(kernel, grid_coordinate(points.y[j], lattice.length_y, n));
    for (std::size_t f = 0; f < fields; ++f) weight[f] = points.weight(f, j);
    for (int a = 0; a < w; ++a) {
      double* row = &padded[(static_cast<std::size_t>(along_y.first + a + w) * stride +
                             static_cast<std::size_t>(along_x.first + w)) * fields];
      const double wy = along_y.values[static_cast<std::size_t>(a)];
      for (std::size_t b = 0; b < static_cast<std::size_t>(w); ++b) {
        const double v = wy * along_x.values[b];
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
  // Each grid allocated in place: copies of a zeroed prototype would hold one grid more at the peak.
  std::vector<std::vector<Complex>> grids((fields + 1) / 2);
  for (std::vector<Complex>& grid : grids) grid.resize(cells);
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

// 3D: deposit the fields `pair` × 2 and × 2 + 1 (real and imaginary part, as in 2D) straight into one
// complex n³ grid (x fastest), the window's grid points wrapped periodically; positions at
// (ξ mod L_x, y, z mod L_z).  One pair at a time keeps a single n³ grid alive.
std::vector<Complex> deposit_pair_3d(const WeightedPoints& points, const ReciprocalLattice& lattice,
                                     const GriddingKernel& kernel, int n, std::size_t pair) {
  const int w = kernel.width();
  const std::size_t fields = points.weights.size();
  const auto side = static_cast<std::size_t>(n);
  std::vector<Complex> grid(side * side * side);
  const auto wrapped = [n](int i) { return static_cast<std::size_t>((i % n + n) % n); };
  std::vector<std::size_t> column(static_cast<std::size_t>(w));
  for (std::size_t j = 0; j < points.size(); ++j) {
    const AxisWindow along_x(kernel, grid_coordinate(lattice.sheared_abscissa(points.x[j], points.y[j]), lattice.length_x, n));
    const AxisWindow along_y(kernel, grid_coordinate(points.y[j], lattice.length_y, n));
    const AxisWindow along_z(kernel, grid_coordinate(points.z[j], lattice.length_z, n));
    const Complex weight(points.weight(2 * pair, j), 2 * pair + 1 < fields ? points.weight(2 * pair + 1, j) : 0.0);
    for (int b = 0; b < w; ++b) column[static_cast<std::size_t>(b)] = wrapped(along_x.first + b);
    for (int c = 0; c < w; ++c) {
      const std::size_t plane = wrapped(along_z.first + c) * side;
      for (int a = 0; a < w; ++a) {
        Complex* row = &grid[(plane + wrapped(along_y.first + a)) * side];
        const double wzy = along_z.values[static_cast<std::size_t>(c)] * along_y.values[static_cast<std::size_t>(a)];
        for (std::size_t b = 0; b < static_cast<std::size_t>(w); ++b) row[column[b]] += (wzy * along_x.values[b]) * weight;
      }
    }
  }
  return grid;
}

// B(l, m) = Σ_grid b e^{+i(l gx + m gy) 2π/n} for |l|, |m| ≤ M of one n × n plane (overwritten): rows
// first, then only the 2M+1 columns that are kept.
ModeValues transform_plane(Complex* grid, int n, int max_mode) {
  Eigen::FFT<double> fft;
  fft.SetFlag(Eigen::FFT<double>::Unscaled);
  std::vector<Complex> buffer(static_cast<std::size_t>(n)), column(static_cast<std::size_t>(n));
  for (int row = 0; row < n; ++row) {
    Complex* data = grid + static_cast<std::size_t>(row) * static_cast<std::size_t>(n);
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

// B(l, m, n') of an n³ grid (planes of constant z): each plane as in 2D, then the kept (l, m) along z.
ModeValues transform_grid_3d(std::vector<Complex>& grid, int n, int max_mode) {
  const auto side = static_cast<std::size_t>(n);
  std::vector<ModeValues> planes;
  for (std::size_t z = 0; z < side; ++z) planes.push_back(transform_plane(&grid[z * side * side], n, max_mode));
  Eigen::FFT<double> fft;
  fft.SetFlag(Eigen::FFT<double>::Unscaled);
  const ModeGrid plane_modes{max_mode, 2}, modes{max_mode, 3};
  std::vector<Complex> line(side), transformed(side);
  ModeValues out(modes.count());
  for (std::size_t i = 0; i < plane_modes.count(); ++i) {
    for (std::size_t z = 0; z < side; ++z) line[z] = planes[z][i];
    fft.inv(transformed.data(), line.data(), n);
    for (int k = -max_mode; k <= max_mode; ++k) {
      out[static_cast<std::size_t>(k + max_mode) * plane_modes.count() + i] = transformed[static_cast<std::size_t>((k + n) % n)];
    }
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
  const bool depth = lattice.dimension == 3;
  if (depth && points.z.size() != points.size()) throw std::invalid_argument("fast_mode_sums: 3D lattice without z");
  // 2D: every pair of fields gridded in one pass; 3D: one pair at a time (below).
  std::vector<std::vector<Complex>> planes;
  if (!depth) planes = fold_into_complex_grids(deposit(points, lattice, kernel, n), fields, n, kernel.width());

  // The window multiplied mode (l, m, n') by Φ(2πl/n) Φ(2πm/n) (Φ(2πn'/n)): divide it out.
  const ModeGrid modes{max_mode, lattice.dimension};
  std::vector<double> window(static_cast<std::size_t>(modes.side()));
  for (int l = -max_mode; l <= max_mode; ++l) {
    window[static_cast<std::size_t>(l + max_mode)] = kernel.fourier(2.0 * std::numbers::pi * l / n);
  }
  const auto window_at = [&](int l) { return window[static_cast<std::size_t>(l + max_mode)]; };
  std::vector<ModeValues> sums(fields, ModeValues(modes.count()));
  for (std::size_t g = 0; g < (fields + 1) / 2; ++g) {
    ModeValues packed;
    if (depth) {
      std::vector<Complex> grid = deposit_pair_3d(points, lattice, kernel, n, g);
      packed = transform_grid_3d(grid, n, max_mode);
    } else {
      packed = transform_plane(planes[g].data(), n, max_mode);
    }
    for (int k = -modes.max_mode_z(); k <= modes.max_mode_z(); ++k) {
      const double window_z = depth ? window_at(k) : 1.0;  // ×1 leaves the 2D products bit for bit
      for (int m = -max_mode; m <= max_mode; ++m) {
        for (int l = -max_mode; l <= max_mode; ++l) {
          const std::size_t i = modes.index(l, m, k);
          const Complex b = packed[i];
          const Complex b_mirror = std::conj(packed[modes.index(-l, -m, -k)]);
          const double scale = 1.0 / (window_at(l) * window_at(m) * window_z);
          sums[2 * g][i] = 0.5 * (b + b_mirror) * scale;
          if (2 * g + 1 < fields) sums[2 * g + 1][i] = Complex(0.0, -0.5) * (b - b_mirror) * scale;
        }
      }
    }
  }
  return sums;
}

}  // namespace granule::spectra
