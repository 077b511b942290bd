// Uses the installed headers under <granule/...>: a configuration parsed by granule::io drives a
// short elastic run of the engine (granule::core); prints what the installed-package test checks.
#include <cstdio>
#include <granule/cells/cell_grid.hpp>
#include <granule/engine/simulation.hpp>
#include <granule/init/initial_state.hpp>
#include <granule/io/config.hpp>
#include <granule/version.hpp>
#include <limits>

int main() {
  const granule::ConfigResult parsed = granule::parse_config("[system]\nparticles = 300\narea_fraction = 0.1\n", {});
  if (!parsed.config) {
    std::fprintf(stderr, "config: %s\n", parsed.error.c_str());
    return 1;
  }
  const granule::RunConfig& config = *parsed.config;
  granule::SystemParams params = config.system;
  params.restitution = 1.0;  // elastic: the kinetic energy must stay what it was
  const auto grid = granule::choose_cell_grid(
      {params.length_x, params.length_y, params.diameter, params.particles, false, 1.0, std::nullopt});
  if (!grid.grid) return 1;
  const auto initial = granule::make_initial_state(params, 1.0, config.seed, granule::Placement::kAuto);
  if (!initial.error.empty()) return 1;
  granule::Simulation<2> sim(params, *grid.grid, initial.state);
  sim.run(std::numeric_limits<double>::infinity(), 10 * params.particles);
  std::printf("granule %s: %lld collisions, t = %.6g\n", granule::kVersion, static_cast<long long>(sim.collisions()),
              sim.time());
  return sim.collisions() == 10 * params.particles ? 0 : 1;
}
