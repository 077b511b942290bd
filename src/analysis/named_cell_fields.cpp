#include "analysis/named_cell_fields.hpp"

#include <algorithm>
#include <cmath>

namespace granule {

const std::vector<std::string>& cell_field_names() {
  static const std::vector<std::string> names{"density",    "temperature", "velocity_x", "velocity_y",
                                              "kinetic_xx", "kinetic_xy",  "kinetic_yy", "pressure_kinetic",
                                              "vorticity",  "count"};
  return names;
}

const std::vector<double>* cell_field_by_name(const CellFields& f, std::string_view name) {
  const std::vector<double>* all[] = {&f.density,    &f.temperature, &f.velocity_x, &f.velocity_y,
                                      &f.kinetic_xx, &f.kinetic_xy,  &f.kinetic_yy, &f.pressure_kinetic,
                                      &f.vorticity,  &f.count};
  const auto& names = cell_field_names();
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (names[k] == name) return all[k];
  }
  return nullptr;
}

FieldGrid automatic_picture_grid(std::int64_t particles, double length_x, double length_y) {
  const double per_length = std::sqrt(static_cast<double>(particles) / (40.0 * length_x * length_y));
  const auto side = [&](double length) { return std::clamp(static_cast<int>(std::lround(per_length * length)), 4, 64); };
  return {side(length_x), side(length_y), length_x, length_y};
}

}  // namespace granule
