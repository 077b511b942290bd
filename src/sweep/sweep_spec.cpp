#include "sweep/sweep_spec.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>

#include "io/config.hpp"
#include "io/config_reader.hpp"

namespace granule::sweep {

namespace {

struct SpecError {
  std::string message;
};

// One swept key and its values, in the order written.
struct Axis {
  std::string key;
  std::vector<PointSetting> values;
};

// The `--set` text of a value: toml++ prints numbers with 17 digits, so the run reads back
// exactly the double of the spec, and keeps integers integers.
std::string exact_toml(const toml::node& node) {
  std::ostringstream out;
  out << toml::node_view<const toml::node>{node};
  return out.str();
}

std::string readable_value(const toml::node& node) {
  return node.is_string() ? node.value_or(std::string{}) : toml_value_text(node);
}

// [sweep] keys may be written dotted (`system.restitution = [...]`, a nested table in TOML) or
// quoted (`"system.restitution" = [...]`): both name the config key system.restitution.
void collect_axes(const toml::table& table, const std::string& prefix, std::vector<Axis>& axes) {
  for (const auto& [name, node] : table) {
    const std::string key = prefix + std::string{name.str()};
    if (prefix.empty() && (key == "zip" || key == "seeds")) continue;
    if (const toml::table* inner = node.as_table()) {
      collect_axes(*inner, key + ".", axes);
      continue;
    }
    const toml::array* list = node.as_array();
    if (list == nullptr || list->empty()) {
      throw SpecError{
          fmt::format("[sweep] {} = {}: expected a non-empty list of the values to run", key, toml_value_text(node))};
    }
    Axis axis{key, {}};
    for (const toml::node& item : *list) axis.values.push_back({key, exact_toml(item), readable_value(item)});
    axes.push_back(std::move(axis));
  }
}

// [sweep] seeds: a list of seeds, or a count n meaning the base seed and the n − 1 after it.
Axis seed_axis(const toml::node& node, const toml::table& root) {
  const auto fail = [&] {
    return SpecError{
        fmt::format("[sweep] seeds = {}: expected a count (an integer ≥ 1) or a non-empty list of distinct "
                    "seeds (integers in [0, 2^63))",
                    toml_value_text(node))};
  };
  std::vector<std::int64_t> seeds;
  if (const auto count = node.value_exact<std::int64_t>()) {
    if (*count < 1 || *count > 1000000) throw fail();
    const std::int64_t base = root["seed"].value_or<std::int64_t>(1);
    if (base < 0 || base > INT64_MAX - *count) throw fail();
    for (std::int64_t k = 0; k < *count; ++k) seeds.push_back(base + k);
  } else if (const toml::array* list = node.as_array(); list != nullptr && !list->empty()) {
    for (const toml::node& item : *list) {
      const auto seed = item.value_exact<std::int64_t>();
      if (!seed || *seed < 0 || std::count(seeds.begin(), seeds.end(), *seed) > 0) throw fail();
      seeds.push_back(*seed);
    }
  } else {
    throw fail();
  }
  Axis axis{"seed", {}};
  for (const std::int64_t seed : seeds) axis.values.push_back({"seed", std::to_string(seed), std::to_string(seed)});
  return axis;
}

// [sweep] zip: true (every key varies together) or the list of keys that do; the others, and the
// seeds, form the Cartesian product with them.
std::set<std::string> zipped_keys(const toml::node* zip, const std::vector<Axis>& axes) {
  std::set<std::string> keys;
  if (zip == nullptr) return keys;
  const auto fail = [&] {
    return SpecError{
        fmt::format("[sweep] zip = {}: expected true, false or a list of the swept keys that vary together",
                    toml_value_text(*zip))};
  };
  if (const auto all = zip->value_exact<bool>()) {
    if (*all) {
      for (const Axis& axis : axes) keys.insert(axis.key);
    }
  } else if (const toml::array* list = zip->as_array()) {
    for (const toml::node& item : *list) {
      const auto key = item.value_exact<std::string>();
      if (!key) throw fail();
      if (std::none_of(axes.begin(), axes.end(), [&](const Axis& a) { return a.key == *key; })) {
        throw SpecError{fmt::format("[sweep] zip names {}, which is not a swept key of [sweep]", *key)};
      }
      keys.insert(*key);
    }
  } else {
    throw fail();
  }
  const Axis* first = nullptr;
  for (const Axis& axis : axes) {
    if (!keys.count(axis.key)) continue;
    if (first != nullptr && axis.values.size() != first->values.size()) {
      throw SpecError{
          fmt::format("[sweep] zip: {} has {} values and {} has {}: keys that vary together need lists of one "
                      "length",
                      first->key, first->values.size(), axis.key, axis.values.size())};
    }
    if (first == nullptr) first = &axis;
  }
  return keys;
}

// A factor of the product: one axis, or the zipped axes that step together.
struct Factor {
  std::vector<const Axis*> axes;
  std::size_t size() const { return axes.front()->values.size(); }
};

std::vector<Factor> product_factors(const std::vector<Axis>& axes, const std::set<std::string>& zipped) {
  std::vector<Factor> factors;
  std::size_t zip_factor = SIZE_MAX;
  for (const Axis& axis : axes) {
    if (!zipped.count(axis.key)) {
      factors.push_back({{&axis}});
    } else if (zip_factor == SIZE_MAX) {
      zip_factor = factors.size();
      factors.push_back({{&axis}});
    } else {
      factors[zip_factor].axes.push_back(&axis);
    }
  }
  return factors;
}

// A value in a directory name: letters, digits and . , + - _ only (brackets, quotes and spaces of
// lists and strings are dropped, anything else becomes _).
std::string name_safe(const std::string& value) {
  std::string out;
  for (const char ch : value) {
    if (std::isalnum(static_cast<unsigned char>(ch)) || std::string_view(".,+-_").find(ch) != std::string_view::npos) {
      out += ch;
    } else if (std::string_view("[]\"' ").find(ch) == std::string_view::npos) {
      out += '_';
    }
  }
  return out.empty() ? "_" : out;
}

// The label of each key in point names: its last part ("restitution"), or the whole key with
// dots as - when two swept keys end alike (system.x and boundary.x).
std::map<std::string, std::string> key_labels(const std::vector<Axis>& axes) {
  std::map<std::string, int> uses;
  const auto last_part = [](const std::string& key) { return key.substr(key.rfind('.') + 1); };
  for (const Axis& axis : axes) ++uses[last_part(axis.key)];
  std::map<std::string, std::string> labels;
  for (const Axis& axis : axes) {
    std::string label = uses[last_part(axis.key)] > 1 ? axis.key : last_part(axis.key);
    std::replace(label.begin(), label.end(), '.', '-');
    labels[axis.key] = label;
  }
  return labels;
}

constexpr std::size_t kMaxNameLength = 200;  // below the 255 bytes of a file name, with room for suffixes

std::vector<SweepPoint> expand(const std::vector<Axis>& axes, const std::set<std::string>& zipped) {
  const std::vector<Factor> factors = product_factors(axes, zipped);
  const std::map<std::string, std::string> labels = key_labels(axes);
  std::size_t count = 1;
  for (const Factor& f : factors) count *= f.size();
  if (count > 1000000)
    throw SpecError{fmt::format("[sweep] gives {} points, more than the 10^6 a sweep may have", count)};
  std::vector<SweepPoint> points;
  std::map<std::string, std::size_t> names;
  for (std::size_t index = 0; index < count; ++index) {
    // The first factor varies slowest, as nested loops in the order of the keys.
    std::vector<std::size_t> choice(factors.size());
    std::size_t rest = index;
    for (std::size_t f = factors.size(); f-- > 0;) {
      choice[f] = rest % factors[f].size();
      rest /= factors[f].size();
    }
    SweepPoint point;
    for (const Axis& axis : axes) {
      for (std::size_t f = 0; f < factors.size(); ++f) {
        const auto& members = factors[f].axes;
        if (std::find(members.begin(), members.end(), &axis) != members.end())
          point.settings.push_back(axis.values[choice[f]]);
      }
    }
    for (const PointSetting& s : point.settings) {
      point.name += (point.name.empty() ? "" : "__") + labels.at(s.key) + "=" + name_safe(s.readable);
    }
    if (point.name.size() > kMaxNameLength) {
      throw SpecError{
          fmt::format("[sweep] point {} has a directory name of {} characters, more than {}: sweep fewer keys "
                      "or shorter values",
                      point.name, point.name.size(), kMaxNameLength)};
    }
    if (const auto [it, fresh] = names.emplace(point.name, index); !fresh) {
      throw SpecError{
          fmt::format("[sweep] points {} and {} both get the directory name {}: their values differ only in "
                      "characters a file name cannot hold",
                      it->second + 1, index + 1, point.name)};
    }
    points.push_back(std::move(point));
  }
  return points;
}

std::string formatted(const toml::table& table) {
  std::ostringstream out;
  out << toml::toml_formatter{table} << '\n';
  return out.str();
}

SweepSpec build(const std::string& text) {
  toml::table root;
  try {
    root = toml::parse(text);
  } catch (const toml::parse_error& error) {
    throw SpecError{fmt::format("malformed TOML at line {}, column {}: {}", error.source().begin.line,
                                error.source().begin.column, error.description())};
  }
  const toml::table* table = root["sweep"].as_table();
  if (table == nullptr) {
    throw SpecError{"the spec has no [sweep] table of keys → lists of values (for a single run use granule run)"};
  }
  std::vector<Axis> axes;
  collect_axes(*table, "", axes);
  const std::set<std::string> zipped = zipped_keys(table->get("zip"), axes);
  if (const toml::node* seeds = table->get("seeds")) {
    if (std::any_of(axes.begin(), axes.end(), [](const Axis& a) { return a.key == "seed"; })) {
      throw SpecError{"[sweep] has both seed and seeds: give the seeds once"};
    }
    axes.push_back(seed_axis(*seeds, root));
  }
  if (axes.empty()) throw SpecError{"[sweep] names no key to vary and no seeds"};

  SweepSpec spec;
  spec.canonical_toml = formatted(root);
  root.erase("sweep");
  spec.base_toml = formatted(root);
  for (const Axis& axis : axes) spec.keys.push_back(axis.key);
  spec.points = expand(axes, zipped);
  for (const SweepPoint& point : spec.points) {
    const ConfigResult checked = parse_config(spec.base_toml, point.overrides());
    if (!checked.config) throw SpecError{fmt::format("[sweep] point {}: {}", point.name, checked.error)};
  }
  return spec;
}

}  // namespace

std::vector<std::string> SweepPoint::overrides() const {
  std::vector<std::string> out;
  for (const PointSetting& s : settings) out.push_back(s.key + "=" + s.toml);
  return out;
}

SweepSpecResult parse_sweep_spec(const std::string& text) {
  try {
    return {build(text), {}};
  } catch (const SpecError& error) {
    return {std::nullopt, error.message};
  }
}

SweepSpecResult load_sweep_spec(const std::string& path) {
  std::ifstream file(path);
  if (!file) return {std::nullopt, "cannot read the sweep spec " + path};
  SweepSpecResult result = parse_sweep_spec({std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()});
  if (!result.spec) result.error = path + ": " + result.error;
  return result;
}

}  // namespace granule::sweep
