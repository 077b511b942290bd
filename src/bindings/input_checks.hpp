// Checks of the bindings' inputs that the command line makes elsewhere: work too large for this
// machine is refused before anything is allocated, as `granule run` refuses a run (exit code 5),
// with Python's MemoryError; paths are taken as Python's open() takes them.
#pragma once

#include <pybind11/pybind11.h>

#include <stdexcept>
#include <string>

#include "io/config.hpp"

namespace granule::bindings {

// The refusal `granule run` makes of a run larger than the available memory
// (driver::check_run_memory), raised in Python as MemoryError (module.cpp registers the
// translation of driver::NotEnoughMemory); driver::require_memory refuses other work.
void require_memory_for_run(const RunConfig& config);

// The name of a value's type, for messages ("int", "ndarray").
std::string type_name(const pybind11::handle& value);

// The file-system bytes of a path given as str, bytes or os.PathLike (pathlib.Path); TypeError
// for anything else ("{argument} must be {expected} (str, …), not int"), ValueError for a NUL
// character (as open() does).
std::string path_argument(const pybind11::handle& path, const std::string& argument,
                          const std::string& expected = "a path");

}  // namespace granule::bindings
