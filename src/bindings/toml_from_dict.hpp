// A Python dict with the keys of a `granule run` TOML file, as TOML text, so
// that a configuration given as a dict goes through the same parser, validation
// and error messages as a file.
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "io/config.hpp"

namespace granule::bindings {

// Values: bool, int (64-bit), float, str, list/tuple (TOML arrays, nested), dict (tables) and
// NumPy's bool, integer and floating scalars.  Refused, naming the key path: another type or a
// non-str key (TypeError), an int beyond 64 bits (OverflowError), a dict or list that contains
// itself or nesting deeper than 64 levels (ValueError).
std::string toml_text_from_dict(const pybind11::dict& config);

// `config` is a dict or a path (str, bytes, os.PathLike); `overrides` are `--set` strings.  A
// path that cannot be read raises the OSError open() would (FileNotFoundError, IsADirectoryError,
// PermissionError); anything but a regular file of a configuration's size, and a configuration
// the command line refuses, raise ConfigError with the command line's message.
RunConfig run_config_from_python(const pybind11::object& config, const std::vector<std::string>& overrides);

}  // namespace granule::bindings
