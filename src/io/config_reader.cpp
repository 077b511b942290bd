#include "io/config_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <sstream>

namespace granule {

// A value as the user wrote it, numbers in their shortest exact form ("1e+300", not the
// 17 digits toml++ prints).
std::string toml_value_text(const toml::node& node) {
  if (node.is_floating_point()) return fmt::format("{}", *node.value<double>());
  if (node.is_string()) return '"' + node.value_or(std::string{}) + '"';
  if (node.is_table()) return "a table";
  if (const toml::array* array = node.as_array()) {
    std::string out;
    for (const toml::node& item : *array) out += (out.empty() ? "" : ", ") + toml_value_text(item);
    return "[" + out + "]";
  }
  std::ostringstream out;
  out << toml::node_view<const toml::node>{node};
  return out.str();
}

namespace {

std::string join(const std::set<std::string>& items) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

std::string section_list(const ConfigSchema& schema) {
  std::string out;
  for (const auto& [name, keys] : schema) {
    if (!name.empty()) out += (out.empty() ? "" : ", ") + name;
  }
  return out;
}

}  // namespace

void ConfigReader::check_known_keys(const ConfigSchema& schema) const {
  for (const auto& [key, node] : root_) {
    const std::string name{key.str()};
    const auto section = schema.find(name);
    const bool is_section = !name.empty() && section != schema.end();
    if (is_section && !node.is_table()) {
      throw ConfigError{fmt::format("{} = {} is not allowed: [{}] is a section (a table of keys)", name,
                                    toml_value_text(node), name)};
    }
    if (node.is_table()) {
      if (!is_section) {
        throw ConfigError{fmt::format("unknown section [{}]; allowed sections: {}", name, section_list(schema))};
      }
      for (const auto& [inner, value] : *node.as_table()) {
        const std::string inner_name{inner.str()};
        if (!section->second.count(inner_name)) {
          throw ConfigError{fmt::format("unknown key {}.{} (value {}); allowed keys in [{}]: {}", name, inner_name,
                                        toml_value_text(value), name, join(section->second))};
        }
      }
    } else if (!schema.at("").count(name)) {
      throw ConfigError{fmt::format("unknown top-level key {} (value {}); allowed: {}, or a section such as [system]",
                                    name, toml_value_text(node), join(schema.at("")))};
    }
  }
}

const toml::node* ConfigReader::find(const std::string& path) const {
  // "section.key" or, inside an inline table, "section.table.key".
  const toml::table* table = &root_;
  std::size_t start = 0;
  for (auto dot = path.find('.'); dot != std::string::npos; dot = path.find('.', start)) {
    const toml::node* inner = table->get(path.substr(start, dot - start));
    if (!inner || !inner->is_table()) return nullptr;
    table = inner->as_table();
    start = dot + 1;
  }
  return table->get(path.substr(start));
}

std::vector<std::pair<double, double>> ConfigReader::number_pairs(const std::string& path, const std::string& what) const {
  const toml::node* node = find(path);
  std::vector<std::pair<double, double>> out;
  if (!node) return out;
  const auto fail = [&] {
    return ConfigError{fmt::format("{} = {} is not allowed: expected a non-empty list of points [{}, ...] of finite numbers",
                                   path, toml_value_text(*node), what)};
  };
  const toml::array* list = node->as_array();
  if (!list || list->empty()) throw fail();
  for (const toml::node& item : *list) {
    const toml::array* pair = item.as_array();
    if (!pair || pair->size() != 2) throw fail();
    const auto a = (*pair)[0].value<double>();
    const auto b = (*pair)[1].value<double>();
    if (!a || !b || !std::isfinite(*a) || !std::isfinite(*b)) throw fail();
    out.emplace_back(*a + 0.0, *b + 0.0);
  }
  return out;
}

bool ConfigReader::table_with_keys(const std::string& path, const std::set<std::string>& allowed) const {
  const toml::node* node = find(path);
  if (!node) return false;
  if (!node->is_table()) {
    throw ConfigError{fmt::format("{} = {} is not allowed: expected a table {{ {} }}", path, toml_value_text(*node), join(allowed))};
  }
  for (const auto& [key, value] : *node->as_table()) {
    if (!allowed.count(std::string{key.str()})) {
      throw ConfigError{fmt::format("unknown key {}.{} (value {}); allowed keys: {}", path, key.str(), toml_value_text(value),
                                    join(allowed))};
    }
  }
  return true;
}

std::optional<double> ConfigReader::number(const std::string& path, const NumberRange& range,
                                           const std::string& why) const {
  return number_if(path, [&](double value) { return range.contains(value); }, range.text() + why);
}

std::optional<double> ConfigReader::number_if(const std::string& path, const std::function<bool(double)>& allowed,
                                              const std::string& allowed_text) const {
  const toml::node* node = find(path);
  if (!node) return std::nullopt;
  const auto value = node->value<double>();
  if (!value || !std::isfinite(*value) || !allowed(*value)) {
    throw ConfigError{fmt::format("{} = {} is out of range: allowed {}", path, toml_value_text(*node), allowed_text)};
  }
  return *value + 0.0;  // -0.0 is 0 (and written as 0 by to_toml)
}

std::optional<std::int64_t> ConfigReader::integer(const std::string& path, std::int64_t low, std::int64_t high) const {
  const toml::node* node = find(path);
  if (!node) return std::nullopt;
  const auto value = node->is_integer() ? node->value<std::int64_t>() : std::nullopt;
  if (!value || *value < low || *value > high) {
    throw ConfigError{fmt::format("{} = {} is not allowed: expected an integer in [{}, {}]", path, toml_value_text(*node), low, high)};
  }
  return value;
}

std::optional<std::string> ConfigReader::text(const std::string& path, const std::set<std::string>& allowed) const {
  const toml::node* node = find(path);
  if (!node) return std::nullopt;
  const auto value = node->value<std::string>();
  if (!value || !allowed.count(*value)) {
    throw ConfigError{fmt::format("{} = {} is not allowed: expected one of {}", path, toml_value_text(*node), join(allowed))};
  }
  return value;
}

std::optional<std::string> ConfigReader::path_text(const std::string& path) const {
  const toml::node* node = find(path);
  if (!node) return std::nullopt;
  const auto value = node->value<std::string>();
  if (!value || value->empty()) {
    throw ConfigError{fmt::format("{} = {} is not allowed: expected a non-empty string (a path)", path, toml_value_text(*node))};
  }
  return value;
}

std::optional<std::vector<double>> ConfigReader::number_list(const std::string& path, std::size_t count,
                                                           const NumberRange& range, const std::string& shape,
                                                           const std::string& why) const {
  const toml::node* node = find(path);
  if (!node) return std::nullopt;
  std::vector<double> out;
  if (const toml::array* array = node->as_array(); array && array->size() == count) {
    for (const toml::node& item : *array) {
      const auto value = item.value<double>();
      if (!value || !range.contains(*value)) break;
      out.push_back(*value + 0.0);
    }
  }
  if (out.size() == count) return out;
  const char* const counts[] = {"no", "one number", "two numbers", "three numbers"};
  throw ConfigError{fmt::format("{} = {} is not allowed: expected {} ({} in {}){}", path, toml_value_text(*node), shape,
                                count < 4 ? counts[count] : "numbers", range.text(), why)};
}

bool ConfigReader::holds_text(const std::string& path) const {
  const toml::node* node = find(path);
  return node && node->is_string();
}

bool ConfigReader::holds_list(const std::string& path) const {
  const toml::node* node = find(path);
  return node && node->is_array();
}

std::optional<std::vector<std::string>> ConfigReader::text_list(const std::string& path, const std::set<std::string>& allowed,
                                                                const std::string& why) const {
  const toml::node* node = find(path);
  if (!node) return std::nullopt;
  std::vector<std::string> out;
  const toml::array* array = node->as_array();
  for (std::size_t k = 0; array && k < array->size(); ++k) {
    const auto value = (*array)[k].value<std::string>();
    if (!value || !allowed.count(*value) || std::find(out.begin(), out.end(), *value) != out.end()) break;
    out.push_back(*value);
  }
  if (array && !out.empty() && out.size() == array->size()) return out;
  throw ConfigError{fmt::format("{} = {} is not allowed: expected a non-empty list of distinct names among {}{}", path,
                                toml_value_text(*node), join(allowed), why)};
}

std::optional<bool> ConfigReader::boolean(const std::string& path) const {
  const toml::node* node = find(path);
  if (!node) return std::nullopt;
  if (!node->is_boolean()) throw ConfigError{fmt::format("{} = {} is not allowed: expected true or false", path, toml_value_text(*node))};
  return node->value<bool>();
}

std::vector<std::pair<double, double>> ConfigReader::windows(const std::string& path) const {
  const toml::node* node = find(path);
  std::vector<std::pair<double, double>> out;
  if (!node) return out;
  const toml::array* list = node->as_array();
  const auto fail = [&] {
    return ConfigError{fmt::format("{} = {} is not allowed: expected a list of windows [[low, high], ...] with "
                                   "0 <= low < high, both finite", path, toml_value_text(*node))};
  };
  if (!list) throw fail();
  for (const toml::node& item : *list) {
    const toml::array* pair = item.as_array();
    if (!pair || pair->size() != 2) throw fail();
    const auto low = (*pair)[0].value<double>();
    const auto high = (*pair)[1].value<double>();
    if (!low || !high || !NumberRange{0.0, kUnbounded}.contains(*low) || !std::isfinite(*high) || !(*low < *high)) {
      throw fail();
    }
    out.emplace_back(*low + 0.0, *high + 0.0);  // no negative zero
  }
  return out;
}

std::optional<std::pair<int, int>> ConfigReader::int_pair(const std::string& path, int low, int high) const {
  const toml::node* node = find(path);
  if (!node) return std::nullopt;
  const toml::array* array = node->as_array();
  if (array && array->size() == 2 && (*array)[0].is_integer() && (*array)[1].is_integer()) {
    const auto a = *(*array)[0].value<std::int64_t>();
    const auto b = *(*array)[1].value<std::int64_t>();
    if (a >= low && a <= high && b >= low && b <= high) return std::pair{static_cast<int>(a), static_cast<int>(b)};
  }
  throw ConfigError{fmt::format("{} = {} is not allowed: expected [nx, ny] with integers in [{}, {}]", path,
                                toml_value_text(*node), low, high)};
}

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
  if (parsed.size() != 1 || !parsed.get("v")) {
    throw ConfigError{fmt::format("--set {}: the value must be a single TOML value", assignment)};
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

}  // namespace granule
