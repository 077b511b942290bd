// The compiled part of the Python package granule (python/granule/__init__.py
// re-exports it).
#include <pybind11/pybind11.h>

#include "bindings/bindings.hpp"
#include "bindings/input_checks.hpp"
#include "bindings/interactive_run.hpp"
#include "driver/run_beginnings.hpp"
#include "granule/version.hpp"

PYBIND11_MODULE(_granule, m) {
  namespace py = pybind11;
  m.doc() =
      "Granule's engine, analyses and theory (event-driven MD of "
      "inelastic hard disks and spheres, Tan 1995)";
  m.attr("__version__") = granule::kVersion;
  // ValueError, so that code catching bad values catches bad configurations
  // too.
  py::register_exception<granule::bindings::ConfigError>(m, "ConfigError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const granule::driver::NotEnoughMemory& refused) {
      PyErr_SetString(PyExc_MemoryError, refused.what());
    }
  });
  granule::bindings::bind_simulation(m);
  granule::bindings::bind_analysis(m);
  granule::bindings::bind_theory(m);
  granule::bindings::bind_run_directory(m);
}
