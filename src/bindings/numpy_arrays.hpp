// NumPy arrays from and to the per-particle columns of ParticleState (x, y, z,
// v…): the engine keeps one record per particle at its clock base, along its present flight, so
// the arrays of one moment are computed, and handed out as read-only copies.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <vector>

#include "engine/system_params.hpp"

namespace granule::bindings {

using Array = pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>;

// An N × columns array of the given columns (each of N values), read-only.
Array read_only_columns(const std::vector<const std::vector<double>*>& columns);
// A 1-D read-only array.
Array read_only_vector(const std::vector<double>& values);

// N × d positions and velocities (d = 2 or 3) and optional masses (N,) as a
// ParticleState for the analyses; throws std::invalid_argument on inconsistent
// shapes.
ParticleState particle_state(const Array& positions, const Array& velocities, const pybind11::object& masses);

}  // namespace granule::bindings
