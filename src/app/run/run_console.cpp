#include "app/run/run_console.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>
#include <chrono>
#include <cmath>
#include <vector>

#include "driver/run_directory.hpp"
#include "granule/version.hpp"

namespace granule::app {

namespace {

// Rough grains, walls and gravity, one line each when present.
void print_grains_walls_gravity(const RunConfig& config) {
  const SystemParams& s = config.system;
  const int d = s.dimension;
  const RoughnessParams& r = s.roughness;
  if (r.rough) {
    fmt::print("rough grains: β = {}, q = {} (I = q m σ²/4), μ = {}{}\n", r.tangential_restitution, r.inertia_factor,
               std::isfinite(r.friction) ? fmt::format("{}", r.friction) : "∞ (no Coulomb limit)",
               config.initial_from ? std::string{} : fmt::format("; initial T_rot = {}", config.initial_rotational_temperature));
  }
  const auto vector_text = [d](const std::array<double, 3>& v) {
    return d == 3 ? fmt::format("({}, {}, {})", v[0], v[1], v[2]) : fmt::format("({}, {})", v[0], v[1]);
  };
  const std::array<double, 3> lengths{s.length_x, s.length_y, s.length_z};
  for (std::size_t axis = 0; axis < 3; ++axis) {
    if (!s.walls[axis]) continue;
    const WallParams& lower = s.wall[2 * axis];
    const WallParams& upper = s.wall[2 * axis + 1];
    const char name = "xyz"[axis];
    fmt::print("walls at {} = 0 (e_w = {}, β_w = {}, velocity {}) and {} = {} (e_w = {}, β_w = {}, velocity {})\n", name,
               lower.restitution, lower.tangential_restitution, vector_text(lower.velocity), name, lengths[axis],
               upper.restitution, upper.tangential_restitution, vector_text(upper.velocity));
  }
  if (s.has_gravity()) fmt::print("gravity g = {}\n", vector_text(s.gravity));
}

}  // namespace

void print_header(const RunConfig& config, bool built_in_example, std::size_t overrides) {
  const SystemParams& s = config.system;
  const char* boundary = config.lees_edwards ? "Lees–Edwards" : s.has_walls() ? "walled" : "periodic";
  const double u = config.lees_edwards ? s.shear_velocity : wall_shear_velocity(s);
  fmt::print("granule {}: {}{}, N = {}, ν = {:.4g}, σ = {:.6g}{}, e = {}, {} box {} × {}{}{}\n", kVersion,
             s.roughness.rough ? "rough " : "", s.dimension == 3 ? "spheres" : "disks", s.particles, config.packing_fraction,
             s.diameter, config.diameters.monodisperse() ? "" : " (largest)", s.restitution, boundary, s.length_x, s.length_y,
             s.dimension == 3 ? fmt::format(" × {}", s.length_z) : std::string{},
             config.lees_edwards || s.walls[1] ? fmt::format(", U = {}", u) : std::string{});
  fmt::print("collision model: {}\n", collision_model_text(s));
  if (built_in_example) {
    fmt::print("config: the built-in example (no CONFIG given: a scaled-down System II of thesis §2.1, free cooling "
               "with the TC model t_c = 1e-7){}; the resolved config is written to config.toml\n",
               overrides > 0 ? fmt::format(" with {} --set override{}; keys not overridden keep the example's values",
                                           overrides, overrides == 1 ? "" : "s")
                             : std::string{});
  }
  print_grains_walls_gravity(config);
  if (config.equilibrate > 0.0) fmt::print("elastic pre-run: {} collisions per particle\n", config.equilibrate);
}

std::string collision_model_text(const SystemParams& s) {
  if (s.tc_duration > 0.0) {
    return fmt::format("e = {} with the TC model (Luding & McNamara 1998): a collision within t_c = {:g} of either "
                       "grain's previous collision is elastic",
                       s.restitution, s.tc_duration);
  }
  return fmt::format("e = {} in every collision (TC model off: an inelastic collapse stops the run with exit 3)",
                     s.restitution);
}

std::string files_written_text(const std::string& out, std::filesystem::file_time_type since) {
  const std::vector<std::string> files = driver::files_written_since(out, since);
  return fmt::format("files written in {}: {}", out, files.empty() ? "none" : fmt::format("{}", fmt::join(files, ", ")));
}

}  // namespace granule::app
