#include "reproduce/streamwise_profiles.hpp"

#include <cmath>
#include <filesystem>
#include <limits>

#include "io/fields_file.hpp"
#include "io/hdf5_util.hpp"

namespace granule::reproduce {

StreamwiseProfiles read_streamwise_profiles(const std::string& fields_path, double c_from, double c_to) {
  StreamwiseProfiles p;
  if (!std::filesystem::exists(fields_path)) return p;
  const std::vector<double> c = read_fields_frame_c(fields_path);
  h5::Handle file = h5::open_file(fields_path);
  p.length_y = h5::read_attribute<double>(file.get(), "length_y", H5T_NATIVE_DOUBLE);
  p.y = h5::read_vector(file.get(), "/profiles/y");
  const std::size_t rows = p.y.size();
  const bool with_flux = h5::has_link(file.get(), "/profiles/average_heat_flux_total_y");
  const auto accumulate = [&](const char* name, std::vector<double>& sum, std::size_t k) {
    const std::vector<double> row = h5::read_frame_values(file.get(), name, k, {rows});
    sum.resize(rows, 0.0);
    for (std::size_t r = 0; r < rows; ++r) sum[r] += row[r];
  };
  for (std::size_t k = 0; k < c.size(); ++k) {
    if (c[k] < c_from || c[k] > c_to) continue;
    accumulate("/profiles/density", p.density, k);
    accumulate("/profiles/velocity_x", p.velocity_x, k);
    accumulate("/profiles/temperature", p.temperature, k);
    if (with_flux) accumulate("/profiles/average_heat_flux_total_y", p.heat_flux_y, k);
    ++p.frames;
  }
  for (std::vector<double>* profile : {&p.density, &p.velocity_x, &p.temperature, &p.heat_flux_y}) {
    for (double& v : *profile) v /= p.frames;
  }
  file.close();
  return p;
}

DensestBand densest_band(const StreamwiseProfiles& p, int band_rows) {
  const int rows = static_cast<int>(p.density.size());
  DensestBand band;
  if (rows == 0 || band_rows < 1 || band_rows >= rows) {
    band.centre = band.distance_from_middle = band.temperature_ratio = band.flux_towards_band =
        std::numeric_limits<double>::quiet_NaN();
    return band;
  }
  const auto inside = [&](int first, int r) { return (r - first + rows) % rows < band_rows; };
  int best = 0;
  double best_mass = -1.0;
  for (int first = 0; first < rows; ++first) {
    double mass = 0.0;
    for (int k = 0; k < band_rows; ++k) mass += p.density[static_cast<std::size_t>((first + k) % rows)];
    if (mass > best_mass) {
      best_mass = mass;
      best = first;
    }
  }
  const double row_height = p.length_y / rows;
  band.centre = std::fmod((best + 0.5 * band_rows) * row_height, p.length_y);
  band.distance_from_middle = std::abs(band.centre - 0.5 * p.length_y);
  double heat_in = 0.0, mass_in = 0.0, heat_out = 0.0, mass_out = 0.0;
  int outside = 0, towards = 0;
  for (int r = 0; r < rows; ++r) {
    const auto k = static_cast<std::size_t>(r);
    if (inside(best, r)) {
      heat_in += p.density[k] * p.temperature[k];
      mass_in += p.density[k];
      continue;
    }
    heat_out += p.density[k] * p.temperature[k];
    mass_out += p.density[k];
    if (p.heat_flux_y.empty()) continue;
    // The shorter way round the periodic y from this row to the band's centre.
    double to_band = band.centre - p.y[k];
    to_band -= p.length_y * std::round(to_band / p.length_y);
    ++outside;
    towards += to_band * p.heat_flux_y[k] > 0.0 ? 1 : 0;
  }
  band.temperature_ratio = (heat_in / mass_in) / (heat_out / mass_out);
  band.flux_towards_band = outside > 0 ? static_cast<double>(towards) / outside : std::numeric_limits<double>::quiet_NaN();
  return band;
}

int dense_layers(const StreamwiseProfiles& p, double threshold) {
  const std::size_t rows = p.density.size();
  double mean = 0.0;
  for (double d : p.density) mean += d / static_cast<double>(rows);
  int layers = 0, dense = 0;
  for (std::size_t r = 0; r < rows; ++r) {
    const bool here = p.density[r] > threshold * mean;
    dense += here ? 1 : 0;
    // A layer starts at a dense row whose lower neighbour (periodic) is not dense.
    layers += here && !(p.density[(r + rows - 1) % rows] > threshold * mean) ? 1 : 0;
  }
  return dense == static_cast<int>(rows) ? 1 : layers;  // every row dense: one layer, no edge
}

}  // namespace granule::reproduce
