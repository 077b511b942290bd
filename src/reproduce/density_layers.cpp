#include "reproduce/density_layers.hpp"

#include <cmath>
#include <stdexcept>

#include "io/fields_file.hpp"
#include "io/hdf5_util.hpp"

namespace granule::reproduce {

namespace {

// var(n/M) about 1 of counts whose mean is M.
double relative_variance(const std::vector<double>& counts, double mean) {
  double sum = 0.0;
  for (double n : counts) sum += (n / mean - 1.0) * (n / mean - 1.0);
  return sum / static_cast<double>(counts.size());
}

// The counts summed over the other axes, by the index along `axis` (x fastest, then y, then z).
std::vector<double> profile(const std::vector<double>& counts, const std::array<int, 3>& cells, int axis) {
  std::vector<double> sums(cells[axis], 0.0);
  for (int iz = 0; iz < cells[2]; ++iz) {
    for (int iy = 0; iy < cells[1]; ++iy) {
      for (int ix = 0; ix < cells[0]; ++ix) {
        const int index[3] = {ix, iy, iz};
        sums[index[axis]] += counts[(static_cast<std::size_t>(iz) * cells[1] + iy) * cells[0] + ix];
      }
    }
  }
  return sums;
}

// Standard deviation of the sample variance of k values of variance v (Gaussian): v √(2/(k − 1)).
double variance_noise_sd(double variance, std::size_t k) {
  return k > 1 ? variance * std::sqrt(2.0 / static_cast<double>(k - 1)) : INFINITY;
}

}  // namespace

double DensityLayers::densest_band_centre(int axis, double fraction, bool periodic) const {
  const std::vector<double>& rows = profiles[axis];
  const int n = static_cast<int>(rows.size());
  const int width = std::max(1, static_cast<int>(std::lround(fraction * n)));
  const int starts = periodic ? n : n - width + 1;
  int best_start = 0;
  double best = -1.0;
  for (int start = 0; start < starts; ++start) {
    double mass = 0.0;
    for (int k = 0; k < width; ++k) mass += rows[(start + k) % n];
    if (mass > best) {
      best = mass;
      best_start = start;
    }
  }
  return std::fmod((best_start + 0.5 * width) / n, 1.0);
}

DensityLayers read_density_layers(const std::string& fields_path) {
  const h5::Handle file = h5::open_file(fields_path);
  const FieldGrid grid = read_fields_grid(file.get());
  const std::int64_t frames = h5::complete_frames(file.get());
  if (frames < 2) throw std::runtime_error(fields_path + ": fewer than two frames of fields");
  DensityLayers d;
  d.dimension = grid.dimension;
  d.cells = {grid.nx, grid.ny, grid.nz};
  const std::vector<hsize_t> map = field_map_shape(grid);
  const std::vector<double> first = h5::read_frame_values(file.get(), "/instant/count", 0, map);
  const std::vector<double> last = h5::read_frame_values(file.get(), "/instant/count", static_cast<hsize_t>(frames - 1), map);
  h5::read_frame(file.get(), "/frames/c", H5T_NATIVE_DOUBLE, &d.c_last, static_cast<hsize_t>(frames - 1), {});
  double particles = 0.0;
  for (double n : last) particles += n;
  // The start's structure factor at the cell scale, S = M var(n/M): 1 for an ideal gas, below 1 for
  // hard spheres; the noise of a homogeneous gas in bins of mean count m is then S/m.
  const double cell_mean = particles / static_cast<double>(grid.cells());
  const double structure = cell_mean * relative_variance(first, cell_mean);
  d.map_homogeneous = structure / cell_mean;
  d.map_excess = relative_variance(last, cell_mean) - d.map_homogeneous;
  d.map_noise_sd = variance_noise_sd(structure / cell_mean, grid.cells());
  std::vector<double> flow_sums(static_cast<std::size_t>(grid.ny) * grid.nz, 0.0);
  for (std::size_t cell = 0; cell < last.size(); ++cell) flow_sums[cell / grid.nx] += last[cell];  // x fastest
  const double flow_mean = particles / static_cast<double>(flow_sums.size());
  d.flow_averaged_excess = relative_variance(flow_sums, flow_mean) - structure / flow_mean;
  d.flow_averaged_noise_sd = variance_noise_sd(structure / flow_mean, flow_sums.size());
  const double lengths[3] = {grid.length_x, grid.length_y, grid.length_z};
  for (int axis = 0; axis < 3; ++axis) {
    const std::vector<double> sums = profile(last, d.cells, axis);
    const double bin_mean = particles / static_cast<double>(sums.size());
    d.profile_excess[axis] = relative_variance(sums, bin_mean) - structure / bin_mean;
    d.profile_noise_sd[axis] = variance_noise_sd(structure / bin_mean, sums.size());
    for (std::size_t i = 0; i < sums.size(); ++i) {
      d.profiles[axis].push_back(sums[i] / bin_mean);
      d.positions[axis].push_back((static_cast<double>(i) + 0.5) * lengths[axis] / static_cast<double>(sums.size()));
    }
  }
  return d;
}

}  // namespace granule::reproduce
