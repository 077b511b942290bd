// NumPy arrays from and to the per-particle columns of ParticleState (x, y, z,
// v…): the engine keeps one record per particle at its clock base, along its present flight, so
// the arrays of one moment are computed, and handed out as read-only copies.  Arrays handed in
// are checked (dtype, shape, values) before they are copied, so that no input reaches the
// analyses that they could not take.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <vector>

#include "engine/system_params.hpp"

namespace granule::bindings {

using Array = pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>;

// An N × columns array of the given columns (each of N values), read-only.
Array read_only_columns(const std::vector<const std::vector<double>*>& columns);
// A 1-D read-only array.
Array read_only_vector(const std::vector<double>& values);

// The box of a configuration, (L_x, L_y) or (L_x, L_y, L_z).
struct Box {
  double length_x = 1.0;
  double length_y = 1.0;
  double length_z = 1.0;  // 1 in 2D
};

// The arrays of one configuration, their shapes and dtypes checked, nothing copied yet: N × d
// positions (d = 2 or 3), velocities of the same shape, masses (N,) or None.  Each holds real
// numbers (a float, int or uint dtype; TypeError otherwise, naming it); a wrong shape raises
// ValueError.
struct ConfigurationArrays {
  pybind11::array positions;
  pybind11::array velocities;
  pybind11::object masses;  // a 1-D array, or None
  std::size_t particles = 0;
  int dimension = 2;
};
ConfigurationArrays configuration_arrays(const pybind11::object& positions, const pybind11::object& velocities,
                                         const pybind11::object& masses);

// `box` as one length per axis, each in the engine's range of lengths [1e-30, 1e30] and within a
// factor 1e9 (its largest L/σ) of the others: ValueError otherwise.
Box box_argument(const pybind11::object& box, int dimension);

// A per-particle array as `columns` columns of N finite numbers (positive when `positive`): shape (N,)
// for one column, (N, columns) for more.  TypeError for a dtype that is not real, ValueError naming
// `name` and the first bad entry.
std::vector<std::vector<double>> particle_columns(const pybind11::object& value, const char* name, std::size_t particles,
                                                  int columns, bool positive);

// The bytes an analysis holds per particle at the most (the copies below and the ParticleState;
// the analyses count their own arrays), for the memory check made before copying.
inline constexpr double kAnalysisBytesPerParticle = 256.0;

// The configuration as a ParticleState for the analyses.  ValueError, naming the array and the
// first bad particle, for a value that is not finite, a position outside [0, L] on its axis, a
// mass that is not positive.
ParticleState particle_state(const ConfigurationArrays& arrays, const Box& box);

}  // namespace granule::bindings
