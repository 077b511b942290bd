// A Python dict with the keys of a `granule run` TOML file, as TOML text, so
// that a configuration given as a dict goes through the same parser, validation
// and error messages as a file.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

namespace granule::bindings {

// Values: bool, int, float, str, list/tuple (TOML arrays, nested) and dict
// (tables).  Anything else raises ConfigError naming the key.
std::string toml_text_from_dict(const pybind11::dict& config);

}  // namespace granule::bindings
