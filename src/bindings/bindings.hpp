// The parts of the Python extension `granule._granule`, each registered on the
// module by its own file (module.cpp calls them in order).
#pragma once

#include <pybind11/pybind11.h>

namespace granule::bindings {

void bind_simulation(pybind11::module_& m);     // Simulation (simulation_binding.cpp)
void bind_analysis(pybind11::module_& m);       // cell_fields, spectra (analysis_binding.cpp)
void bind_theory(pybind11::module_& m);         // the submodule theory (theory_binding.cpp)
void bind_run_directory(pybind11::module_& m);  // _run_directory (run_directory_binding.cpp)

}  // namespace granule::bindings
