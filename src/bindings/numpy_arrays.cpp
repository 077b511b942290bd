#include "bindings/numpy_arrays.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace granule::bindings {

namespace py = pybind11;

namespace {

Array finished(Array array) {
  py::detail::array_proxy(array.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return array;
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

ParticleState particle_state(const Array& positions, const Array& velocities, const py::object& masses) {
  if (positions.ndim() != 2 || (positions.shape(1) != 2 && positions.shape(1) != 3)) {
    throw std::invalid_argument("positions must be an N × 2 or N × 3 array");
  }
  if (velocities.ndim() != 2 || velocities.shape(0) != positions.shape(0) ||
      velocities.shape(1) != positions.shape(1)) {
    throw std::invalid_argument("velocities must have the shape of positions");
  }
  ParticleState state;
  state.dimension = static_cast<int>(positions.shape(1));
  const auto n = static_cast<std::size_t>(positions.shape(0));
  state.resize(n);
  const auto r = positions.unchecked<2>();
  const auto v = velocities.unchecked<2>();
  std::vector<double>* position_columns[3] = {&state.x, &state.y, &state.z};
  std::vector<double>* velocity_columns[3] = {&state.vx, &state.vy, &state.vz};
  for (std::size_t i = 0; i < n; ++i) {
    for (int a = 0; a < state.dimension; ++a) {
      (*position_columns[a])[i] = r(static_cast<py::ssize_t>(i), a);
      (*velocity_columns[a])[i] = v(static_cast<py::ssize_t>(i), a);
    }
  }
  if (!masses.is_none()) {
    const auto m = masses.cast<Array>();
    if (m.ndim() != 1 || static_cast<std::size_t>(m.shape(0)) != n) {
      throw std::invalid_argument(fmt::format("masses must have N = {} entries", n));
    }
    state.mass.assign(m.data(), m.data() + n);
  }
  return state;
}

}  // namespace granule::bindings
