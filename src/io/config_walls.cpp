#include "io/config_walls.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "io/input_ranges.hpp"

namespace granule {

namespace {

constexpr const char* kAxisNames[3] = {"x", "y", "z"};
const char* const kWallKeys[] = {"boundary.wall_axes", "boundary.wall_restitution",
                                 "boundary.wall_tangential_restitution"};

// One number for every wall, or [lower, upper] for the walls at 0 and at L of each wall axis.
std::array<double, 2> per_side(const ConfigReader& in, const std::string& path, const NumberRange& range, double fallback,
                               const std::string& meaning) {
  const std::string why = fmt::format(" ({}; one number for every wall, or [lower, upper] for the walls at 0 and at L "
                                      "of each wall axis)", meaning);
  if (in.holds_list(path)) {
    const std::vector<double> sides = *in.number_list(path, 2, range, "[lower, upper]", why);
    return {sides[0], sides[1]};
  }
  const double both = in.number(path, range, why).value_or(fallback);
  return {both, both};
}

// A number, or [lower, upper] when the two sides differ (what per_side reads back).
std::string per_side_text(double lower, double upper) {
  return lower == upper ? fmt::format("{:.17g}", lower) : fmt::format("[{:.17g}, {:.17g}]", lower, upper);
}

int first_wall_axis(const SystemParams& s) {
  for (int axis = 0; axis < 3; ++axis) {
    if (s.walls[static_cast<std::size_t>(axis)]) return axis;
  }
  return -1;
}

}  // namespace

void resolve_walls(const ConfigReader& in, bool walls, RunConfig& c) {
  SystemParams& s = c.system;
  if (!walls) {
    for (const char* key : kWallKeys) {
      if (in.has(key)) throw ConfigError{fmt::format("{} requires boundary.kind = \"walls\"", key)};
    }
    return;
  }
  const std::set<std::string> axes = s.dimension == 3 ? std::set<std::string>{"x", "y", "z"} : std::set<std::string>{"x", "y"};
  const auto names = in.text_list("boundary.wall_axes", axes,
                                  s.dimension == 3 ? std::string{}
                                                   : " (z walls need system.dimension = 3: a 2D box has no z axis)")
                         .value_or(std::vector<std::string>{"y"});
  for (const std::string& name : names) s.walls[name == "x" ? 0 : name == "y" ? 1 : 2] = true;
  const auto restitution = per_side(in, "boundary.wall_restitution", kRestitutions, 1.0, "e_w, normal restitution");
  const auto tangential = per_side(in, "boundary.wall_tangential_restitution", kTangentialRestitutions, -1.0,
                                   "β_w, tangential restitution: −1 a smooth wall, +1 a perfectly rough one");
  const std::array<double, 3> lengths{s.length_x, s.length_y, s.length_z};
  for (std::size_t axis = 0; axis < 3; ++axis) {
    if (!s.walls[axis]) continue;
    // Every centre stays one radius from each wall: the side must hold one diameter.
    if (!(lengths[axis] > s.diameter)) {
      throw ConfigError{fmt::format("boundary.wall_axes includes {}: the box side L_{} = {} must exceed the {}diameter "
                                    "σ = {} (every centre stays one radius from each wall)", kAxisNames[axis],
                                    kAxisNames[axis], lengths[axis], c.diameters.monodisperse() ? "" : "largest ",
                                    s.diameter)};
    }
    for (std::size_t side = 0; side < 2; ++side) {
      s.wall[2 * axis + side].restitution = restitution[side];
      s.wall[2 * axis + side].tangential_restitution = tangential[side];
    }
  }
}

void set_wall_shear(SystemParams& s, double shear_velocity) {
  s.wall[2].velocity[0] = 0.0 - 0.5 * shear_velocity;  // +0, not −0, for walls at rest (printed, echoed)
  s.wall[3].velocity[0] = 0.5 * shear_velocity;
}

double wall_shear_velocity(const SystemParams& s) {
  return s.walls[1] ? s.wall[3].velocity[0] - s.wall[2].velocity[0] : 0.0;
}

std::string boundary_kind_name(const RunConfig& c) {
  return c.system.has_walls() ? "walls" : c.lees_edwards ? "lees-edwards" : "periodic";
}

std::string walls_to_toml(const RunConfig& c) {
  const SystemParams& s = c.system;
  const int first = first_wall_axis(s);
  if (first < 0) return {};
  std::string axes;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    if (s.walls[axis]) axes += fmt::format("{}\"{}\"", axes.empty() ? "" : ", ", kAxisNames[axis]);
  }
  // Every wall axis has the same pair (resolve_walls): the first one speaks for all.
  const WallParams& lower = s.wall[static_cast<std::size_t>(2 * first)];
  const WallParams& upper = s.wall[static_cast<std::size_t>(2 * first + 1)];
  return fmt::format("wall_axes = [{}]\nwall_restitution = {}\nwall_tangential_restitution = {}\n", axes,
                     per_side_text(lower.restitution, upper.restitution),
                     per_side_text(lower.tangential_restitution, upper.tangential_restitution));
}

void resolve_gravity(const ConfigReader& in, RunConfig& c) {
  SystemParams& s = c.system;
  const auto g = in.number_list("system.gravity", static_cast<std::size_t>(s.dimension),
                                NumberRange{-kUnbounded, kUnbounded, true, true}, s.dimension == 3 ? "[g_x, g_y, g_z]" : "[g_x, g_y]",
                                fmt::format(" for system.dimension = {}", s.dimension));
  if (!g) return;
  for (std::size_t axis = 0; axis < g->size(); ++axis) s.gravity[axis] = (*g)[axis];
  if (c.lees_edwards && s.gravity[1] != 0.0) {
    throw ConfigError{fmt::format(
        "system.gravity = [{}] has g_y = {} ≠ 0, which boundary.kind = \"lees-edwards\" cannot have: the sheared "
        "images make the abscissa of a grain crossing y depend on time, and a parabolic flight in y would make that "
        "crossing cubic in time; a periodic gradient direction under gravity is not a physical flow either.  Allowed: "
        "g_y = 0 with Lees–Edwards, or walls on y (boundary.kind = \"walls\", the walls carrying the shear)",
        fmt::join(*g, ", "), s.gravity[1])};
  }
}

std::string gravity_to_toml(const RunConfig& c) {
  const SystemParams& s = c.system;
  if (!s.has_gravity()) return {};
  return s.dimension == 3 ? fmt::format("gravity = [{:.17g}, {:.17g}, {:.17g}]\n", s.gravity[0], s.gravity[1], s.gravity[2])
                          : fmt::format("gravity = [{:.17g}, {:.17g}]\n", s.gravity[0], s.gravity[1]);
}

void resolve_rest(const ConfigReader& in, RunConfig& c) {
  SystemParams& s = c.system;
  const auto speed = in.number("system.rest_speed", NumberRange{0.0, kUnbounded, true, true},
                               " (a grain slower than this after a hit of a static support comes to rest)");
  const auto wake = in.number("system.wake_speed", NumberRange{0.0, kUnbounded, false, true},
                              " (a grain at rest struck at a larger normal speed moves again)");
  if (!speed) {
    if (wake) throw ConfigError{"system.wake_speed needs system.rest_speed: without it no grain comes to rest"};
    return;
  }
  if (!s.has_gravity()) {
    throw ConfigError{fmt::format("system.rest_speed = {} needs system.gravity: a grain comes to rest where its supports "
                                  "hold it against gravity, and without gravity nothing holds a grain at rest",
                                  *speed)};
  }
  if (s.dimension == 3) {
    throw ConfigError{fmt::format("system.rest_speed = {} is for disks (system.dimension = 2) so far: a bed of spheres "
                                  "under the rule keeps waking itself (its grains slide off the shoulders they come to "
                                  "rest on), and costs more events than without it",
                                  *speed)};
  }
  if (c.lees_edwards) {
    throw ConfigError{fmt::format("system.rest_speed = {} cannot be combined with boundary.kind = \"lees-edwards\": a grain "
                                  "at rest is a fixed support, and the sliding images would carry its images through the "
                                  "flow.  Allowed: walls (boundary.kind = \"walls\") or a periodic box",
                                  *speed)};
  }
  // By default a grain at rest moves again when struck hard enough to lift it by more than σ/200
  // (u²/2g): a gentler blow only rocks it in its pocket, from which it would come to rest again.
  double g = 0.0;
  for (const double component : s.gravity) g += component * component;
  s.rest = {*speed, wake.value_or(std::max(*speed, 0.1 * std::sqrt(std::sqrt(g) * s.diameter)))};
}

std::string rest_to_toml(const RunConfig& c) {
  const RestParams& r = c.system.rest;
  if (!r.on()) return {};
  return fmt::format("rest_speed = {:.17g}\nwake_speed = {:.17g}\n", r.speed, r.wake_speed);
}

}  // namespace granule
