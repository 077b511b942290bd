#include "io/config.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <toml++/toml.h>

#include "cells/cell_grid.hpp"
#include "events/event_slot.hpp"
#include "io/config_geometry.hpp"
#include "io/config_obstacles.hpp"
#include "io/config_reader.hpp"
#include "io/config_restitution.hpp"
#include "io/config_roughness.hpp"
#include "io/config_shear.hpp"
#include "io/config_walls.hpp"
#include "io/input_ranges.hpp"

namespace granule {

namespace {

const ConfigSchema& schema() {
  static const ConfigSchema keys = {
      {"", {"seed", "obstacles"}},
      {"system",
       {"dimension", "particles", "area_fraction", "packing_fraction", "diameter", "diameters", "masses", "box",
        "restitution", "restitution_law", "elastic_below", "viscoelastic_constant", "tc_duration", "gravity",
        "rest_speed", "wake_speed", "tangential_restitution", "inertia_factor", "friction"}},
      {"boundary",
       {"kind", "shear_velocity", "shear_ramp_time", "shear_schedule", "shear_oscillation", "shear_tolerance", "wall_axes",
        "wall_restitution", "wall_tangential_restitution", "wall_motion"}},
      {"initial",
       {"temperature", "temperature_over_steady", "shear_profile", "from", "frame", "equilibrate", "placement",
        "rotational_temperature"}},
      {"run", {"until_collisions_per_particle", "until_time"}},
      {"output",
       {"every_collisions_per_particle", "every_time", "snapshot_every_collisions_per_particle",
        "snapshot_every_time", "checkpoint_every_seconds"}},
      {"engine", {"particles_per_cell", "cells", "renumber_every"}},
      {"diagnostics", {"cells"}},
      {"fields", {"enabled", "cells", "every_collisions_per_particle", "every_time", "subtract_shear_profile"}},
      {"collisions",
       {"impact_parameters", "free_paths", "window_collisions_per_particle", "from_collisions_per_particle",
        "density_windows", "speed_windows", "impact_bins", "length_bins", "angle_bins", "max_length"}},
  };
  return keys;
}

constexpr NumberRange kPositive{0.0, kUnbounded, true, true};

// A setting in collisions per particle c.  c·N is rounded to a whole number of collisions, so it
// must name at least one (c ≥ 1/N) and at most 2⁶² (kMaxCollisions), so that the count and a count
// plus an interval fit in an int64.  `zero_meaning` describes c = 0 where 0 is allowed.
std::optional<double> collision_count_setting(const ConfigReader& in, const std::string& path, std::int64_t particles,
                                              const std::string& zero_meaning = {}) {
  const auto n = static_cast<double>(particles);
  const NumberRange counts{1.0 / n, kMaxCollisions / n};
  const bool zero_allowed = !zero_meaning.empty();
  return in.number_if(path, [&](double c) { return (zero_allowed && c == 0.0) || counts.contains(c); },
                      fmt::format("{}{} for N = {} (from one collision, c·N ≥ 1, to 2^62 collisions)",
                                  zero_allowed ? "0 (" + zero_meaning + ") or " : "", counts.text(), particles));
}

// Exactly one of `count` and `time` may be given.
void require_one_of(const ConfigReader& in, const std::string& count, const std::string& time) {
  if (in.has(count) && in.has(time)) throw ConfigError{fmt::format("{} and {} are both set: give one", count, time)};
}

// The engine's cell grid must exist (choose_cell_grid explains why not) and have 28-bit cell ids.
static_assert(kMaxEngineCells <= EventSlot::kCellLimit, "every cell id of an accepted grid fits in an event slot");
void check_engine_grid(const RunConfig& c) {
  const CellGridChoice choice = choose_cell_grid(engine_grid_request(c));
  if (!choice.grid) throw ConfigError{choice.error};
  const std::int64_t cells = choice.grid->cell_count();
  if (cells > kMaxEngineCells) {
    // Automatic grids widen their cells to stay within the limit: only a grid given by hand gets here.
    throw ConfigError{fmt::format("engine.cells gives an engine grid of {} × {} = {} cells, more than 2^28: choose fewer",
                                  choice.grid->nx, choice.grid->ny, cells)};
  }
}

RunConfig resolve(const toml::table& root) {
  ConfigReader in(root);
  in.check_known_keys(schema());
  RunConfig c;
  c.seed = static_cast<std::uint64_t>(in.integer("seed", 0, INT64_MAX).value_or(1));

  SystemParams& s = c.system;
  s.particles = in.integer("system.particles", 2, INT32_MAX).value_or(4000);
  const std::int64_t n = s.particles;
  const std::string placement = in.text("initial.placement", {"auto", "random", "lattice"}).value_or("auto");
  c.placement = placement == "random" ? Placement::kRandom : placement == "lattice" ? Placement::kLattice : Placement::kAuto;
  resolve_geometry(in, c);
  s.restitution = in.number("system.restitution", kRestitutions).value_or(0.6);
  s.tc_duration = in.number("system.tc_duration", kContactDurations, " (0 switches the TC model off)").value_or(0.0);
  resolve_restitution_law(in, c);
  resolve_speeds(in, c);
  if (const auto from = in.path_text("initial.from")) {
    for (const char* key : {"initial.temperature", "initial.temperature_over_steady", "initial.shear_profile", "initial.placement",
                            "initial.rotational_temperature"}) {
      if (in.has(key)) throw ConfigError{fmt::format("{} cannot be combined with initial.from: the state comes from {}", key, *from)};
    }
    c.initial_from = InitialSource{*from, in.integer("initial.frame", 0, INT32_MAX)};
  } else if (in.has("initial.frame")) {
    throw ConfigError{"initial.frame needs initial.from = \"DIR\" (the run whose snapshot frame to start from)"};
  }
  resolve_roughness(in, c);
  resolve_gravity(in, c);
  resolve_rest(in, c);
  resolve_obstacles(root, c);
  c.equilibrate = collision_count_setting(in, "initial.equilibrate", n, "no elastic pre-run").value_or(0.0);

  c.until_collisions_per_particle = collision_count_setting(in, "run.until_collisions_per_particle", n);
  c.until_time = in.number("run.until_time", kPositive);
  if (!c.until_collisions_per_particle && !c.until_time) c.until_collisions_per_particle = 10.0;

  require_one_of(in, "output.every_collisions_per_particle", "output.every_time");
  c.sample_every_collisions_per_particle = collision_count_setting(in, "output.every_collisions_per_particle", n);
  c.sample_every_time = in.number("output.every_time", kPositive);
  if (!c.sample_every_collisions_per_particle && !c.sample_every_time) c.sample_every_collisions_per_particle = 1.0;
  require_one_of(in, "output.snapshot_every_collisions_per_particle", "output.snapshot_every_time");
  c.snapshot_every_collisions_per_particle =
      collision_count_setting(in, "output.snapshot_every_collisions_per_particle", n, "initial and final state only");
  c.snapshot_every_time = in.number("output.snapshot_every_time", kPositive);
  if (!c.snapshot_every_collisions_per_particle && !c.snapshot_every_time) c.snapshot_every_collisions_per_particle = 0.0;

  // Wall time is free of the simulation's scales: a checkpoint a year apart is still a schedule.
  c.checkpoint_every_seconds =
      in.number("output.checkpoint_every_seconds", NumberRange{0.0, 3.2e7}, " seconds of wall time (0: at every stop)")
          .value_or(600.0);

  // The engine needs about N/particles_per_cell cells, each with a 28-bit id.
  const double min_per_cell = std::max(0.1, static_cast<double>(n) / static_cast<double>(kMaxEngineCells));
  c.particles_per_cell = in.number("engine.particles_per_cell", NumberRange{min_per_cell, 20.0},
                                   min_per_cell > 0.1 ? fmt::format(" for N = {} (at most 2^28 engine cells)", n)
                                                      : std::string{})
                             .value_or(std::max(min_per_cell, kDefaultParticlesPerCell));
  // Grids given by hand have two counts: 3D runs choose theirs (engine, diagnostics, fields).
  if (s.dimension == 3) {
    for (const char* key : {"engine.cells", "diagnostics.cells", "fields.cells"}) {
      if (in.has(key)) throw ConfigError{fmt::format("{} is for 2D runs only: with system.dimension = 3 the grid is chosen "
                                                     "automatically (engine.particles_per_cell spheres per engine cell, ~20 per field cell)", key)};
    }
  }
  c.engine_cells = in.int_pair("engine.cells", 3, 1 << 15);
  // A matter of speed only (the trajectory is the same for any value): no upper limit is needed
  // but a run's length, and one beyond 10⁶ events per particle is never.
  s.renumber_every = in.number("engine.renumber_every", NumberRange{0.0, 1e6}, " events per particle (0: never)")
                         .value_or(default_renumber_every(s.dimension, s.particles));
  check_engine_grid(c);
  const auto diag = in.int_pair("diagnostics.cells", 1, 1 << 14);
  if (diag) {
    c.diagnostic_cells = *diag;
  } else {  // ~20 disks per cell, within the range an explicit grid may have
    const FieldGrid grid = default_field_grid(s.length_x, s.length_y, s.particles);
    c.diagnostic_cells = {std::min(grid.nx, 1 << 14), std::min(grid.ny, 1 << 14)};
  }

  FieldsConfig& f = c.fields;
  f.enabled = in.boolean("fields.enabled").value_or(true);
  f.cells = in.int_pair("fields.cells", 1, 1 << 14).value_or(c.diagnostic_cells);
  require_one_of(in, "fields.every_collisions_per_particle", "fields.every_time");
  f.every_collisions_per_particle = collision_count_setting(in, "fields.every_collisions_per_particle", n);
  f.every_time = in.number("fields.every_time", kPositive);
  f.subtract_shear_profile = in.boolean("fields.subtract_shear_profile").value_or(false);

  CollisionStatisticsConfig& k = c.collisions;
  // Impact parameters and free paths are measured on disks and spheres alike.
  k.impact_parameters = in.boolean("collisions.impact_parameters").value_or(true);
  k.free_paths = in.boolean("collisions.free_paths").value_or(false);
  k.window_collisions_per_particle =
      collision_count_setting(in, "collisions.window_collisions_per_particle", n).value_or(1.0);
  k.from_collisions_per_particle =
      in.number("collisions.from_collisions_per_particle", NumberRange{0.0, kMaxCollisions / static_cast<double>(n)},
                fmt::format(" for N = {} (at most 2^62 collisions)", n))
          .value_or(0.0);
  for (const auto& [low, high] : in.windows("collisions.density_windows")) k.density_windows.push_back({low, high});
  for (const auto& [low, high] : in.windows("collisions.speed_windows")) k.speed_windows.push_back({low, high});
  k.impact_bins = static_cast<int>(in.integer("collisions.impact_bins", 2, 100000).value_or(50));
  k.length_bins = static_cast<int>(in.integer("collisions.length_bins", 2, 100000).value_or(100));
  k.angle_bins = static_cast<int>(in.integer("collisions.angle_bins", 4, 100000).value_or(72));
  // Default range: ten mean free paths, l = Lx Ly / (2 N σ) in 2D (thesis §3.1.2) and the
  // Boltzmann l = 1/(√2 π n σ²) in 3D.  The bin width must stay a normal number, and the range finite.
  const NumberRange lengths{kMinMaxLengthOverDiameter * s.diameter,
                            kMaxMaxLengthOverBox * std::max({s.length_x, s.length_y, s.dimension == 3 ? s.length_z : 0.0})};
  // A range the user gives is kept (longer paths overflow and are reported); the default one widens.
  k.widen_max_length = !in.has("collisions.max_length");
  k.max_length = in.number("collisions.max_length", lengths,
                           fmt::format(" ({:g} σ to {:g} box lengths)", kMinMaxLengthOverDiameter, kMaxMaxLengthOverBox))
                     .value_or(s.dimension == 3 ? 10.0 * s.length_x * s.length_y * s.length_z /
                                                      (std::sqrt(2.0) * M_PI * static_cast<double>(n) * s.diameter * s.diameter)
                                                : 10.0 * s.length_x * s.length_y / (2.0 * static_cast<double>(n) * s.diameter));
  return c;
}


// What a --set of a key replaces from the file (or the built-in example): the other ways of saying
// the same thing, so that overriding never makes a "both are set" error; and for initial.from the
// settings of a new gas (its pre-run too: a state taken from a run is not re-melted unless asked).
const std::map<std::string, std::vector<std::string>>& replaced_keys() {
  static const std::map<std::string, std::vector<std::string>> replaces = {
      {"system.area_fraction", {"system.diameter", "system.packing_fraction"}},
      {"system.packing_fraction", {"system.diameter", "system.area_fraction"}},
      {"system.diameter", {"system.area_fraction", "system.packing_fraction"}},
      {"initial.temperature", {"initial.temperature_over_steady", "initial.from", "initial.frame"}},
      {"initial.temperature_over_steady", {"initial.temperature", "initial.from", "initial.frame"}},
      {"initial.from", {"initial.temperature", "initial.temperature_over_steady", "initial.shear_profile",
                        "initial.placement", "initial.equilibrate", "initial.rotational_temperature"}},
      {"output.every_collisions_per_particle", {"output.every_time"}},
      {"output.every_time", {"output.every_collisions_per_particle"}},
      {"output.snapshot_every_collisions_per_particle", {"output.snapshot_every_time"}},
      {"output.snapshot_every_time", {"output.snapshot_every_collisions_per_particle"}},
      {"fields.every_collisions_per_particle", {"fields.every_time"}},
      {"fields.every_time", {"fields.every_collisions_per_particle"}},
      {"boundary.shear_velocity", {"boundary.shear_schedule"}},
      {"boundary.shear_schedule", {"boundary.shear_velocity", "boundary.shear_ramp_time"}},
  };
  return replaces;
}

void erase_replaced(toml::table& root, const std::string& assignment) {
  const auto found = replaced_keys().find(assignment.substr(0, assignment.find('=')));
  if (found == replaced_keys().end()) return;
  for (const std::string& other : found->second) {
    const auto dot = other.find('.');
    if (toml::table* section = root[other.substr(0, dot)].as_table()) section->erase(other.substr(dot + 1));
  }
}

}  // namespace

CellGridRequest engine_grid_request(const RunConfig& config) {
  const SystemParams& s = config.system;
  CellGridRequest request{s.length_x, s.length_y, s.diameter, s.particles, config.lees_edwards, config.particles_per_cell,
                          config.engine_cells};
  request.dimension = s.dimension;
  request.length_z = s.length_z;
  request.max_cells = kMaxEngineCells;
  return request;
}

ConfigResult parse_config(const std::string& text, const std::vector<std::string>& overrides) {
  try {
    toml::table root = toml::parse(text);
    for (const auto& assignment : overrides) {
      erase_replaced(root, assignment);
      apply_override(root, assignment);
    }
    return {resolve(root), {}};
  } catch (const toml::parse_error& error) {
    std::ostringstream out;
    out << "malformed TOML at line " << error.source().begin.line << ", column "
        << error.source().begin.column << ": " << error.description();
    return {std::nullopt, out.str()};
  } catch (const ConfigError& error) {
    return {std::nullopt, error.message};
  }
}

ConfigResult load_config_file(const std::string& path, const std::vector<std::string>& overrides) {
  std::ifstream file(path);
  if (!file) return {std::nullopt, "cannot read the config file " + path};
  std::stringstream buffer;
  buffer << file.rdbuf();
  ConfigResult result = parse_config(buffer.str(), overrides);
  if (!result.config) result.error = path + ": " + result.error;
  return result;
}

std::string to_toml(const RunConfig& c) {
  const SystemParams& s = c.system;
  std::string out = "# Fully resolved configuration written by granule run: repeat the run with\n"
                    "#   granule run config.toml\n";
  out += fmt::format("seed = {}\n\n[system]\n", c.seed) + geometry_to_toml(c);
  if (s.restitution_law.kind != RestitutionKind::kViscoelastic) out += fmt::format("restitution = {:.17g}\n", s.restitution);
  out += restitution_law_to_toml(c) + fmt::format("tc_duration = {:.17g}\n", s.tc_duration);
  out += roughness_to_toml(c) + gravity_to_toml(c) + rest_to_toml(c) + "\n";
  out += speeds_to_toml(c) + rotational_temperature_to_toml(c);
  const char* placement = c.placement == Placement::kRandom ? "random" : c.placement == Placement::kLattice ? "lattice" : "auto";
  out += fmt::format("equilibrate = {:.17g}\n", c.equilibrate);
  if (!c.initial_from) out += fmt::format("placement = \"{}\"\n", placement);
  out += "\n[run]\n";
  if (c.until_collisions_per_particle) out += fmt::format("until_collisions_per_particle = {:.17g}\n", *c.until_collisions_per_particle);
  if (c.until_time) out += fmt::format("until_time = {:.17g}\n", *c.until_time);
  out += "\n[output]\n";
  if (c.sample_every_collisions_per_particle) out += fmt::format("every_collisions_per_particle = {:.17g}\n", *c.sample_every_collisions_per_particle);
  if (c.sample_every_time) out += fmt::format("every_time = {:.17g}\n", *c.sample_every_time);
  if (c.snapshot_every_collisions_per_particle) out += fmt::format("snapshot_every_collisions_per_particle = {:.17g}\n", *c.snapshot_every_collisions_per_particle);
  if (c.snapshot_every_time) out += fmt::format("snapshot_every_time = {:.17g}\n", *c.snapshot_every_time);
  out += fmt::format("checkpoint_every_seconds = {:.17g}\n", c.checkpoint_every_seconds);
  out += fmt::format("\n[engine]\nparticles_per_cell = {:.17g}\n", c.particles_per_cell);
  if (c.engine_cells) out += fmt::format("cells = [{}, {}]\n", c.engine_cells->first, c.engine_cells->second);
  // Hand-made grids are 2D keys: a 3D run's grids follow from its box and N.
  const bool planar = c.system.dimension == 2;
  if (planar) out += fmt::format("\n[diagnostics]\ncells = [{}, {}]\n", c.diagnostic_cells.first, c.diagnostic_cells.second);
  const FieldsConfig& f = c.fields;
  out += fmt::format("\n[fields]\nenabled = {}\n", f.enabled);
  if (planar) out += fmt::format("cells = [{}, {}]\n", f.cells.first, f.cells.second);
  out += fmt::format("subtract_shear_profile = {}\n", f.subtract_shear_profile);
  if (f.every_collisions_per_particle) out += fmt::format("every_collisions_per_particle = {:.17g}\n", *f.every_collisions_per_particle);
  if (f.every_time) out += fmt::format("every_time = {:.17g}\n", *f.every_time);
  const CollisionStatisticsConfig& k = c.collisions;
  const auto windows = [](const auto& list) {
    std::string text;
    for (const auto& w : list) text += fmt::format("{}[{:.17g}, {:.17g}]", text.empty() ? "" : ", ", w.low, w.high);
    return "[" + text + "]";
  };
  out += fmt::format("\n[collisions]\nimpact_parameters = {}\nfree_paths = {}\nwindow_collisions_per_particle = {:.17g}\n"
                     "from_collisions_per_particle = {:.17g}\ndensity_windows = {}\nspeed_windows = {}\nimpact_bins = {}\n"
                     "length_bins = {}\nangle_bins = {}\n",
                     k.impact_parameters, k.free_paths, k.window_collisions_per_particle, k.from_collisions_per_particle,
                     windows(k.density_windows), windows(k.speed_windows), k.impact_bins, k.length_bins, k.angle_bins);
  // The default range is left out, so that reading this file back gives the default again: a range
  // that widens (a written number would be read as a fixed range).
  out += k.widen_max_length ? fmt::format("# max_length: default {:.17g}, widened as long paths come\n", k.max_length)
                            : fmt::format("max_length = {:.17g}\n", k.max_length);
  return out + obstacles_to_toml(c);
}

std::string default_example_toml() {
  return R"(# Built-in example: a scaled-down System II of thesis §2.1 — free cooling of inelastic disks
# (e = 0.6, area fraction 0.05) from an equilibrated elastic gas, through the clustering transition.
seed = 1995

[system]
particles = 40000
area_fraction = 0.05
box = [1.0, 1.0]
restitution = 0.6
tc_duration = 1e-7   # TC model (Luding & McNamara 1998) against inelastic collapse

[boundary]
kind = "periodic"

[initial]
temperature = 1.0
equilibrate = 5

[run]
until_collisions_per_particle = 100

[output]
every_collisions_per_particle = 0.5
snapshot_every_collisions_per_particle = 10
)";
}

}  // namespace granule
