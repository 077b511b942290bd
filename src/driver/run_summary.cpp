#include "driver/run_summary.hpp"

#include <cmath>

#include "engine/stop_reason_names.hpp"
#include "granule/version.hpp"
#include "theory/steady_shear.hpp"

namespace granule::driver {

const char* stop_text(StopReason reason) {
  for (const auto& [known, name] : kStopReasonNames) {
    if (known == reason) return name;
  }
  return "unknown";
}

namespace {

// The parameters of rough grains, walls and gravity: rough grains (β, q, μ, the initial T_rot of a new gas; null when
// smooth), the walls (one entry per wall, empty without) and g.
template <int D>
void describe_grains_walls_gravity(const RunConfig& config, nlohmann::json& j) {
  const SystemParams& s = config.system;
  const RoughnessParams& r = s.roughness;
  j["roughness"] = nullptr;
  if (r.rough) {
    j["roughness"] = {{"tangential_restitution", r.tangential_restitution},
                      {"inertia_factor", r.inertia_factor},
                      {"friction", std::isfinite(r.friction) ? nlohmann::json(r.friction) : nlohmann::json(nullptr)},
                      {"initial_rotational_temperature", config.initial_from ? nlohmann::json(nullptr)
                                                                             : nlohmann::json(config.initial_rotational_temperature)}};
  }
  const std::array<double, 3> lengths{s.length_x, s.length_y, s.length_z};
  nlohmann::json walls = nlohmann::json::array();
  for (std::size_t axis = 0; axis < static_cast<std::size_t>(D); ++axis) {
    if (!s.walls[axis]) continue;
    for (std::size_t side = 0; side < 2; ++side) {
      const WallParams& w = s.wall[2 * axis + side];
      walls.push_back({{"axis", std::string(1, "xyz"[axis])},
                       {"position", side == 0 ? 0.0 : lengths[axis]},
                       {"restitution", w.restitution},
                       {"tangential_restitution", w.tangential_restitution},
                       {"velocity", std::vector<double>(w.velocity.begin(), w.velocity.begin() + D)}});
    }
  }
  j["walls"] = walls;
  if (s.walls[1]) j["wall_shear_velocity"] = wall_shear_velocity(s);
  j["gravity"] = std::vector<double>(s.gravity.begin(), s.gravity.begin() + D);
}

}  // namespace

template <int D>
nlohmann::json summary_json(const RunConfig& config, const Simulation<D>& sim, const CellGrid& grid, StopReason reason,
                            const RunFacts& facts, const std::vector<DiagnosticsSample>& samples) {
  const SystemParams& s = config.system;
  nlohmann::json j;
  j["version"] = kVersion;
  j["particles"] = s.particles;
  j["diameter"] = s.diameter;
  j["dimension"] = D;
  j["packing_fraction"] = config.packing_fraction;
  if (D == 2) {
    j["area_fraction"] = config.packing_fraction;
    j["box"] = {s.length_x, s.length_y};
  } else {
    j["box"] = {s.length_x, s.length_y, s.length_z};
  }
  j["polydisperse"] = !config.diameters.monodisperse();
  j["restitution"] = s.restitution;
  j["tc_duration"] = s.tc_duration;
  j["boundary"] = boundary_kind_name(config);
  j["shear_velocity"] = s.shear_velocity;
  describe_grains_walls_gravity<D>(config, j);
  j["seed"] = config.seed;
  j["collisions"] = sim.collisions();
  j["events"] = sim.events();
  j["equilibrate_collisions"] = facts.equilibrate_collisions;
  j["wall_seconds"] = facts.wall_seconds;
  // The speed of this invocation, pre-run collisions included (they took part of its wall time): a
  // resumed run's earlier segments ran elsewhere, maybe.
  j["collisions_per_second"] =
      facts.segment_wall_seconds > 0.0
          ? static_cast<double>(facts.segment_collisions + facts.segment_prerun_collisions) / facts.segment_wall_seconds
          : 0.0;
  j["prerun_collisions_this_invocation"] = facts.segment_prerun_collisions;
  j["t"] = sim.time();
  j["c"] = sim.collisions_per_particle();
  j["stop_reason"] = stop_text(reason);
  j["snapshots"] = facts.snapshots;
  j["engine_cells"] = D == 2 ? nlohmann::json{grid.nx, grid.ny} : nlohmann::json{grid.nx, grid.ny, grid.nz};
  j["bytes_per_particle"] = sim.bytes_per_particle();
  if (!samples.empty()) {
    // The Chapter 4 flow measures of the last sample (docs/macrostructure.md).
    nlohmann::json flow = {{"c", samples.back().c}};
    for_each_flow_measure(samples.back().flow, [&](const char* name, double value) { flow[name] = value; });
    j["flow_classification"] = flow;
  }
  if (D == 2 && config.lees_edwards && !samples.empty()) {
    // Steady-shear temperature: measured T̄ (mean over the second half of the samples) beside
    // the thesis's fit (3.1) and the Jenkins–Richman dilute law (3.2).
    const std::size_t from = samples.size() / 2;
    const auto mean = [&](double DiagnosticsSample::*column) {
      double sum = 0.0;
      for (std::size_t k = from; k < samples.size(); ++k) sum += samples[k].*column;
      return sum / static_cast<double>(samples.size() - from);
    };
    const double gamma = s.shear_velocity / s.length_y;
    // T̄ with the imposed profile removed in each cell (what (3.1) and (3.2) describe), beside the
    // thesis's lab-velocity cell average (grid-dependent under shear) and the global ½⟨(v − u)²⟩.
    j["steady_shear"] = {
        {"temperature_measured", mean(&DiagnosticsSample::temperature)},
        {"temperature_thesis_cells_measured", mean(&DiagnosticsSample::temperature_thesis_cells)},
        {"temperature_global_measured", mean(&DiagnosticsSample::temperature_global)},
        {"measured_over_c", {samples[from].c, samples.back().c}},
        {"temperature_tan_fit_eq_3_1", theory::steady_shear_temperature_tan_fit(s.restitution, gamma, s.diameter, config.packing_fraction)},
        {"temperature_jenkins_richman_eq_3_2",
         theory::steady_shear_temperature_jenkins_richman(s.restitution, gamma, s.diameter, config.packing_fraction)},
    };
  }
  return j;
}

template nlohmann::json summary_json(const RunConfig&, const Simulation<2>&, const CellGrid&, StopReason, const RunFacts&,
                                     const std::vector<DiagnosticsSample>&);
template nlohmann::json summary_json(const RunConfig&, const Simulation<3>&, const CellGrid&, StopReason, const RunFacts&,
                                     const std::vector<DiagnosticsSample>&);

}  // namespace granule::driver
