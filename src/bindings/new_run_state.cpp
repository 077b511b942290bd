#include "bindings/new_run_state.hpp"

#include <fmt/format.h>

#include "bindings/interactive_run.hpp"
#include "boundary/shear_protocol.hpp"

namespace granule::bindings {

NewRunState new_run_state(const RunConfig& config) {
  const CellGridChoice choice = choose_cell_grid(engine_grid_request(config));
  if (!choice.grid) throw ConfigError(choice.error);
  const double protocol_start = ShearProtocol(config.system.shear_velocity, config.system.shear_history).velocity(0.0);
  ClockState clock;
  clock.held_shear_velocity = config.initial_shear_profile ? protocol_start : 0.0;
  InitialStateResult initial = make_initial_state(
      config.system, config.initial_temperature, config.seed, config.placement, clock.held_shear_velocity,
      particle_sizes(config), {config.initial_shear_profile, config.initial_rotational_temperature});
  if (!initial.error.empty()) {
    throw ConfigError(fmt::format("{} (system.{} = {:.4g})", initial.error,
                                  config.system.dimension == 2 ? "area_fraction" : "packing_fraction",
                                  config.packing_fraction));
  }
  return {*choice.grid, std::move(initial.state), clock};
}

}  // namespace granule::bindings
