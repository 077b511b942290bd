// Checks of the bindings' inputs that the command line makes elsewhere: work too large for this
// machine is refused before anything is allocated, as `granule run` refuses a run (exit code 5),
// with Python's MemoryError; paths are taken as Python's open() takes them.
#pragma once

#include <pybind11/pybind11.h>

#include <stdexcept>
#include <string>

#include "io/config.hpp"

namespace granule::bindings {

// Raised in Python as MemoryError (module.cpp registers the translation).
struct MemoryRefused : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Throws MemoryRefused, with the estimate and what is available, when `needed_bytes` exceed the
// available memory (driver::available_memory_bytes; nothing is refused where it cannot be read).
// `what` names the work: "a run of N = 1000".
void require_memory(double needed_bytes, const std::string& what);

// The estimate `granule run` makes of a run's peak memory (driver::estimated_run_bytes).
void require_memory_for_run(const RunConfig& config);

// The name of a value's type, for messages ("int", "ndarray").
std::string type_name(const pybind11::handle& value);

// The file-system bytes of a path given as str, bytes or os.PathLike (pathlib.Path); TypeError
// for anything else ("{argument} must be {expected} (str, …), not int"), ValueError for a NUL
// character (as open() does).
std::string path_argument(const pybind11::handle& path, const std::string& argument,
                          const std::string& expected = "a path");

}  // namespace granule::bindings
