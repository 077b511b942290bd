// A Python dict with the keys of a `granule run` TOML file, as TOML text, so
// that a configuration given as a dict goes through the same parser, validation
// and error messages as a file.
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "io/config.hpp"

namespace granule::bindings {

// Values: bool, int, float, str, list/tuple (TOML arrays, nested) and dict
// (tables).  Anything else raises ConfigError naming the key.
std::string toml_text_from_dict(const pybind11::dict& config);

// `config` is a dict or a path (str, pathlib.Path); `overrides` are `--set` strings.  Throws
// ConfigError with the command line's message.
RunConfig run_config_from_python(const pybind11::object& config, const std::vector<std::string>& overrides);

}  // namespace granule::bindings
