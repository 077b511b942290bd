// granule.Simulation: one run of disks or spheres, stepped from Python
// (bindings/interactive_run.hpp).
#include <pybind11/stl.h>

#include <variant>

#include "bindings/bindings.hpp"
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
    if (parsed.system.dimension == 3) {
      run_ = std::make_unique<InteractiveRun<3>>(parsed);
    } else {
      run_ = std::make_unique<InteractiveRun<2>>(parsed);
    }
    last_reason_ = with_gil_released([](auto& run) { return run.equilibrate(no_pending_signal); });
  }

  std::string run(std::optional<double> until_collisions_per_particle, std::optional<double> until_time) {
    const RunLimits limits{until_collisions_per_particle, until_time};
    last_reason_ = with_gil_released([&](auto& run) { return run.run(limits, no_pending_signal); });
    return driver::stop_text(last_reason_);
  }

  template <typename F>
  auto visit(F&& f) const {
    return std::visit([&](const auto& run) { return f(*run); }, run_);
  }
  template <typename F>
  auto visit_engine(F&& f) const {
    return visit([&](const auto& run) { return f(run.engine()); });
  }

  ParticleState state() const {
    return visit_engine([](const auto& sim) { return sim.state(); });
  }
  int dimension() const {
    return visit_engine([](const auto& sim) { return sim.params().dimension; });
  }
  StopReason last_reason() const { return last_reason_; }

 private:
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
};

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
range).

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
      .def("run", &PySimulation::run, py::arg("until_collisions_per_particle") = py::none(),
           py::arg("until_time") = py::none(),
           R"doc(
Run to the first of the limits, absolute since production started (c = total collisions / N, and
t); without either, to the configuration's run.until_*.  Returns why it stopped ("collisions
reached", "time reached", "no further events", "inelastic collapse").  The GIL is released while
the engine runs; Ctrl-C stops it after the current chunk of max(1000, N/4) collisions (the state
stays consistent and can be run further) and raises KeyboardInterrupt.  The time series gains its
scheduled rows (output.every_*) and a last row at the stop.
)doc")
      .def_property_readonly("dimension", &PySimulation::dimension)
      .def_property_readonly(
          "particles",
          [](const PySimulation& s) { return s.visit_engine([](const auto& sim) { return sim.params().particles; }); })
      .def_property_readonly(
          "time", [](const PySimulation& s) { return s.visit_engine([](const auto& sim) { return sim.time(); }); })
      .def_property_readonly(
          "collisions",
          [](const PySimulation& s) { return s.visit_engine([](const auto& sim) { return sim.collisions(); }); })
      .def_property_readonly(
          "events", [](const PySimulation& s) { return s.visit_engine([](const auto& sim) { return sim.events(); }); })
      .def_property_readonly("collisions_per_particle",
                             [](const PySimulation& s) {
                               return s.visit_engine([](const auto& sim) { return sim.collisions_per_particle(); });
                             })
      .def_property_readonly(
          "shear_velocity",
          [](const PySimulation& s) { return s.visit_engine([](const auto& sim) { return sim.image_velocity(); }); },
          "U(t), the velocity of the upper Lees–Edwards images now (0 in a "
          "periodic box)")
      .def_property_readonly(
          "shear_offset",
          [](const PySimulation& s) { return s.visit_engine([](const auto& sim) { return sim.shear_offset(); }); },
          "Δ(t) ∈ [0, L_x), the Lees–Edwards image offset now")
      .def_property_readonly("box",
                             [](const PySimulation& s) {
                               return s.visit_engine([](const auto& sim) {
                                 const SystemParams& p = sim.params();
                                 return p.dimension == 3 ? py::make_tuple(p.length_x, p.length_y, p.length_z)
                                                         : py::make_tuple(p.length_x, p.length_y);
                               });
                             })
      .def_property_readonly("positions", &positions, "N × d lab positions now, in [0, L) per axis (a computed copy)")
      .def_property_readonly("velocities", &velocities, "N × d lab velocities now (a computed copy)")
      .def_property_readonly("diameters", &diameters, "σ_i (N,): drawn per particle when polydisperse, else σ")
      .def_property_readonly("masses", &masses, "m_i (N,): mean 1 when polydisperse, else 1")
      .def_property_readonly("spins", &spins,
                             "angular velocities of rough grains now: ω_z (N,) "
                             "of disks, N × 3 of spheres; None when smooth")
      .def_property_readonly("timeseries", &timeseries,
                             "the time series so far: column name → array, the "
                             "columns of timeseries.csv")
      .def_property_readonly(
          "timeseries_row",
          [](const PySimulation& s) { return s.visit([](const auto& run) { return row_dict(run.samples().back()); }); },
          "the latest row of the time series (at the last stop of run()) as a "
          "dict")
      .def_property_readonly(
          "config_toml",
          [](const PySimulation& s) { return s.visit([](const auto& run) { return to_toml(run.config()); }); },
          "the fully resolved configuration as TOML: `granule run` of it makes "
          "the same run")
      .def(
          "summary",
          [](const PySimulation& s) {
            return s.visit([&](const auto& run) { return json_to_python(run.summary(s.last_reason())); });
          },
          "summary.json's content for the run so far (dict)")
      .def(
          "write_snapshot",
          [](const PySimulation& s, const py::object& path) {
            s.visit([&](const auto& run) { run.write_snapshot(py::str(path).cast<std::string>()); });
          },
          py::arg("path"),
          "Append the present state as a frame of a snapshots.h5 file (created "
          "when missing; schema of `granule run`'s), "
          "readable by `granule analyze`, `granule plot` and h5py");
}

}  // namespace granule::bindings
