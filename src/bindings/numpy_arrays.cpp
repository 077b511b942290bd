#include "bindings/numpy_arrays.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "bindings/input_checks.hpp"
#include "io/input_ranges.hpp"

namespace granule::bindings {

namespace py = pybind11;

namespace {

// The largest ratio of two box sides: the engine's largest L/σ (io/input_ranges.hpp).  It keeps
// the default field grid (about 20 particles a cell, cells as square as the box allows) to
// counts of cells an int holds.
constexpr double kMaxBoxAspect = kMaxBoxOverDiameter;

Array finished(Array array) {
  py::detail::array_proxy(array.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return array;
}

// `value` as a NumPy array (a view where it is one) of `dimensions` axes holding real numbers.
py::array real_array(const py::object& value, const char* name, int dimensions) {
  const py::array array = py::module_::import("numpy").attr("asarray")(value);
  const char kind = array.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u') {
    throw py::type_error(fmt::format("{} must hold real numbers (a float or int dtype), not {}", name,
                                     py::str(array.dtype()).cast<std::string>()));
  }
  if (array.ndim() != dimensions) {
    throw py::value_error(fmt::format("{} must be a {}-D array, not {}-D", name, dimensions, array.ndim()));
  }
  return array;
}

// The values of a checked array as contiguous doubles (the copy is made here, after the caller's
// memory check).
Array doubles(const py::array& array) {
  Array converted = Array::ensure(array);
  if (!converted) throw py::type_error("an array could not be converted to float64");
  return converted;
}

}  // namespace

Array read_only_columns(const std::vector<const std::vector<double>*>& columns) {
  const std::size_t n = columns.front()->size();
  const std::size_t d = columns.size();
  Array array({static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(d)});
  auto out = array.mutable_unchecked<2>();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t a = 0; a < d; ++a) out(i, a) = (*columns[a])[i];
  }
  return finished(std::move(array));
}

Array read_only_vector(const std::vector<double>& values) {
  Array array(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), array.mutable_data());
  return finished(std::move(array));
}

ConfigurationArrays configuration_arrays(const py::object& positions, const py::object& velocities,
                                         const py::object& masses) {
  ConfigurationArrays arrays;
  arrays.positions = real_array(positions, "positions", 2);
  if (arrays.positions.shape(1) != 2 && arrays.positions.shape(1) != 3) {
    throw py::value_error(fmt::format("positions must be an N × 2 or N × 3 array, not N × {}", arrays.positions.shape(1)));
  }
  arrays.particles = static_cast<std::size_t>(arrays.positions.shape(0));
  arrays.dimension = static_cast<int>(arrays.positions.shape(1));
  arrays.velocities = real_array(velocities, "velocities", 2);
  if (arrays.velocities.shape(0) != arrays.positions.shape(0) || arrays.velocities.shape(1) != arrays.positions.shape(1)) {
    throw py::value_error(fmt::format("velocities must have the shape of positions, {} × {}, not {} × {}",
                                      arrays.positions.shape(0), arrays.positions.shape(1), arrays.velocities.shape(0),
                                      arrays.velocities.shape(1)));
  }
  arrays.masses = masses;
  if (!masses.is_none()) {
    const py::array m = real_array(masses, "masses", 1);
    if (static_cast<std::size_t>(m.shape(0)) != arrays.particles) {
      throw py::value_error(fmt::format("masses must have N = {} entries, not {}", arrays.particles, m.shape(0)));
    }
    arrays.masses = m;
  }
  return arrays;
}

std::vector<std::vector<double>> particle_columns(const py::object& value, const char* name, std::size_t particles,
                                                  int columns, bool positive) {
  const py::array array = real_array(value, name, columns == 1 ? 1 : 2);
  if (static_cast<std::size_t>(array.shape(0)) != particles || (columns > 1 && array.shape(1) != columns)) {
    throw py::value_error(columns == 1 ? fmt::format("{} must have N = {} entries, not {}", name, particles, array.shape(0))
                                       : fmt::format("{} must be an N × {} array (N = {}), not {} × {}", name, columns,
                                                     particles, array.shape(0), array.shape(1)));
  }
  const Array values = doubles(array);
  const double* data = values.data();
  std::vector<std::vector<double>> out(static_cast<std::size_t>(columns), std::vector<double>(particles));
  for (std::size_t i = 0; i < particles; ++i) {
    for (std::size_t c = 0; c < out.size(); ++c) {
      const double v = data[i * out.size() + c];
      if (!std::isfinite(v) || (positive && !(v > 0.0))) {
        throw py::value_error(fmt::format("{}[{}{}] = {}: must be {}finite", name, i, columns > 1 ? fmt::format(", {}", c) : "",
                                          v, positive ? "positive and " : ""));
      }
      out[c][i] = v;
    }
  }
  return out;
}

Box box_argument(const py::object& box, int dimension) {
  const py::array lengths = real_array(box, "box", 1);
  if (lengths.shape(0) != dimension) {
    throw py::value_error(fmt::format("box must have one length per axis of positions ({}), not {}", dimension,
                                      lengths.shape(0)));
  }
  const Array values = doubles(lengths);
  const double* l = values.data();
  for (int a = 0; a < dimension; ++a) {
    if (!kLengthRange.contains(l[a])) {
      throw py::value_error(fmt::format("box[{}] = {}: a box length must be in {}", a, l[a], kLengthRange.text()));
    }
  }
  const auto [shortest, longest] = std::minmax_element(l, l + dimension);
  if (*longest > kMaxBoxAspect * *shortest) {
    throw py::value_error(fmt::format("box sides {} and {}: they must be within a factor {:g} of one another",
                                      *shortest, *longest, kMaxBoxAspect));
  }
  return {l[0], l[1], dimension == 3 ? l[2] : 1.0};
}

ParticleState particle_state(const ConfigurationArrays& arrays, const Box& box) {
  ParticleState state;
  state.dimension = arrays.dimension;
  const std::size_t n = arrays.particles;
  state.resize(n);
  const Array positions = doubles(arrays.positions);
  const Array velocities = doubles(arrays.velocities);
  const auto r = positions.unchecked<2>();
  const auto v = velocities.unchecked<2>();
  const double lengths[3] = {box.length_x, box.length_y, box.length_z};
  const char* axes = "xyz";
  std::vector<double>* position_columns[3] = {&state.x, &state.y, &state.z};
  std::vector<double>* velocity_columns[3] = {&state.vx, &state.vy, &state.vz};
  for (std::size_t i = 0; i < n; ++i) {
    const auto row = static_cast<py::ssize_t>(i);
    for (int a = 0; a < state.dimension; ++a) {
      // [0, L] closed: np.mod(x, L) may round a small negative x up to L.
      if (!(r(row, a) >= 0.0 && r(row, a) <= lengths[a])) {
        throw py::value_error(fmt::format("positions[{}, {}] = {}: positions must be finite and inside the box, "
                                          "0 ≤ {} ≤ {} (wrap them with numpy.mod(positions, box))",
                                          i, a, r(row, a), axes[a], lengths[a]));
      }
      if (!std::isfinite(v(row, a))) {
        throw py::value_error(fmt::format("velocities[{}, {}] = {}: velocities must be finite", i, a, v(row, a)));
      }
      (*position_columns[a])[i] = r(row, a);
      (*velocity_columns[a])[i] = v(row, a);
    }
  }
  if (!arrays.masses.is_none()) {
    const Array masses = doubles(arrays.masses.cast<py::array>());
    const double* m = masses.data();
    for (std::size_t i = 0; i < n; ++i) {
      if (!(std::isfinite(m[i]) && m[i] > 0.0)) {
        throw py::value_error(fmt::format("masses[{}] = {}: masses must be positive and finite", i, m[i]));
      }
    }
    state.mass.assign(m, m + n);
  }
  return state;
}

}  // namespace granule::bindings
