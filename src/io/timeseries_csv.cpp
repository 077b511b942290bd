#include "io/timeseries_csv.hpp"

#include <fmt/format.h>

#include "io/atomic_file.hpp"

namespace granule {

std::string timeseries_header() {
  return "t,c,kinetic_energy,temperature,temperature_thesis_cells,temperature_global,flatness,"
         "asymmetry_x,asymmetry_y,pressure_kinetic,pressure_collisional,shear_stress_kinetic,"
         "shear_stress_collisional,collision_rate\n";
}

std::string timeseries_row(const DiagnosticsSample& s) {
  return fmt::format("{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g}\n",
                     s.t, s.c, s.kinetic_energy, s.temperature, s.temperature_thesis_cells, s.temperature_global,
                     s.flatness, s.asymmetry_x, s.asymmetry_y, s.pressure_kinetic, s.pressure_collisional,
                     s.shear_stress_kinetic, s.shear_stress_collisional, s.collision_rate);
}

void write_timeseries(const std::string& path, const std::vector<DiagnosticsSample>& samples,
                      const std::string& previous_rows) {
  std::string content = timeseries_header() + previous_rows;
  for (const auto& sample : samples) content += timeseries_row(sample);
  write_file_atomically(path, content);
}

}  // namespace granule
