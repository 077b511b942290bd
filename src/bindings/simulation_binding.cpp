// granule.Simulation: one run of disks or spheres, stepped from Python
// (bindings/interactive_run.hpp).
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <stdexcept>
#include <variant>

#include "bindings/bindings.hpp"
#include "bindings/input_checks.hpp"
#include "bindings/interactive_run.hpp"
#include "bindings/numpy_arrays.hpp"
#include "bindings/toml_from_dict.hpp"

namespace granule::bindings {

namespace py = pybind11;

namespace {

// Asked between chunks of a run, with the GIL released around the chunks: a
// pending Ctrl-C (or any other Python signal handler that raised) stops the run
// after a whole chunk.
bool no_pending_signal() {
  py::gil_scoped_acquire gil;
  return PyErr_CheckSignals() == 0;
}

class PySimulation {
 public:
  PySimulation(const py::object& config, const std::vector<std::string>& overrides) {
    const RunConfig parsed = run_config_from_python(config, overrides);
    require_memory_for_run(parsed);
    if (parsed.system.dimension == 3) {
      run_ = std::make_unique<InteractiveRun<3>>(parsed);
    } else {
      run_ = std::make_unique<InteractiveRun<2>>(parsed);
    }
    last_reason_ = with_gil_released([](auto& run) { return run.equilibrate(no_pending_signal); });
  }

  template <typename F>
  auto visit(F&& f) const {
    return std::visit([&](const auto& run) { return f(*run); }, run_);
  }
  template <typename F>
  auto visit_engine(F&& f) const {
    return visit([&](const auto& run) { return f(run.engine()); });
  }

  std::string run(const RunLimits& limits) {
    const RunTargets targets = visit([&](const auto& run) { return run.targets(limits); });
    const Running running(running_);
    last_reason_ = with_gil_released([&](auto& run) { return run.run(targets, no_pending_signal); });
    return driver::stop_text(last_reason_);
  }

  ParticleState state() const {
    return visit_engine([](const auto& sim) { return sim.state(); });
  }
  int dimension() const {
    return visit_engine([](const auto& sim) { return sim.params().dimension; });
  }
  StopReason last_reason() const { return last_reason_; }
  bool running() const { return running_; }

 private:
  // Marks the engine busy while run() drives it without the GIL.  Set and read with the GIL held,
  // so that a second thread (or a signal handler between chunks) sees it.
  class Running {
   public:
    explicit Running(bool& flag) : flag_(flag) { flag_ = true; }
    ~Running() { flag_ = false; }
    Running(const Running&) = delete;
    Running& operator=(const Running&) = delete;

   private:
    bool& flag_;
  };

  // Runs `f` on the run; a pending Python exception (KeyboardInterrupt) is
  // raised afterwards.
  template <typename F>
  StopReason with_gil_released(F&& f) {
    StopReason reason;
    {
      py::gil_scoped_release release;
      reason = std::visit([&](auto& run) { return f(*run); }, run_);
    }
    if (PyErr_Occurred()) throw py::error_already_set();
    return reason;
  }

  std::variant<std::unique_ptr<InteractiveRun<2>>, std::unique_ptr<InteractiveRun<3>>> run_;
  StopReason last_reason_ = StopReason::kCollisionsReached;
  bool running_ = false;
};

// The Simulation a method is called on, when nothing else uses its engine.  A Simulation runs
// with the GIL released, so any other thread may call it meanwhile: every method refuses then
// (RuntimeError) rather than read or step an engine that is moving.  The check also refuses an
// object whose __init__ never ran (Simulation.__new__(Simulation)), whose C++ part does not exist.
PySimulation& simulation_of(py::handle self) {
  if (!py::isinstance<PySimulation>(self)) {
    throw py::type_error(fmt::format("a method of granule.Simulation called on a {}", type_name(self)));
  }
  auto* instance = reinterpret_cast<py::detail::instance*>(self.ptr());
  const py::detail::value_and_holder holder =
      instance->get_value_and_holder(py::detail::get_type_info(typeid(PySimulation)));
  if (!holder.holder_constructed()) {
    throw py::type_error("this granule.Simulation was never initialised (its __init__ did not run)");
  }
  PySimulation& simulation = *holder.value_ptr<PySimulation>();
  if (simulation.running()) {
    throw std::runtime_error(
        "Simulation is being run from another thread (or this is a signal handler during its run()): "
        "its engine is not available until that run() returns; one Simulation runs one call at a time");
  }
  return simulation;
}

// A method or property of the Simulation `self`: `f(simulation)` or `f(engine)` (Simulation<D>).
template <typename F>
auto on_simulation(F f) {
  return [f](py::handle self) { return f(simulation_of(self)); };
}
template <typename F>
auto on_engine(F f) {
  return on_simulation([f](const PySimulation& s) { return s.visit_engine(f); });
}

Array positions(const PySimulation& s) {
  const ParticleState state = s.state();
  return s.dimension() == 3 ? read_only_columns({&state.x, &state.y, &state.z})
                            : read_only_columns({&state.x, &state.y});
}

Array velocities(const PySimulation& s) {
  const ParticleState state = s.state();
  return s.dimension() == 3 ? read_only_columns({&state.vx, &state.vy, &state.vz})
                            : read_only_columns({&state.vx, &state.vy});
}

// σ_i and m_i of every particle (a monodisperse run: σ and unit masses).
Array diameters(const PySimulation& s) {
  const ParticleState state = s.state();
  if (state.polydisperse()) return read_only_vector(state.diameter);
  return read_only_vector(
      std::vector<double>(state.size(), s.visit_engine([](const auto& sim) { return sim.params().diameter; })));
}

Array masses(const PySimulation& s) {
  const ParticleState state = s.state();
  return read_only_vector(state.polydisperse() ? state.mass : std::vector<double>(state.size(), 1.0));
}

// ω_z (N,) of disks, (ω_x, ω_y, ω_z) (N × 3) of spheres; None for smooth
// grains.
py::object spins(const PySimulation& s) {
  const ParticleState state = s.state();
  if (!state.rough()) return py::none();
  if (state.dimension == 3) return read_only_columns({&state.wx, &state.wy, &state.wz});
  return read_only_vector(state.wz);
}

py::dict row_dict(const DiagnosticsSample& sample) {
  py::dict row;
  for_each_column(sample, [&](const auto& name, const double& value) { row[py::str(std::string(name))] = value; });
  return row;
}

// Column name → array over the rows of the time series.
py::dict timeseries(const PySimulation& s) {
  return s.visit([](const auto& run) {
    py::dict columns;
    const auto& samples = run.samples();
    for_each_column(samples.front(), [&](const auto& name, const double&) {
      std::vector<double> column;
      column.reserve(samples.size());
      for (const DiagnosticsSample& sample : samples) {
        for_each_column(sample, [&](const auto& other, const double& value) {
          if (std::string(other) == std::string(name)) column.push_back(value);
        });
      }
      columns[py::str(std::string(name))] = read_only_vector(column);
    });
    return columns;
  });
}

py::object json_to_python(const nlohmann::json& json) { return py::module_::import("json").attr("loads")(json.dump()); }

}  // namespace

void bind_simulation(py::module_& m) {
  py::class_<PySimulation>(m, "Simulation", R"doc(
One run of inelastic hard disks or spheres, as `granule run` would make it from the same
configuration, stepped from Python.

``config`` is the path of a TOML file or a dict with the same keys (``{"system": {"particles":
1000}, "seed": 3}``); ``overrides`` are ``--set`` strings ("system.restitution=0.8").  A bad
configuration raises granule.ConfigError with the command line's message (key, value, allowed
range).  A path that cannot be read raises FileNotFoundError, IsADirectoryError or
PermissionError.  A dict's values are bool, int, float, str, list, tuple, dict or NumPy scalars;
another type raises TypeError, an int beyond 64 bits OverflowError, a dict or list that contains
itself or nests deeper than 64 levels ValueError, each naming the key.  A run needing more memory
than is available raises MemoryError before anything is allocated, as ``granule run`` refuses it.

Construction makes the initial state as ``granule run`` does (a frame of an earlier run with
``initial.from``, else the state of thesis §1.4.2) and runs the elastic pre-run
(``initial.equilibrate``); production starts at t = 0, c = 0.  The trajectory equals that of
``granule run`` for the same configuration and seed, bit for bit: the engine's does not depend on
where it is stopped.

The particle arrays are computed on access: the engine stores each particle at the time of its
own last event, so the state of one moment is extrapolated (positions in the box, lab velocities)
into fresh read-only NumPy arrays; nothing is shared with the engine.  Read them once per stop.
)doc")
      .def(py::init<const py::object&, const std::vector<std::string>&>(), py::arg("config"),
           py::arg("overrides") = std::vector<std::string>{})
      .def(
          "run",
          [](py::handle self, std::optional<double> until_collisions_per_particle, std::optional<double> until_time) {
            return simulation_of(self).run({until_collisions_per_particle, until_time});
          },
          py::arg("until_collisions_per_particle") = py::none(), py::arg("until_time") = py::none(),
          R"doc(
Run to the first of the limits, absolute since production started (c = total collisions / N, and
t).  The limits given replace the configuration's run.until_*, which apply when neither is given.
Returns why it stopped ("collisions reached", "time reached", "no further events", "inelastic
collapse").

A limit must be a finite number: c in [1/N, 2^62/N] (the engine counts collisions in 64 bits) and
t > 0.  A limit the run has reached already (c or t at or below the present value) raises
ValueError with the present c or t: such a run would do nothing.

The GIL is released while the engine runs; Ctrl-C stops it after the current chunk of
max(1000, N/4) collisions or within 0.1 s, whichever comes first (the state stays consistent and
can be run further), and raises KeyboardInterrupt.  The time series gains its scheduled rows (output.every_*) and a last row at
the stop.  While one thread runs a Simulation, every call of that Simulation from another thread
raises RuntimeError (it does not wait): one Simulation serves one call at a time.
)doc")
      .def_property_readonly("dimension", on_simulation([](const PySimulation& s) { return s.dimension(); }))
      .def_property_readonly("particles", on_engine([](const auto& sim) { return sim.params().particles; }))
      .def_property_readonly("time", on_engine([](const auto& sim) { return sim.time(); }))
      .def_property_readonly("collisions", on_engine([](const auto& sim) { return sim.collisions(); }))
      .def_property_readonly("events", on_engine([](const auto& sim) { return sim.events(); }))
      .def_property_readonly("collisions_per_particle",
                             on_engine([](const auto& sim) { return sim.collisions_per_particle(); }))
      .def_property_readonly("shear_velocity", on_engine([](const auto& sim) { return sim.image_velocity(); }),
                             "U(t), the velocity of the upper Lees–Edwards images now (0 in a periodic box)")
      .def_property_readonly("shear_offset", on_engine([](const auto& sim) { return sim.shear_offset(); }),
                             "Δ(t) ∈ [0, L_x), the Lees–Edwards image offset now")
      .def_property_readonly("box", on_engine([](const auto& sim) {
                               const SystemParams& p = sim.params();
                               return p.dimension == 3 ? py::make_tuple(p.length_x, p.length_y, p.length_z)
                                                       : py::make_tuple(p.length_x, p.length_y);
                             }))
      .def_property_readonly("positions", on_simulation(&positions),
                             "N × d lab positions now, in [0, L) per axis (a computed copy)")
      .def_property_readonly("velocities", on_simulation(&velocities), "N × d lab velocities now (a computed copy)")
      .def_property_readonly("diameters", on_simulation(&diameters),
                             "σ_i (N,): drawn per particle when polydisperse, else σ")
      .def_property_readonly("masses", on_simulation(&masses), "m_i (N,): mean 1 when polydisperse, else 1")
      .def_property_readonly("spins", on_simulation(&spins),
                             "angular velocities of rough grains now: ω_z (N,) of disks, N × 3 of spheres; None "
                             "when smooth")
      .def_property_readonly("timeseries", on_simulation(&timeseries),
                             "the time series so far: column name → array, the columns of timeseries.csv")
      .def_property_readonly(
          "timeseries_row",
          on_simulation([](const PySimulation& s) {
            return s.visit([](const auto& run) { return row_dict(run.samples().back()); });
          }),
          "the latest row of the time series (at the last stop of run()) as a dict")
      .def_property_readonly(
          "config_toml",
          on_simulation([](const PySimulation& s) { return s.visit([](const auto& run) { return to_toml(run.config()); }); }),
          "the fully resolved configuration as TOML: `granule run` of it makes the same run")
      .def("summary",
           on_simulation([](const PySimulation& s) {
             return s.visit([&](const auto& run) { return json_to_python(run.summary(s.last_reason())); });
           }),
           "summary.json's content for the run so far (dict)")
      .def(
          "write_snapshot",
          [](py::handle self, const py::object& path) {
            const PySimulation& s = simulation_of(self);
            const std::string file = path_argument(path, "path");
            s.visit([&](const auto& run) { run.write_snapshot(file); });
          },
          py::arg("path"),
          "Append the present state as a frame of a snapshots.h5 file (created when missing; schema of "
          "`granule run`'s), readable by `granule analyze`, `granule plot` and h5py");
}

}  // namespace granule::bindings
