#include "driver/run_start.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <string>

#include "boundary/shear_protocol.hpp"
#include "io/snapshot_file.hpp"
#include "io/system_checks.hpp"

namespace granule::driver {

namespace {

// initial.from: frame K of another run, which must hold the same particles in the same box.
ParticleState state_from_run(const RunConfig& config) {
  const InitialSource& from = *config.initial_from;
  const std::int64_t frame = from.frame.value_or(-1);
  SnapshotRead read;
  try {
    std::string path = from.directory + "/snapshots.h5";
    if (!std::filesystem::exists(path) && std::filesystem::exists(path + ".partial")) path += ".partial";
    read = read_snapshot(path, frame);
  } catch (const std::exception& error) {
    throw ConfigError(fmt::format("initial.from = \"{}\", initial.frame = {}: {}", from.directory,
                                  from.frame ? std::to_string(*from.frame) : "last", error.what()));
  }
  const SystemParams& theirs = read.metadata.system;
  const SystemParams& ours = config.system;
  if (theirs.dimension != ours.dimension || theirs.particles != ours.particles || theirs.diameter != ours.diameter ||
      theirs.length_x != ours.length_x || theirs.length_y != ours.length_y ||
      (ours.dimension == 3 && theirs.length_z != ours.length_z)) {
    throw ConfigError(fmt::format("initial.from = \"{}\" holds d = {}, N = {}, σ = {}, box [{}, {}, {}]; this run has "
                                  "d = {}, N = {}, σ = {}, box [{}, {}, {}]: system.* must match the run it starts from",
                                  from.directory, theirs.dimension, theirs.particles, theirs.diameter, theirs.length_x,
                                  theirs.length_y, theirs.length_z, ours.dimension, ours.particles, ours.diameter,
                                  ours.length_x, ours.length_y, ours.length_z));
  }
  // A frame is a state of its own boundaries and grains: its centres keep a radius from its walls
  // only, and only rough frames carry spins.
  if (theirs.walls != ours.walls || theirs.roughness.rough != ours.roughness.rough) {
    throw ConfigError(fmt::format("initial.from = \"{}\" is a run with {} and {} grains; this run has {} and {} grains: "
                                  "boundary.kind / boundary.wall_axes and system.tangential_restitution must agree",
                                  from.directory, theirs.has_walls() ? "walls" : "no walls",
                                  theirs.roughness.rough ? "rough" : "smooth", ours.has_walls() ? "walls" : "no walls",
                                  ours.roughness.rough ? "rough" : "smooth"));
  }
  // The sizes and masses are those this configuration draws from its seed: the frame's must agree.
  const ParticleSizes sizes = particle_sizes(config);
  if (sizes.diameter != read.frame.particles.diameter || sizes.mass != read.frame.particles.mass) {
    throw ConfigError(fmt::format("initial.from = \"{}\" holds other particle diameters or masses than "
                                  "system.diameters / system.masses / seed give", from.directory));
  }
  // This run's obstacles may stand where the frame's grains are.
  if (!ours.obstacles.empty()) {
    if (const std::vector<std::string> problems = particle_problems(read.frame.particles, ours); !problems.empty()) {
      throw ConfigError(fmt::format("initial.from = \"{}\": {}: [[obstacles]] must leave the frame's grains outside",
                                    from.directory, problems.front()));
    }
  }
  return read.frame.particles;
}

}  // namespace

CellGrid run_cell_grid(const RunConfig& config) {
  const CellGridChoice choice = choose_cell_grid(engine_grid_request(config));
  if (!choice.grid) throw ConfigError(choice.error);
  return *choice.grid;
}

RunStart run_start(const RunConfig& config) {
  // A frame of an earlier run carries its flow, so its images move with the protocol from the start.
  const bool sheared = config.initial_shear_profile || config.initial_from;
  const double protocol_start = image_protocol(config.system).velocity(0.0);
  RunStart start;
  start.clock.held_shear_velocity = sheared ? protocol_start : 0.0;
  if (config.initial_from) {
    start.particles = state_from_run(config);
    return start;
  }
  InitialStateResult initial = make_initial_state(config.system, config.initial_temperature, config.seed,
                                                  config.placement, start.clock.held_shear_velocity, particle_sizes(config),
                                                  {config.initial_shear_profile, config.initial_rotational_temperature});
  if (!initial.error.empty()) {
    throw ConfigError(fmt::format("{} (system.{} = {:.4g})", initial.error,
                                  config.system.dimension == 2 ? "area_fraction" : "packing_fraction",
                                  config.packing_fraction));
  }
  start.particles = std::move(initial.state);
  return start;
}

std::vector<std::string> run_warnings(const RunConfig& config) {
  std::vector<std::string> warnings;
  if (config.lees_edwards) {
    const ShearHistory& history = config.system.shear_history;
    const std::int64_t segments = ShearProtocol(config.system.shear_velocity, history).segments_while_changing(kManySegments + 1);
    if (segments > kManySegments) {
      ShearHistory usual = history;
      usual.tolerance = 1e-3;
      warnings.push_back(fmt::format(
          "boundary.shear_tolerance = {:g} makes the shear protocol take more than {} segments while U(t) changes "
          "(each ends with an engine action that re-predicts the grains at the Lees–Edwards faces); the default 1e-3 "
          "takes {}", history.tolerance, kManySegments, ShearProtocol(config.system.shear_velocity, usual).segments_while_changing(kManySegments + 1)));
    }
  }
  return warnings;
}

}  // namespace granule::driver
