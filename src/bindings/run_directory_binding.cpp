// granule.run_directory: a whole `granule run` into a directory through the driver's RunSession,
// the library the command line uses — the same files (but the picture, which the command line
// draws), checkpoints that `granule run --resume` continues, the [fields] and [collisions]
// measurements.
#include <pybind11/stl.h>

#include <csignal>

#include "bindings/bindings.hpp"
#include "bindings/interactive_run.hpp"
#include "bindings/toml_from_dict.hpp"
#include "driver/run_session.hpp"
#include "driver/run_start.hpp"
#include "io/atomic_file.hpp"

namespace granule::bindings {

namespace py = pybind11;

namespace {

volatile std::sig_atomic_t interrupt_flag = 0;

extern "C" void raise_interrupt_flag(int signal) { interrupt_flag = signal; }

// While a session runs without the GIL, SIGINT raises the engine's stop flag (checked before
// each event), as the command line's handler does; Python's handler comes back afterwards.
class SigintToFlag {
 public:
  SigintToFlag() {
    interrupt_flag = 0;
    struct sigaction action {};
    action.sa_handler = raise_interrupt_flag;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &previous_);
  }
  ~SigintToFlag() { sigaction(SIGINT, &previous_, nullptr); }
  SigintToFlag(const SigintToFlag&) = delete;
  SigintToFlag& operator=(const SigintToFlag&) = delete;

 private:
  struct sigaction previous_ {};
};

template <int D>
nlohmann::json run_session(const RunConfig& config, const std::string& out) {
  const CellGrid grid = driver::run_cell_grid(config);
  const driver::RunStart start = driver::run_start(config);
  write_file_atomically(out + "/config.toml", to_toml(config));
  driver::RunSession<D> session(config, grid, out, start);
  const SigintToFlag signals;
  return session.finish(session.run(&interrupt_flag));
}

// `out` exists and is empty (python/granule/__init__.py checks it).
py::object run_directory(const py::object& config, const std::string& out, const std::vector<std::string>& overrides) {
  const RunConfig parsed = run_config_from_python(config, overrides);
  nlohmann::json summary;
  {
    py::gil_scoped_release release;
    summary = parsed.system.dimension == 3 ? run_session<3>(parsed, out) : run_session<2>(parsed, out);
  }
  if (interrupt_flag != 0) {
    PyErr_SetNone(PyExc_KeyboardInterrupt);
    throw py::error_already_set();
  }
  return py::module_::import("json").attr("loads")(summary.dump());
}

}  // namespace

void bind_run_directory(py::module_& m) {
  m.def("_run_directory", &run_directory, py::arg("config"), py::arg("out"),
        py::arg("overrides") = std::vector<std::string>{});
}

}  // namespace granule::bindings
