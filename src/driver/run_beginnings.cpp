#include "driver/run_beginnings.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <utility>

#include "io/atomic_file.hpp"
#include "io/checkpoint_file.hpp"

namespace granule::driver {

namespace {

// The first `--set` key outside run.*, output.* and `also_allowed`, or "".
std::string first_physics_override(const std::vector<std::string>& overrides, const std::vector<std::string>& also_allowed) {
  for (const std::string& assignment : overrides) {
    const std::string key = assignment.substr(0, assignment.find('='));
    const bool allowed = key.rfind("run.", 0) == 0 || key.rfind("output.", 0) == 0 ||
                         std::find(also_allowed.begin(), also_allowed.end(), key) != also_allowed.end();
    if (!allowed) return key;
  }
  return {};
}

// With a frame the run takes another branch from an earlier state, so the TC model may be
// switched on (the way out of an inelastic collapse); nothing else of the physics may change.
const std::vector<std::string> kFromFrameKeys = {"system.tc_duration"};

}  // namespace

RunConfig run_configuration(const std::string& config_path, const std::string& continued, bool from_frame,
                            const std::vector<std::string>& overrides) {
  if (!continued.empty()) {
    const auto also_allowed = from_frame ? kFromFrameKeys : std::vector<std::string>{};
    if (const std::string key = first_physics_override(overrides, also_allowed); !key.empty()) {
      throw ConfigError(fmt::format("--set {}: a resumed run may only change run.* and output.* keys{} "
                                    "(the physics of {} is fixed by its config.toml)", key,
                                    from_frame ? " and system.tc_duration" : "", continued));
    }
  }
  const ConfigResult parsed = !continued.empty()   ? load_config_file(continued + "/config.toml", overrides)
                              : config_path.empty() ? parse_config(default_example_toml(), overrides)
                                                    : load_config_file(config_path, overrides);
  if (!parsed.config) throw ConfigError(parsed.error);
  return *parsed.config;
}

void require_memory(double needed_bytes, const std::string& what) {
  const double available = available_memory_bytes();
  if (available > 0.0 && !(needed_bytes <= available)) {
    constexpr double kGiB = 1 << 30;
    throw NotEnoughMemory(fmt::format("{} needs about {:.3g} GiB of memory, but {:.3g} GiB are available", what,
                                      needed_bytes / kGiB, available / kGiB));
  }
}

void check_run_memory(const RunConfig& config, const CellGrid& grid) {
  std::string what = fmt::format("a run of N = {}", config.system.particles);
  // A measurement grid of more cells than particles is named: it is what to change.
  const auto larger = [&](const std::pair<int, int>& cells) {
    return static_cast<double>(cells.first) * cells.second > static_cast<double>(config.system.particles);
  };
  if (config.system.dimension == 2 && config.fields.enabled && larger(config.fields.cells)) {
    what += fmt::format(" with fields.cells = [{}, {}]", config.fields.cells.first, config.fields.cells.second);
  }
  if (larger(config.diagnostic_cells)) {
    what += fmt::format(" with diagnostics.cells = [{}, {}]", config.diagnostic_cells.first, config.diagnostic_cells.second);
  }
  require_memory(estimated_run_bytes(config, grid), what);
}

template <int D>
std::unique_ptr<RunSession<D>> begin_new_run(const RunConfig& config, const CellGrid& grid, const std::string& out, bool force) {
  check_run_memory(config, grid);
  const RunStart start = run_start(config);
  prepare_new_output_directory(out, force);
  write_file_atomically(out + "/config.toml", to_toml(config));
  return std::make_unique<RunSession<D>>(config, grid, out, start);
}

template <int D>
std::unique_ptr<RunSession<D>> resume_run(const RunConfig& config, const CellGrid& grid, const std::string& out) {
  StateArchive checkpoint;
  try {
    checkpoint = read_checkpoint(out + "/checkpoint.h5");
  } catch (const std::exception& error) {
    throw RunDirectoryRefused(fmt::format("cannot resume {}: {}", out, error.what()));
  }
  check_run_memory(config, grid);
  std::unique_ptr<RunSession<D>> session;
  try {
    session = std::make_unique<RunSession<D>>(config, grid, out, checkpoint);
  } catch (const std::runtime_error& error) {
    throw RunDirectoryRefused(fmt::format("cannot resume {}: {}", out, error.what()));
  }
  remove_end_of_run_outputs(out);
  write_file_atomically(out + "/config.toml", to_toml(config));
  return session;
}

template <int D>
BranchedRun<D> branch_run_from_frame(const RunConfig& config, const CellGrid& grid, const std::string& out, std::int64_t frame) {
  const std::string snapshots = existing_run_output(out, "snapshots.h5");
  SnapshotRead read;
  try {
    if (snapshots.empty()) throw std::runtime_error("the run has no snapshot file");
    read = read_snapshot(snapshots, frame);
  } catch (const std::exception& error) {
    throw RunDirectoryRefused(fmt::format("--from-frame {}: cannot read {}: {}", frame, out, error.what()));
  }
  const SystemParams& theirs = read.metadata.system;
  if (theirs.particles != config.system.particles || theirs.diameter != config.system.diameter ||
      theirs.dimension != config.system.dimension) {
    throw RunDirectoryRefused(fmt::format("{} does not match {}/config.toml", snapshots, out));
  }
  BranchedRun<D> branch;
  branch.frame = frame < 0 ? read.frames + frame : frame;
  branch.time = read.frame.clock.time;
  branch.collisions_per_particle = read.frame.collisions_per_particle;
  check_run_memory(config, grid);
  // Everything the run wrote moves aside; frames and rows up to the frame come back.
  BranchedOutputs branched = branch_run_outputs(out, branch.frame, branch.collisions_per_particle, config.fields.enabled);
  branch.aside = branched.aside;
  typename RunSession<D>::FrameStart start;
  start.frame = read.frame;
  start.snapshot_frames = branch.frame + 1;
  start.samples = std::move(branched.samples);
  start.kept = branched.kept;
  write_file_atomically(out + "/config.toml", to_toml(config));
  branch.session = std::make_unique<RunSession<D>>(config, grid, out, start);
  return branch;
}

template std::unique_ptr<RunSession<2>> begin_new_run<2>(const RunConfig&, const CellGrid&, const std::string&, bool);
template std::unique_ptr<RunSession<3>> begin_new_run<3>(const RunConfig&, const CellGrid&, const std::string&, bool);
template std::unique_ptr<RunSession<2>> resume_run<2>(const RunConfig&, const CellGrid&, const std::string&);
template std::unique_ptr<RunSession<3>> resume_run<3>(const RunConfig&, const CellGrid&, const std::string&);
template BranchedRun<2> branch_run_from_frame<2>(const RunConfig&, const CellGrid&, const std::string&, std::int64_t);
template BranchedRun<3> branch_run_from_frame<3>(const RunConfig&, const CellGrid&, const std::string&, std::int64_t);

}  // namespace granule::driver
