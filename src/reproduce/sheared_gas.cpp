#include "reproduce/sheared_gas.hpp"

#include <fmt/format.h>

namespace granule::reproduce {

std::string sheared_gas_tables(int seed, int particles, double restitution, const std::string& boundary_lines) {
  return fmt::format(R"(seed = {}
[system]
particles = {}
area_fraction = 0.05
restitution = {}
tc_duration = 1e-7   # TC model against inelastic collapse (thesis: none)
[boundary]
kind = "lees-edwards"
{}
)",
                     seed, particles, restitution, boundary_lines);
}

}  // namespace granule::reproduce
