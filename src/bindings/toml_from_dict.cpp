#include "bindings/toml_from_dict.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <sstream>
#include <variant>

#include "bindings/interactive_run.hpp"

namespace granule::bindings {

namespace py = pybind11;

namespace {

toml::table table_from_dict(const py::dict& dict, const std::string& prefix);

using TomlValue = std::variant<bool, std::int64_t, double, std::string, toml::table, toml::array>;

// The TOML value of `value` (the key path `where` names it in errors).
TomlValue convert(py::handle value, const std::string& where) {
  // bool before int: Python's True is an int too.
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
  if (py::isinstance<py::int_>(value)) return value.cast<std::int64_t>();
  if (py::isinstance<py::float_>(value)) return value.cast<double>();
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::dict>(value)) return table_from_dict(value.cast<py::dict>(), where + ".");
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    toml::array array;
    for (py::handle item : value) std::visit([&](auto&& v) { array.push_back(std::move(v)); }, convert(item, where));
    return array;
  }
  throw ConfigError(fmt::format("{}: a {} is not a TOML value (bool, int, float, str, list or dict)", where,
                                py::str(value.get_type().attr("__name__")).cast<std::string>()));
}

toml::table table_from_dict(const py::dict& dict, const std::string& prefix) {
  toml::table table;
  for (const auto& [key, value] : dict) {
    if (!py::isinstance<py::str>(key))
      throw ConfigError(fmt::format("{}: keys must be strings", prefix.empty() ? "config" : prefix));
    const std::string name = key.cast<std::string>();
    std::visit([&](auto&& v) { table.insert(name, std::move(v)); }, convert(value, prefix + name));
  }
  return table;
}

}  // namespace

std::string toml_text_from_dict(const py::dict& config) {
  std::ostringstream text;
  text << table_from_dict(config, "");
  return text.str();
}

RunConfig run_config_from_python(const py::object& config, const std::vector<std::string>& overrides) {
  if (py::isinstance<py::dict>(config))
    return parse_run_config(toml_text_from_dict(config.cast<py::dict>()), overrides);
  return load_run_config(py::str(config).cast<std::string>(), overrides);
}

}  // namespace granule::bindings
