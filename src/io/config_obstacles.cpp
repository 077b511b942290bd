#include "io/config_obstacles.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "io/config_reader.hpp"
#include "io/input_ranges.hpp"
#include "io/system_checks.hpp"

namespace granule {

namespace {

constexpr const char* kKey = "obstacles";
// Files of obstacles are read whole: a row of pegs or a porous bed is thousands, not millions.
constexpr std::size_t kMostObstacles = 1'000'000;

std::string entry_name(std::size_t k) { return fmt::format("{}[{}]", kKey, k); }

// A number of entry k, in `range`, or nothing when the key is absent.
std::optional<double> number_of(const toml::table& entry, std::size_t k, const char* key, const NumberRange& range,
                                const std::string& why = {}) {
  const toml::node* node = entry.get(key);
  if (!node) return std::nullopt;
  const std::optional<double> value = node->value<double>();
  if (!value || !range.contains(*value)) {
    throw ConfigError{fmt::format("{}.{} = {} is not allowed: a number in {}{}", entry_name(k), key, toml_value_text(*node),
                                  range.text(), why)};
  }
  return value;
}

}  // namespace

std::vector<Obstacle> read_obstacle_csv(const std::string& path, int dimension) {
  std::ifstream file(path);
  if (!file) throw ConfigError{fmt::format("cannot read the obstacle file {}", path)};
  std::string line;
  if (!std::getline(file, line)) throw ConfigError{fmt::format("{}: empty, expected a header line x,y{},diameter", path, dimension == 3 ? ",z" : "")};
  std::vector<std::string> columns;
  {
    std::stringstream header(line);
    for (std::string name; std::getline(header, name, ',');) {
      name.erase(std::remove_if(name.begin(), name.end(), [](unsigned char ch) { return std::isspace(ch); }), name.end());
      columns.push_back(name);
    }
  }
  std::vector<std::string> wanted{"x", "y"};
  if (dimension == 3) wanted.push_back("z");
  wanted.push_back("diameter");
  std::vector<std::size_t> at;
  for (const std::string& name : wanted) {
    const auto found = std::find(columns.begin(), columns.end(), name);
    if (found == columns.end()) {
      throw ConfigError{fmt::format("{}: line 1 has no column \"{}\" (expected a header naming x, y{}, diameter)", path, name,
                                    dimension == 3 ? ", z" : "")};
    }
    at.push_back(static_cast<std::size_t>(found - columns.begin()));
  }
  std::vector<Obstacle> obstacles;
  for (std::size_t number = 2; std::getline(file, line); ++number) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    if (obstacles.size() == kMostObstacles) throw ConfigError{fmt::format("{}: more than {} obstacles", path, kMostObstacles)};
    std::vector<std::string> cells;
    std::stringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    Obstacle o;
    for (std::size_t w = 0; w < wanted.size(); ++w) {
      double value = NAN;
      std::size_t used = 0;
      try {
        value = at[w] < cells.size() ? std::stod(cells[at[w]], &used) : NAN;
      } catch (const std::exception&) {
        value = NAN;
      }
      const bool rest_blank = at[w] < cells.size() && cells[at[w]].find_first_not_of(" \t\r", used) == std::string::npos;
      if (!std::isfinite(value) || !rest_blank) {
        throw ConfigError{fmt::format("{}: line {}, column {} (\"{}\") is not a finite number", path, number, at[w] + 1, wanted[w])};
      }
      if (w + 1 == wanted.size()) {
        o.diameter = value;
      } else {
        o.centre[w] = value;
      }
    }
    obstacles.push_back(o);
  }
  if (obstacles.empty()) throw ConfigError{fmt::format("{}: no obstacles after the header", path)};
  return obstacles;
}

void resolve_obstacles(const toml::table& root, RunConfig& c) {
  const toml::node* node = root.get(kKey);
  if (!node) return;
  const toml::array* entries = node->as_array();
  if (!entries || !entries->is_array_of_tables()) {
    throw ConfigError{fmt::format("{} must be an array of tables, one [[obstacles]] per obstacle (or file of them)", kKey)};
  }
  SystemParams& s = c.system;
  if (c.lees_edwards) {
    throw ConfigError{"[[obstacles]] cannot be combined with boundary.kind = \"lees-edwards\": an obstacle is fixed in the lab, "
                      "while the images of the sheared box slide at ±U, so its images would move through the flow. A "
                      "shear past obstacles is a wall-driven flow: boundary.kind = \"walls\" with wall_axes = [\"y\"] and "
                      "shear_velocity"};
  }
  for (std::size_t k = 0; k < entries->size(); ++k) {
    const toml::table& entry = *entries->get(k)->as_table();
    const std::string where = entry_name(k);
    for (const auto& [key, value] : entry) {
      static const std::set<std::string> kKeys{"centre", "diameter", "file", "restitution", "tangential_restitution"};
      if (!kKeys.count(std::string(key.str()))) {
        throw ConfigError{fmt::format("unknown key {}.{} (value {}); allowed: centre, diameter (or file), restitution, "
                                      "tangential_restitution", where, key.str(), toml_value_text(value))};
      }
    }
    const double e = number_of(entry, k, "restitution", kRestitutions).value_or(1.0);
    const double beta = number_of(entry, k, "tangential_restitution", kTangentialRestitutions, " (−1 smooth, +1 perfectly rough)")
                            .value_or(-1.0);
    std::vector<Obstacle> given;
    if (const toml::node* file = entry.get("file")) {
      if (entry.get("centre") || entry.get("diameter")) {
        throw ConfigError{fmt::format("{} has a file and a centre or diameter: give one obstacle, or a file of them", where)};
      }
      const std::optional<std::string> path = file->value<std::string>();
      if (!path || path->empty()) throw ConfigError{fmt::format("{}.file = {} is not allowed: a path to a CSV file", where, toml_value_text(*file))};
      given = read_obstacle_csv(*path, s.dimension);
    } else {
      Obstacle o;
      const toml::node* centre = entry.get("centre");
      const toml::array* values = centre ? centre->as_array() : nullptr;
      if (!values || values->size() != static_cast<std::size_t>(s.dimension)) {
        throw ConfigError{fmt::format("{} needs centre = [x, y{}] ({} numbers for system.dimension = {}){}", where,
                                      s.dimension == 3 ? ", z" : "", s.dimension, s.dimension,
                                      centre ? fmt::format(", not {}", toml_value_text(*centre)) : "")};
      }
      for (std::size_t a = 0; a < values->size(); ++a) {
        const std::optional<double> v = values->get(a)->value<double>();
        if (!v || !std::isfinite(*v)) throw ConfigError{fmt::format("{}.centre = {} is not allowed: finite numbers", where, toml_value_text(*centre))};
        o.centre[a] = *v;
      }
      const std::optional<double> diameter = number_of(entry, k, "diameter", kLengthRange);
      if (!diameter) throw ConfigError{fmt::format("{} needs diameter = D in {}", where, kLengthRange.text())};
      o.diameter = *diameter;
      given.push_back(o);
    }
    for (std::size_t m = 0; m < given.size(); ++m) {
      Obstacle& o = given[m];
      o.restitution = e;
      o.tangential_restitution = beta;
      // The rules a snapshot's obstacles are checked by too: in the box, narrower than it less a grain
      // along a periodic axis (never touching its own image), a diameter > 0.
      const std::string name = entry.get("file") ? fmt::format("{}: obstacle {} of the file", where, m + 1) : where;
      if (const std::vector<std::string> problems = obstacle_problems(o, s, name); !problems.empty()) throw ConfigError{problems.front()};
      if (s.obstacles.size() == kMostObstacles) throw ConfigError{fmt::format("more than {} obstacles", kMostObstacles)};
      s.obstacles.push_back(o);
    }
  }
}

std::string obstacles_to_toml(const RunConfig& c) {
  std::string out;
  for (const Obstacle& o : c.system.obstacles) {
    std::string centre = fmt::format("{:.17g}, {:.17g}", o.centre[0], o.centre[1]);
    if (c.system.dimension == 3) centre += fmt::format(", {:.17g}", o.centre[2]);
    out += fmt::format("\n[[obstacles]]\ncentre = [{}]\ndiameter = {:.17g}\nrestitution = {:.17g}\ntangential_restitution = {:.17g}\n",
                       centre, o.diameter, o.restitution, o.tangential_restitution);
  }
  return out;
}

}  // namespace granule
