// granule.run_directory: a whole `granule run` into a directory through the driver's RunSession,
// the library the command line uses — the same files (but the picture, which the command line
// draws), checkpoints that `granule run --resume` continues, the [fields] and [collisions]
// measurements.
#include <pybind11/stl.h>

#include <csignal>
#include <filesystem>
#include <mutex>
#include <set>
#include <stdexcept>

#include "bindings/bindings.hpp"
#include "bindings/input_checks.hpp"
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

// While sessions run without the GIL, SIGINT raises the engine's stop flag (checked before each
// event), as the command line's handler does; Python's handler comes back when the last running
// session of the process ends.  Sessions run from several threads share the handler and the flag, so
// Ctrl-C stops every one of them.
class SigintToFlag {
 public:
  SigintToFlag() {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (sessions_++ > 0) return;
    interrupt_flag = 0;
    struct sigaction action {};
    action.sa_handler = raise_interrupt_flag;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &previous_);
  }
  ~SigintToFlag() {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (--sessions_ == 0) sigaction(SIGINT, &previous_, nullptr);
  }
  SigintToFlag(const SigintToFlag&) = delete;
  SigintToFlag& operator=(const SigintToFlag&) = delete;

 private:
  static inline std::mutex mutex_;
  static inline int sessions_ = 0;
  static inline struct sigaction previous_ {};
};

// A run directory is written by one session, and only when it is empty: checked here, under the
// lock, so that two threads given the same directory cannot both find it empty.  A directory in
// use raises RuntimeError, one with files FileExistsError.
class DirectoryInUse {
 public:
  explicit DirectoryInUse(const std::string& out) : key_(std::filesystem::weakly_canonical(out).string()) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (in_use_.count(key_) > 0) throw std::runtime_error(out + " is being written by run_directory in another thread");
    std::error_code error;
    if (!std::filesystem::is_empty(out, error) && !error) {
      PyErr_SetString(PyExc_FileExistsError, (out + " holds files: a run directory must be empty").c_str());
      throw py::error_already_set();
    }
    in_use_.insert(key_);
  }
  ~DirectoryInUse() {
    const std::lock_guard<std::mutex> lock(mutex_);
    in_use_.erase(key_);
  }
  DirectoryInUse(const DirectoryInUse&) = delete;
  DirectoryInUse& operator=(const DirectoryInUse&) = delete;

 private:
  static inline std::mutex mutex_;
  static inline std::set<std::string> in_use_;
  std::string key_;
};

template <int D>
nlohmann::json run_session(const RunConfig& config, const std::string& out) {
  // From the start: a Ctrl-C while the initial state is made stops the run before its first event.
  const SigintToFlag signals;
  const CellGrid grid = driver::run_cell_grid(config);
  const driver::RunStart start = driver::run_start(config);
  write_file_atomically(out + "/config.toml", to_toml(config));
  driver::RunSession<D> session(config, grid, out, start);
  return session.finish(session.run(&interrupt_flag));
}

// `out` exists (python/granule/__init__.py creates it).
py::object run_directory(const py::object& config, const py::object& out_path, const std::vector<std::string>& overrides) {
  const RunConfig parsed = run_config_from_python(config, overrides);
  require_memory_for_run(parsed);
  const std::string out = path_argument(out_path, "out");
  const DirectoryInUse claim(out);
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
