#include "io/config.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <toml++/toml.h>

namespace granule {

namespace {

// A validation failure: the message is complete ("key = value: allowed ...").
struct ConfigError {
  std::string message;
};

// The accepted keys of each section ("" is the top level).
const std::map<std::string, std::set<std::string>>& schema() {
  static const std::map<std::string, std::set<std::string>> keys = {
      {"", {"seed"}},
      {"system", {"particles", "area_fraction", "diameter", "box", "restitution", "tc_duration"}},
      {"boundary", {"kind", "shear_velocity"}},
      {"initial", {"temperature", "equilibrate", "placement"}},
      {"run", {"until_collisions_per_particle", "until_time"}},
      {"output",
       {"every_collisions_per_particle", "every_time", "snapshot_every_collisions_per_particle",
        "snapshot_every_time", "checkpoint_every_seconds"}},
      {"engine", {"particles_per_cell", "cells"}},
      {"diagnostics", {"cells"}},
      {"fields", {"enabled", "cells", "every_collisions_per_particle", "every_time", "subtract_shear_profile"}},
      {"collisions",
       {"impact_parameters", "free_paths", "window_collisions_per_particle", "from_collisions_per_particle",
        "density_windows", "speed_windows", "impact_bins", "length_bins", "angle_bins", "max_length"}},
  };
  return keys;
}

std::string show(const toml::node& node) {
  std::ostringstream out;
  if (node.is_string()) {
    out << '"' << node.value_or(std::string{}) << '"';
  } else if (node.is_array()) {
    out << *node.as_array();
  } else if (node.is_table()) {
    out << "a table";
  } else {
    out << toml::node_view<const toml::node>{node};
  }
  return out.str();
}

class Reader {
 public:
  explicit Reader(const toml::table& root) : root_(root) {}

  void check_known_keys() const {
    for (const auto& [key, node] : root_) {
      const std::string name{key.str()};
      if (node.is_table()) {
        auto section = schema().find(name);
        if (section == schema().end() || name.empty()) {
          throw ConfigError{fmt::format("unknown section [{}]; allowed sections: system, boundary, "
                                        "initial, run, output, engine, diagnostics, fields, collisions", name)};
        }
        for (const auto& [inner, value] : *node.as_table()) {
          const std::string inner_name{inner.str()};
          if (!section->second.count(inner_name)) {
            throw ConfigError{fmt::format("unknown key {}.{} (value {}); allowed keys in [{}]: {}", name,
                                          inner_name, show(value), name, join(section->second))};
          }
        }
      } else if (!schema().at("").count(name)) {
        throw ConfigError{fmt::format("unknown top-level key {} (value {}); allowed: seed, or a "
                                      "section such as [system]", name, show(node))};
      }
    }
  }

  const toml::node* find(const std::string& path) const {
    const auto dot = path.find('.');
    if (dot == std::string::npos) return root_.get(path);
    const toml::node* section = root_.get(path.substr(0, dot));
    if (!section || !section->is_table()) return nullptr;
    return section->as_table()->get(path.substr(dot + 1));
  }

  // A number (integer or float) in [lo, hi] with open/closed ends as described by `range`.
  std::optional<double> number(const std::string& path, double lo, double hi, bool lo_open,
                               bool hi_open, const std::string& range) const {
    const toml::node* node = find(path);
    if (!node) return std::nullopt;
    const auto value = node->value<double>();
    const bool ok = value && std::isfinite(*value) && (lo_open ? *value > lo : *value >= lo) &&
                    (hi_open ? *value < hi : *value <= hi);
    if (!ok) throw ConfigError{fmt::format("{} = {} is out of range: allowed {}", path, show(*node), range)};
    return value;
  }

  std::optional<std::int64_t> integer(const std::string& path, std::int64_t lo, std::int64_t hi,
                                      const std::string& range) const {
    const toml::node* node = find(path);
    if (!node) return std::nullopt;
    const auto value = node->is_integer() ? node->value<std::int64_t>() : std::nullopt;
    if (!value || *value < lo || *value > hi) {
      throw ConfigError{fmt::format("{} = {} is not allowed: expected an integer in {}", path, show(*node), range)};
    }
    return value;
  }

  std::optional<std::string> text(const std::string& path, const std::set<std::string>& allowed) const {
    const toml::node* node = find(path);
    if (!node) return std::nullopt;
    const auto value = node->value<std::string>();
    if (!value || !allowed.count(*value)) {
      throw ConfigError{fmt::format("{} = {} is not allowed: expected one of {}", path, show(*node), join(allowed))};
    }
    return value;
  }

  // A pair of positive numbers [a, b].
  std::optional<std::pair<double, double>> number_pair(const std::string& path) const {
    const toml::node* node = find(path);
    if (!node) return std::nullopt;
    const toml::array* array = node->as_array();
    if (array && array->size() == 2) {
      const auto a = (*array)[0].value<double>();
      const auto b = (*array)[1].value<double>();
      if (a && b && std::isfinite(*a) && std::isfinite(*b) && *a > 0.0 && *b > 0.0) return std::pair{*a, *b};
    }
    throw ConfigError{fmt::format("{} = {} is not allowed: expected [Lx, Ly] with two positive numbers", path, show(*node))};
  }

  std::optional<bool> boolean(const std::string& path) const {
    const toml::node* node = find(path);
    if (!node) return std::nullopt;
    if (!node->is_boolean()) throw ConfigError{fmt::format("{} = {} is not allowed: expected true or false", path, show(*node))};
    return node->value<bool>();
  }

  // A list of windows [[low, high], ...] with 0 ≤ low < high.
  std::vector<std::pair<double, double>> windows(const std::string& path) const {
    const toml::node* node = find(path);
    std::vector<std::pair<double, double>> out;
    if (!node) return out;
    const toml::array* list = node->as_array();
    const auto fail = [&] {
      return ConfigError{fmt::format("{} = {} is not allowed: expected a list of windows [[low, high], ...] with "
                                     "0 <= low < high", path, show(*node))};
    };
    if (!list) throw fail();
    for (const toml::node& item : *list) {
      const toml::array* pair = item.as_array();
      if (!pair || pair->size() != 2) throw fail();
      const auto low = (*pair)[0].value<double>();
      const auto high = (*pair)[1].value<double>();
      if (!low || !high || !std::isfinite(*high) || *low < 0.0 || *low >= *high) throw fail();
      out.emplace_back(*low, *high);
    }
    return out;
  }

  std::optional<std::pair<int, int>> int_pair(const std::string& path, int lo, int hi) const {
    const toml::node* node = find(path);
    if (!node) return std::nullopt;
    const toml::array* array = node->as_array();
    if (array && array->size() == 2 && (*array)[0].is_integer() && (*array)[1].is_integer()) {
      const auto a = *(*array)[0].value<std::int64_t>();
      const auto b = *(*array)[1].value<std::int64_t>();
      if (a >= lo && a <= hi && b >= lo && b <= hi) return std::pair{static_cast<int>(a), static_cast<int>(b)};
    }
    throw ConfigError{fmt::format("{} = {} is not allowed: expected [nx, ny] with integers in [{}, {}]", path,
                                  show(*node), lo, hi)};
  }

 private:
  static std::string join(const std::set<std::string>& items) {
    std::string out;
    for (const auto& item : items) out += (out.empty() ? "" : ", ") + item;
    return out;
  }
  const toml::table& root_;
};

void apply_override(toml::table& root, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw ConfigError{fmt::format("--set {}: expected section.key=value", assignment)};
  }
  const std::string path = assignment.substr(0, eq);
  const std::string raw = assignment.substr(eq + 1);
  // The value is TOML ("0.8", "[2, 1]", "\"lees-edwards\""); a bare word is taken as a string.
  toml::table parsed;
  try {
    parsed = toml::parse("v = " + raw);
  } catch (const toml::parse_error&) {
    parsed = toml::table{{"v", raw}};
  }
  const auto dot = path.find('.');
  toml::table* target = &root;
  std::string key = path;
  if (dot != std::string::npos) {
    const std::string section = path.substr(0, dot);
    key = path.substr(dot + 1);
    if (!root.contains(section)) root.insert(section, toml::table{});
    target = root.get(section)->as_table();
    if (!target) throw ConfigError{fmt::format("--set {}: {} is not a section", assignment, section)};
  }
  target->insert_or_assign(key, *parsed.get("v"));
}

RunConfig resolve(const toml::table& root) {
  Reader in(root);
  in.check_known_keys();
  RunConfig c;
  c.seed = static_cast<std::uint64_t>(in.integer("seed", 0, INT64_MAX, "[0, 2^63)").value_or(1));

  SystemParams& s = c.system;
  s.particles = in.integer("system.particles", 2, INT32_MAX, "[2, 2147483647]").value_or(4000);
  const auto box = in.number_pair("system.box").value_or(std::pair{1.0, 1.0});
  s.length_x = box.first;
  s.length_y = box.second;
  const auto nu = in.number("system.area_fraction", 0.0, kClosePacking, true, true,
                            fmt::format("(0, {:.4f}) (hexagonal close packing π/(2√3))", kClosePacking));
  const auto diameter = in.number("system.diameter", 0.0, INFINITY, true, true, "(0, ∞)");
  if (nu && diameter) {
    throw ConfigError{"system.area_fraction and system.diameter are both set: give one of them "
                      "(the other follows from ν = πNσ²/(4 Lx Ly))"};
  }
  const double area = s.length_x * s.length_y;
  const auto n = static_cast<double>(s.particles);
  if (diameter) {
    s.diameter = *diameter;
    c.area_fraction = M_PI * n * s.diameter * s.diameter / (4.0 * area);
    if (c.area_fraction >= kClosePacking) {
      throw ConfigError{fmt::format("system.diameter = {} gives area fraction {:.4f}, at or above close "
                                    "packing {:.4f}: allowed diameters are below {:.6g}", *diameter,
                                    c.area_fraction, kClosePacking, std::sqrt(4.0 * area * kClosePacking / (M_PI * n)))};
    }
  } else {
    c.area_fraction = nu.value_or(0.05);
    s.diameter = std::sqrt(4.0 * c.area_fraction * area / (M_PI * n));
  }
  s.restitution = in.number("system.restitution", 0.0, 1.0, true, false, "(0, 1]").value_or(0.6);
  s.tc_duration = in.number("system.tc_duration", 0.0, INFINITY, false, true, "[0, ∞) (0 switches the TC model off)").value_or(0.0);

  c.lees_edwards = in.text("boundary.kind", {"periodic", "lees-edwards"}).value_or("periodic") == "lees-edwards";
  s.shear_velocity = in.number("boundary.shear_velocity", -INFINITY, INFINITY, true, true, "any finite number").value_or(0.0);
  if (!c.lees_edwards && s.shear_velocity != 0.0) {
    throw ConfigError{fmt::format("boundary.shear_velocity = {} requires boundary.kind = \"lees-edwards\" "
                                  "(a periodic box has no shear; allowed: 0)", s.shear_velocity)};
  }

  c.initial_temperature = in.number("initial.temperature", 0.0, INFINITY, true, true, "(0, ∞)").value_or(1.0);
  c.equilibrate = in.number("initial.equilibrate", 0.0, INFINITY, false, true, "[0, ∞) collisions per particle").value_or(0.0);
  const std::string placement = in.text("initial.placement", {"auto", "random", "lattice"}).value_or("auto");
  c.placement = placement == "random" ? Placement::kRandom : placement == "lattice" ? Placement::kLattice : Placement::kAuto;

  c.until_collisions_per_particle = in.number("run.until_collisions_per_particle", 0.0, INFINITY, true, true, "(0, ∞)");
  c.until_time = in.number("run.until_time", 0.0, INFINITY, true, true, "(0, ∞)");
  if (!c.until_collisions_per_particle && !c.until_time) c.until_collisions_per_particle = 10.0;

  c.sample_every_collisions_per_particle = in.number("output.every_collisions_per_particle", 0.0, INFINITY, true, true, "(0, ∞)");
  c.sample_every_time = in.number("output.every_time", 0.0, INFINITY, true, true, "(0, ∞)");
  if (c.sample_every_collisions_per_particle && c.sample_every_time) {
    throw ConfigError{"output.every_collisions_per_particle and output.every_time are both set: give one"};
  }
  if (!c.sample_every_collisions_per_particle && !c.sample_every_time) c.sample_every_collisions_per_particle = 1.0;
  c.snapshot_every_collisions_per_particle = in.number("output.snapshot_every_collisions_per_particle", 0.0, INFINITY, false, true, "[0, ∞) (0: final state only)");
  c.snapshot_every_time = in.number("output.snapshot_every_time", 0.0, INFINITY, true, true, "(0, ∞)");
  if (c.snapshot_every_collisions_per_particle && c.snapshot_every_time) {
    throw ConfigError{"output.snapshot_every_collisions_per_particle and output.snapshot_every_time are both set: give one"};
  }
  if (!c.snapshot_every_collisions_per_particle && !c.snapshot_every_time) c.snapshot_every_collisions_per_particle = 0.0;

  c.checkpoint_every_seconds =
      in.number("output.checkpoint_every_seconds", 0.0, INFINITY, false, true, "[0, ∞) seconds of wall time (0: at every stop of the loop)")
          .value_or(600.0);

  c.particles_per_cell = in.number("engine.particles_per_cell", 0.1, 20.0, false, false, "[0.1, 20]").value_or(1.0);
  c.engine_cells = in.int_pair("engine.cells", 3, 1 << 15);
  const auto diag = in.int_pair("diagnostics.cells", 1, 1 << 14);
  if (diag) {
    c.diagnostic_cells = *diag;
  } else {
    const FieldGrid grid = default_field_grid(s.length_x, s.length_y, s.particles);
    c.diagnostic_cells = {grid.nx, grid.ny};
  }

  FieldsConfig& f = c.fields;
  f.enabled = in.boolean("fields.enabled").value_or(true);
  f.cells = in.int_pair("fields.cells", 1, 1 << 14).value_or(c.diagnostic_cells);
  f.every_collisions_per_particle = in.number("fields.every_collisions_per_particle", 0.0, INFINITY, true, true, "(0, ∞)");
  f.every_time = in.number("fields.every_time", 0.0, INFINITY, true, true, "(0, ∞)");
  if (f.every_collisions_per_particle && f.every_time) {
    throw ConfigError{"fields.every_collisions_per_particle and fields.every_time are both set: give one"};
  }
  f.subtract_shear_profile = in.boolean("fields.subtract_shear_profile").value_or(false);

  CollisionStatisticsConfig& k = c.collisions;
  k.impact_parameters = in.boolean("collisions.impact_parameters").value_or(true);
  k.free_paths = in.boolean("collisions.free_paths").value_or(false);
  k.window_collisions_per_particle =
      in.number("collisions.window_collisions_per_particle", 0.0, INFINITY, true, true, "(0, ∞)").value_or(1.0);
  k.from_collisions_per_particle =
      in.number("collisions.from_collisions_per_particle", 0.0, INFINITY, false, true, "[0, ∞)").value_or(0.0);
  for (const auto& [low, high] : in.windows("collisions.density_windows")) k.density_windows.push_back({low, high});
  for (const auto& [low, high] : in.windows("collisions.speed_windows")) k.speed_windows.push_back({low, high});
  k.impact_bins = static_cast<int>(in.integer("collisions.impact_bins", 2, 100000, "[2, 100000]").value_or(50));
  k.length_bins = static_cast<int>(in.integer("collisions.length_bins", 2, 100000, "[2, 100000]").value_or(100));
  k.angle_bins = static_cast<int>(in.integer("collisions.angle_bins", 4, 100000, "[4, 100000]").value_or(72));
  // Default range: ten mean free paths l = Lx Ly / (2 N σ) (thesis §3.1.2).
  k.max_length = in.number("collisions.max_length", 0.0, INFINITY, true, true, "(0, ∞)")
                     .value_or(10.0 * area / (2.0 * n * s.diameter));
  return c;
}

}  // namespace

ConfigResult parse_config(const std::string& text, const std::vector<std::string>& overrides) {
  try {
    toml::table root = toml::parse(text);
    for (const auto& assignment : overrides) apply_override(root, assignment);
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
  out += fmt::format("seed = {}\n\n[system]\nparticles = {}\ndiameter = {:.17g}  # area_fraction = {:.17g}\n"
                     "box = [{:.17g}, {:.17g}]\nrestitution = {:.17g}\ntc_duration = {:.17g}\n\n",
                     c.seed, s.particles, s.diameter, c.area_fraction, s.length_x, s.length_y,
                     s.restitution, s.tc_duration);
  out += fmt::format("[boundary]\nkind = \"{}\"\nshear_velocity = {:.17g}\n\n",
                     c.lees_edwards ? "lees-edwards" : "periodic", s.shear_velocity);
  const char* placement = c.placement == Placement::kRandom ? "random" : c.placement == Placement::kLattice ? "lattice" : "auto";
  out += fmt::format("[initial]\ntemperature = {:.17g}\nequilibrate = {:.17g}\nplacement = \"{}\"\n\n[run]\n",
                     c.initial_temperature, c.equilibrate, placement);
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
  out += fmt::format("\n[diagnostics]\ncells = [{}, {}]\n", c.diagnostic_cells.first, c.diagnostic_cells.second);
  const FieldsConfig& f = c.fields;
  out += fmt::format("\n[fields]\nenabled = {}\ncells = [{}, {}]\nsubtract_shear_profile = {}\n", f.enabled, f.cells.first,
                     f.cells.second, f.subtract_shear_profile);
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
                     "length_bins = {}\nangle_bins = {}\nmax_length = {:.17g}\n",
                     k.impact_parameters, k.free_paths, k.window_collisions_per_particle, k.from_collisions_per_particle,
                     windows(k.density_windows), windows(k.speed_windows), k.impact_bins, k.length_bins, k.angle_bins,
                     k.max_length);
  return out;
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
