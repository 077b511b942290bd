#include "bindings/input_checks.hpp"

#include <fmt/format.h>

#include "driver/run_beginnings.hpp"
#include "driver/run_start.hpp"

namespace granule::bindings {

namespace py = pybind11;

void require_memory_for_run(const RunConfig& config) { driver::check_run_memory(config, driver::run_cell_grid(config)); }

std::string type_name(const py::handle& value) {
  return py::str(py::type::handle_of(value).attr("__name__")).cast<std::string>();
}

std::string path_argument(const py::handle& path, const std::string& argument, const std::string& expected) {
  if (!py::isinstance<py::str>(path) && !py::isinstance<py::bytes>(path) && !py::hasattr(path, "__fspath__")) {
    throw py::type_error(fmt::format("{} must be {} (str, bytes or os.PathLike), not {}", argument, expected,
                                     type_name(path)));
  }
  const std::string bytes = py::module_::import("os").attr("fsencode")(path).cast<std::string>();
  if (bytes.find('\0') != std::string::npos) throw py::value_error(argument + ": the path holds a NUL character");
  return bytes;
}

}  // namespace granule::bindings
