// Seeded fuzzing of parse_config(): thousands of mutations of valid configurations (deleted keys,
// hostile values, wrong types, unknown keys and sections, duplicate keys, broken TOML, bad
// --set overrides).  No mutation may crash or throw; a refusal must name a key (or the TOML
// position); an accepted configuration must satisfy invariants checked here from the README's
// ranges, independently of the parser: finite values, 0 < ν < close packing, collision targets
// of at least one and at most 2^62 collisions, an engine grid with 32-bit cell ids, and an exact
// round trip through to_toml() (a resumed run reads its own config.toml).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "cells/cell_grid.hpp"
#include "io/config.hpp"
#include "io/input_ranges.hpp"

namespace granule {
namespace {

const std::string kLeesEdwardsBase = R"(seed = 7
[system]
particles = 300
area_fraction = 0.1
box = [1.0, 1.5]
restitution = 0.8
[boundary]
kind = "lees-edwards"
shear_velocity = 20.0
[initial]
temperature = 2.0
equilibrate = 1
[run]
until_collisions_per_particle = 4
until_time = 100.0
[output]
every_time = 0.01
snapshot_every_collisions_per_particle = 2
[engine]
particles_per_cell = 1.5
)";

const std::string kMeasurementsBase = R"([system]
particles = 400
diameter = 0.01
box = [1.0, 1.0]
restitution = 0.9
tc_duration = 1e-6
[run]
until_collisions_per_particle = 3
[output]
every_collisions_per_particle = 0.5
snapshot_every_time = 0.1
[diagnostics]
cells = [8, 8]
[fields]
enabled = true
cells = [10, 12]
every_collisions_per_particle = 1
subtract_shear_profile = false
[collisions]
impact_parameters = true
free_paths = true
window_collisions_per_particle = 0.5
from_collisions_per_particle = 1
density_windows = [[0, 300], [300, 1e9]]
speed_windows = [[0, 1], [1, 1e3]]
impact_bins = 20
length_bins = 50
angle_bins = 36
max_length = 0.5
)";

// Every key of the README's configuration reference.
const std::vector<std::string> kKeys = {
    "seed", "system.particles", "system.area_fraction", "system.packing_fraction", "system.diameter",
    "system.diameters", "system.masses", "system.box", "system.restitution",
    "system.tc_duration", "system.gravity", "system.tangential_restitution", "system.inertia_factor",
    "system.friction", "boundary.kind", "boundary.shear_velocity", "boundary.wall_axes",
    "boundary.wall_restitution", "boundary.wall_tangential_restitution", "initial.rotational_temperature", "initial.temperature", "initial.equilibrate",
    "initial.placement", "run.until_collisions_per_particle", "run.until_time", "output.every_collisions_per_particle",
    "output.every_time", "output.snapshot_every_collisions_per_particle", "output.snapshot_every_time",
    "engine.particles_per_cell", "engine.cells", "diagnostics.cells", "fields.enabled", "fields.cells",
    "fields.every_collisions_per_particle", "fields.every_time", "fields.subtract_shear_profile",
    "collisions.impact_parameters", "collisions.free_paths", "collisions.window_collisions_per_particle",
    "collisions.from_collisions_per_particle", "collisions.density_windows", "collisions.speed_windows",
    "collisions.impact_bins", "collisions.length_bins", "collisions.angle_bins", "collisions.max_length", "obstacles"};

const std::vector<std::string> kHostileValues = {
    "nan", "+nan", "inf", "-inf", "0", "-0.0", "-1", "1e308", "-1e308", "1e-308", "5e-324", "9223372036854775807",
    "-9223372036854775808", "2147483648", "2147483647", "0.5", "1", "2", "3", "1e-9", "1e30", "1e-30", "1e300",
    "0.00025", "\"text\"", "\"\"", "\"lees-edwards\"", "\"lattice\"", "true", "false", "[]", "[1.0]",
    "[1.0, 2.0, 3.0]", "[nan, 1.0]", "[1.0, inf]", "[1e-300, 1e300]", "[1e300, 1e300]", "[[1.0, 2.0]]",
    "[[nan, 1.0]]", "[[2.0, 1.0]]", "[[-0.0, 1.0]]", "[[0, 1e300]]", "[[0, inf]]", "[3, 3]", "[0, 5]", "[40000, 40000]",
    "[16384, 16384]", "[2.5, 3]", "{ a = 1 }", "[\"a\", \"b\"]", "1979-05-27", "0x10", "0.9069", "0.9068",
};

// Values at or near the edges of the documented ranges: most are accepted somewhere.
const std::vector<std::string> kEdgeValues = {
    "1e-60", "1e60", "1e-30", "1e30", "1e10", "-1e10", "1e-20", "0.00025", "2.5e-5", "0.0033333333333333335",
    "0.0025", "1152921504606846", "0.9", "0.45", "1e-17", "1e-9", "0.1", "20", "true", "false", "\"random\"",
    "\"lattice\"", "\"periodic\"", "\"lees-edwards\"", "[1e-30, 1e-30]", "[1e30, 1e30]", "[1.0, 1e-3]",
    "[3, 3]", "[16384, 16384]", "[1, 1]", "[[0, 1e300]]", "[[0.5, 0.6], [0, 1e9]]", "100000", "2", "4",
};

const std::vector<std::string> kBadOverrides = {
    "=1", "system.restitution", "system.=1", ".x=1", "a.b.c=1", "system.restitution=[", "system=1", "seed.x=1",
    "system.particles=1\nseed=2", "system.box=[1,", " =", "==", "system.restitution==0.5", "system.box.x=1",
    "system.particles=", "[system]=1", "run.until_collisions_per_particle=1e-300", "boundary.shear_velocity=1e300",
};

class Mutator {
 public:
  explicit Mutator(std::uint64_t seed) : rng_(seed) {}

  std::size_t below(std::size_t n) { return static_cast<std::size_t>(rng_() % n); }
  bool chance(double p) { return static_cast<double>(rng_() % 1000000) < p * 1e6; }
  template <class T>
  const T& pick(const std::vector<T>& items) { return items[below(items.size())]; }

  // Deletes, replaces or adds keys of the parsed table; records what it did in `log`.
  void mutate_table(toml::table& root, std::string& log) {
    const std::string key = chance(0.8) ? pick(kKeys) : pick(std::vector<std::string>{"system.colour", "seed2", "run.until", "nosuch.key"});
    const auto dot = key.find('.');
    toml::table* section = &root;
    std::string name = key;
    if (dot != std::string::npos) {
      const std::string section_name = key.substr(0, dot);
      name = key.substr(dot + 1);
      if (!root.contains(section_name)) root.insert(section_name, toml::table{});
      section = root.get(section_name)->as_table();
      if (!section) return;
    }
    if (chance(0.25)) {
      section->erase(name);
      log += " delete " + key + ";";
    } else {
      const std::string value = chance(0.4) ? pick(kEdgeValues) : pick(kHostileValues);
      const toml::table parsed = toml::parse("v = " + value);
      section->insert_or_assign(name, *parsed.get("v"));
      log += " " + key + " = " + value + ";";
    }
  }

  // Breaks the text: a duplicated line, a deleted or inserted character, truncation.
  void mutate_text(std::string& text, std::string& log) {
    if (text.empty()) return;
    const std::size_t at = below(text.size());
    switch (below(4)) {
      case 0: {
        const std::size_t start = text.rfind('\n', at) == std::string::npos ? 0 : text.rfind('\n', at) + 1;
        const std::size_t end = text.find('\n', at);
        const std::string line = text.substr(start, end == std::string::npos ? std::string::npos : end - start);
        text.insert(start, line + "\n");
        log += " duplicate line '" + line + "';";
        break;
      }
      case 1:
        text.erase(at, 1);
        log += " delete char " + std::to_string(at) + ";";
        break;
      case 2: {
        const std::string chars = "[]=\"'{}#\n.,x0-";
        text.insert(at, 1, chars[below(chars.size())]);
        log += " insert char at " + std::to_string(at) + ";";
        break;
      }
      default:
        text.resize(at);
        log += " truncate at " + std::to_string(at) + ";";
    }
  }

  std::string override_assignment() {
    if (chance(0.4)) return pick(kBadOverrides);
    return pick(kKeys) + "=" + pick(kHostileValues);
  }

 private:
  std::mt19937_64 rng_;
};

// A refusal must say what is wrong where: a key, a --set argument, or a TOML position.
bool names_a_key(const std::string& error) {
  for (const std::string& marker : {std::string("malformed TOML at line"), std::string("--set "),
                                    std::string("unknown section ["), std::string("unknown key "), std::string("unknown top-level key"),
                                    std::string("is a section")}) {
    if (error.find(marker) != std::string::npos) return true;
  }
  for (const auto& key : kKeys) {
    if (error.find(key) != std::string::npos) return true;
  }
  return false;
}

// The invariants of an accepted configuration; returns the first violated one ("" if none).
std::string violated_invariant(const RunConfig& c) {
  const SystemParams& s = c.system;
  const auto n = static_cast<double>(s.particles);
  const auto finite_in = [](double v, double low, double high) { return std::isfinite(v) && v >= low && v <= high; };
  if (s.particles < 2 || s.particles > 2147483647) return "N outside [2, 2^31 - 1]";
  if (!finite_in(s.length_x, 1e-30, 1e30) || !finite_in(s.length_y, 1e-30, 1e30)) return "box side outside [1e-30, 1e30]";
  if (!(std::isfinite(s.diameter) && s.diameter > 0.0)) return "diameter not finite positive";
  if (std::max(s.length_x, s.length_y) / s.diameter > 1e9 * (1.0 + 1e-12)) return "more than 1e9 diameters across the box";
  const double nu = M_PI * n * s.diameter * s.diameter / (4.0 * s.length_x * s.length_y);
  if (!(c.packing_fraction > 0.0 && c.packing_fraction < M_PI / (2.0 * std::sqrt(3.0)))) return "area fraction outside (0, close packing)";
  if (std::abs(c.packing_fraction - nu) > 1e-12 * nu) return "area fraction does not match N, σ and the box";
  if (!(s.restitution > 0.0 && s.restitution <= 1.0)) return "restitution outside (0, 1]";
  if (!finite_in(s.tc_duration, 0.0, INFINITY)) return "tc_duration not finite non-negative";
  if (!finite_in(c.initial_temperature, 1e-60, 1e60)) return "T_i outside [1e-60, 1e60]";
  const double u = std::abs(s.shear_velocity);
  if (u != 0.0 && (!c.lees_edwards || !finite_in(u, 1e-30, 1e30) || u > 1e10 * std::sqrt(c.initial_temperature) * (1.0 + 1e-12))) {
    return "shear velocity outside its range";
  }
  // Collision-count settings: whole counts of at least one collision (0 where it means "none"), at most 2^62.
  const auto count_ok = [&](double per_particle, bool zero_allowed) {
    if (zero_allowed && per_particle == 0.0) return true;
    return std::isfinite(per_particle) && per_particle * n <= 0x1p62 * (1.0 + 1e-12) && std::llround(per_particle * n) >= 1;
  };
  if (!c.until_collisions_per_particle && !c.until_time) return "no stop criterion";
  if (c.until_collisions_per_particle && !count_ok(*c.until_collisions_per_particle, false)) return "until count out of range";
  if (c.sample_every_collisions_per_particle.has_value() == c.sample_every_time.has_value()) return "not exactly one sample interval";
  if (c.sample_every_collisions_per_particle && !count_ok(*c.sample_every_collisions_per_particle, false)) return "sample interval count out of range";
  if (c.snapshot_every_collisions_per_particle && c.snapshot_every_time) return "two snapshot intervals";
  if (c.snapshot_every_collisions_per_particle && !count_ok(*c.snapshot_every_collisions_per_particle, true)) return "snapshot interval count out of range";
  if (c.fields.every_collisions_per_particle && c.fields.every_time) return "two fields intervals";
  if (c.fields.every_collisions_per_particle && !count_ok(*c.fields.every_collisions_per_particle, false)) return "fields interval count out of range";
  if (!count_ok(c.collisions.window_collisions_per_particle, false)) return "window count out of range";
  if (!count_ok(c.equilibrate, true)) return "equilibrate count out of range";
  if (!finite_in(c.collisions.from_collisions_per_particle * n, 0.0, 0x1p62 * (1.0 + 1e-12))) return "from count out of range";
  for (const auto& t : {c.until_time, c.sample_every_time, c.snapshot_every_time, c.fields.every_time}) {
    if (t && !(std::isfinite(*t) && *t > 0.0)) return "a time not finite positive";
  }
  if (!finite_in(c.particles_per_cell, 0.1, 20.0)) return "particles_per_cell outside [0.1, 20]";
  const CellGridChoice grid = choose_cell_grid(engine_grid_request(c));
  if (!grid.grid) return "no engine grid: " + grid.error;
  if (grid.grid->cell_count() > kMaxEngineCells) return "more than 2^28 engine cells";
  for (const auto& [nx, ny] : {c.diagnostic_cells, c.fields.cells}) {
    if (nx < 1 || ny < 1 || nx > 16384 || ny > 16384) return "coarse-graining grid outside [1, 16384]";
  }
  const CollisionStatisticsConfig& k = c.collisions;
  if (k.impact_bins < 2 || k.length_bins < 2 || k.angle_bins < 4) return "too few histogram bins";
  if (!(std::isfinite(k.max_length) && std::isnormal(k.max_length / k.length_bins))) return "free-path bins not normal";
  for (const auto& w : k.density_windows) {
    if (!(std::isfinite(w.low) && std::isfinite(w.high) && w.low >= 0.0 && w.low < w.high)) return "bad density window";
  }
  for (const auto& w : k.speed_windows) {
    if (!(std::isfinite(w.low) && std::isfinite(w.high) && w.low >= 0.0 && w.low < w.high)) return "bad speed window";
  }
  const std::string text = to_toml(c);
  const ConfigResult again = parse_config(text, {});
  if (!again.config) return "to_toml output refused: " + again.error;
  if (to_toml(*again.config) != text) return "to_toml round trip changed the configuration:\n" + text + "\n---\n" + to_toml(*again.config);
  return {};
}

TEST(ConfigFuzz, SeededMutationsNeverCrashAndValidResultsAreSound) {
  const std::vector<std::string> bases = {default_example_toml(), kLeesEdwardsBase, kMeasurementsBase};
  for (const auto& base : bases) ASSERT_TRUE(parse_config(base, {}).config) << "a base configuration is invalid";
  constexpr int kMutations = 5000;
  Mutator mutator(20240612);
  std::map<std::string, int> outcomes;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < kMutations; ++i) {
    std::string log = "case " + std::to_string(i) + ":";
    toml::table root = toml::parse(bases[i % bases.size()]);
    const std::size_t edits = 1 + mutator.below(2);
    for (std::size_t j = 0; j < edits; ++j) mutator.mutate_table(root, log);
    std::ostringstream serialised;
    serialised << root;
    std::string text = serialised.str();
    if (mutator.chance(0.3)) mutator.mutate_text(text, log);
    std::vector<std::string> overrides;
    if (mutator.chance(0.4)) {
      for (std::size_t j = 0, m = 1 + mutator.below(3); j < m; ++j) overrides.push_back(mutator.override_assignment());
      for (const auto& o : overrides) log += " --set '" + o + "';";
    }
    ConfigResult result;
    try {
      result = parse_config(text, overrides);
    } catch (const std::exception& error) {
      ADD_FAILURE() << log << " threw " << error.what();
      continue;
    } catch (...) {
      ADD_FAILURE() << log << " threw a non-standard exception";
      continue;
    }
    if (result.config) {
      const std::string broken = violated_invariant(*result.config);
      EXPECT_EQ(broken, "") << log;
      ++outcomes["accepted"];
    } else {
      EXPECT_TRUE(names_a_key(result.error)) << log << " refused without naming a key: " << result.error;
      ++outcomes[result.error.rfind("malformed TOML", 0) == 0 ? "refused: malformed TOML" : "refused: a key"];
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("config fuzz: %d mutations in %.2f s:", kMutations, seconds);
  for (const auto& [outcome, count] : outcomes) std::printf(" %s %d;", outcome.c_str(), count);
  std::printf("\n");
  // Both outcomes must be well represented, or the fuzzing tests little.
  EXPECT_GT(outcomes["accepted"], kMutations / 20);
  EXPECT_GT(outcomes["refused: a key"], kMutations / 4);
  EXPECT_LT(seconds, 10.0);
}

}  // namespace
}  // namespace granule
