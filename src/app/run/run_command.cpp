// `granule run`: validate a configuration and the output directory, prepare the initial state of
// thesis §1.4.2 (or continue a run from its checkpoint), run it (driver/run_session.hpp) and report.
// Exit codes are listed in README.md ("Exit codes") and in exit_codes.hpp.
#include "app/run/run_command.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>

#include "app/exit_codes.hpp"
#include "app/interrupt_signals.hpp"
#include "render/snapshot_picture.hpp"
#include "app/run/run_console.hpp"
#include "driver/run_directory.hpp"
#include "driver/run_session.hpp"
#include "driver/run_start.hpp"
#include "io/atomic_file.hpp"
#include "io/checkpoint_file.hpp"
#include "io/io_error.hpp"
#include "io/snapshot_file.hpp"

namespace granule::app {

namespace {

using driver::RunSession;
using driver::stop_text;

struct RunOptions {
  std::string config_path;
  std::vector<std::string> overrides;
  std::string out_dir;
  std::string resume_dir;
  std::optional<std::int64_t> from_frame;
  bool force = false;
};

// The first `--set` key outside run.*, output.* and `also_allowed`, or "" (a resumed run keeps
// its physics).
std::string first_physics_override(const std::vector<std::string>& overrides, const std::vector<std::string>& also_allowed) {
  for (const std::string& assignment : overrides) {
    const std::string key = assignment.substr(0, assignment.find('='));
    const bool allowed = key.rfind("run.", 0) == 0 || key.rfind("output.", 0) == 0 ||
                         std::find(also_allowed.begin(), also_allowed.end(), key) != also_allowed.end();
    if (!allowed) return key;
  }
  return {};
}

// Refuses (exit 5) a run whose estimated peak memory exceeds what the machine has available.
void check_memory_for_run(const RunConfig& config, const CellGrid& grid) {
  const double needed = driver::estimated_run_bytes(config, grid);
  const double available = driver::available_memory_bytes();
  if (available > 0.0 && needed > available) {
    throw CommandFailure{kExitOutOfMemory,
                         fmt::format("a run of N = {} needs about {:.3g} GiB of memory, but {:.3g} GiB are available",
                                     config.system.particles, needed / (1 << 30), available / (1 << 30))};
  }
}

// With --from-frame the run takes another branch from an earlier state, so the TC model may be
// switched on (the way out of an inelastic collapse); nothing else of the physics may change.
const std::vector<std::string> kFromFrameKeys = {"system.tc_duration"};

RunConfig configuration(const RunOptions& options, bool resume, const std::string& out) {
  if (resume) {
    // Only how long to run and what to write may change: anything else would be another run.
    const auto also_allowed = options.from_frame ? kFromFrameKeys : std::vector<std::string>{};
    if (const std::string key = first_physics_override(options.overrides, also_allowed); !key.empty()) {
      throw CommandFailure{kExitBadInput, fmt::format("--set {}: a resumed run may only change run.* and output.* keys{} "
                                                      "(the physics of {} is fixed by its config.toml)", key,
                                                      options.from_frame ? " and system.tc_duration" : "", out)};
    }
  }
  const ConfigResult parsed = resume ? load_config_file(out + "/config.toml", options.overrides)
                              : options.config_path.empty() ? parse_config(default_example_toml(), options.overrides)
                                                            : load_config_file(options.config_path, options.overrides);
  if (!parsed.config) throw CommandFailure{kExitBadInput, parsed.error};
  return *parsed.config;
}

// A refusal of the shared start (driver/run_start.hpp) as the command's exit code 2.
template <typename F>
auto or_bad_input(F&& f) {
  try {
    return f();
  } catch (const driver::ConfigError& error) {
    throw CommandFailure{kExitBadInput, error.what()};
  }
}

template <int D>
std::unique_ptr<RunSession<D>> new_session(const RunConfig& config, const CellGrid& grid, const RunOptions& options) {
  const std::string& out = options.out_dir;
  check_memory_for_run(config, grid);
  const driver::RunStart start = or_bad_input([&] { return driver::run_start(config); });
  try {
    driver::prepare_new_output_directory(out, options.force);
  } catch (const driver::RunDirectoryRefused& refused) {
    throw CommandFailure{kExitBadInput, refused.what()};
  }
  write_file_atomically(out + "/config.toml", to_toml(config));
  return std::make_unique<RunSession<D>>(config, grid, out, start);
}

template <int D>
std::unique_ptr<RunSession<D>> resumed_session(const RunConfig& config, const CellGrid& grid, const std::string& out) {
  StateArchive checkpoint;
  try {
    checkpoint = read_checkpoint(out + "/checkpoint.h5");
  } catch (const std::exception& error) {
    throw CommandFailure{kExitBadInput, fmt::format("cannot resume {}: {}", out, error.what())};
  }
  check_memory_for_run(config, grid);
  auto session = [&] {
    try {
      return std::make_unique<RunSession<D>>(config, grid, out, checkpoint);
    } catch (const std::runtime_error& error) {
      throw CommandFailure{kExitBadInput, fmt::format("cannot resume {}: {}", out, error.what())};
    }
  }();
  driver::remove_end_of_run_outputs(out);
  write_file_atomically(out + "/config.toml", to_toml(config));
  const Simulation<D>& sim = session->simulation();
  fmt::print("resuming {} at t = {:.6g}, c = {:.6g}\n", out, sim.time(), sim.collisions_per_particle());
  return session;
}

template <int D>
std::unique_ptr<RunSession<D>> from_frame_session(const RunConfig& config, const CellGrid& grid, const std::string& out,
                                               std::int64_t frame) {
  const std::string snapshots = driver::existing_run_output(out, "snapshots.h5");
  SnapshotRead read;
  try {
    if (snapshots.empty()) throw std::runtime_error("the run has no snapshot file");
    read = read_snapshot(snapshots, frame);
  } catch (const std::exception& error) {
    throw CommandFailure{kExitBadInput, fmt::format("--from-frame {}: cannot read {}: {}", frame, out, error.what())};
  }
  if (read.metadata.system.particles != config.system.particles || read.metadata.system.diameter != config.system.diameter ||
      read.metadata.system.dimension != config.system.dimension) {
    throw CommandFailure{kExitBadInput, fmt::format("{} does not match {}/config.toml", snapshots, out)};
  }
  const std::int64_t k = frame < 0 ? read.frames + frame : frame;
  check_memory_for_run(config, grid);
  // Everything the run wrote moves aside; frames and rows up to frame K come back.
  const double c = read.frame.collisions_per_particle;
  driver::BranchedOutputs branched = driver::branch_run_outputs(out, k, c, config.fields.enabled);
  const std::string& aside = branched.aside;
  typename RunSession<D>::FrameStart start;
  start.frame = read.frame;
  start.snapshot_frames = k + 1;
  start.samples = std::move(branched.samples);
  start.kept = branched.kept;
  write_file_atomically(out + "/config.toml", to_toml(config));
  auto session = std::make_unique<RunSession<D>>(config, grid, out, start);
  fmt::print("continuing {} from frame {} (t = {:.6g}, c = {:.6g}); the later outputs are in {}\n", out, k,
             read.frame.clock.time, c, aside);
  return session;
}

// The mean free time per disk over the last sampled interval (each collision involves two disks).
template <int D>
double mean_free_time(const RunSession<D>& session) {
  const Simulation<D>& sim = session.simulation();
  for (auto it = session.samples().rbegin(); it != session.samples().rend(); ++it) {
    if (it->collision_rate > 0.0) return 0.5 / it->collision_rate;
  }
  return sim.collisions() > 0 ? 0.5 * sim.time() / sim.collisions_per_particle() : 0.0;
}

template <int D>
std::string collapse_report(const RunSession<D>& session, const std::string& out) {
  const Simulation<D>& sim = session.simulation();
  const CollapseReport& c = sim.collapse();
  const double free_time = mean_free_time(session);
  const std::int64_t frames = session.snapshot_frames();
  return fmt::format(
             "granule run: stopped by inelastic collapse at t = {:.9g} (c = {:.6g}): particles {} and {} near ({:.4g}, {:.4g}, {:.4g})"
             " collided ever faster until the clock stopped advancing (McNamara & Young 1994).\n"
             "  The collapsing state is saved in {}/snapshots.h5 (frame {}).  The TC model (Luding & McNamara 1998) avoids\n"
             "  it; continue from an earlier frame with it switched on, e.g.\n"
             "    granule run --resume {} --from-frame {} --set system.tc_duration={:.3g}\n"
             "  (a t_c of 10⁻⁴ of the mean free time {:.3g} at the collapse leaves the physics unchanged).\n",
             c.time, sim.collisions_per_particle(), c.first, c.second, c.position.x, c.position.y, c.position.z, out, frames - 1, out,
             std::max<std::int64_t>(0, frames - 2), 1e-4 * free_time, free_time);
}

// The run itself, in the engine of dimension D (disks or spheres).
template <int D>
int run_in(const RunOptions& options, const RunConfig& config, const CellGrid& grid) {
  const bool resume = !options.resume_dir.empty();
  const std::string out = resume ? options.resume_dir : options.out_dir;
  // Files modified from here on are this invocation's (less a margin for the file system's coarse
  // clock, which may stamp a file a tick before now()).
  const auto since = std::filesystem::file_time_type::clock::now() - std::chrono::milliseconds(50);
  try {
    std::unique_ptr<RunSession<D>> session = !resume              ? new_session<D>(config, grid, options)
                                             : options.from_frame ? from_frame_session<D>(config, grid, out, *options.from_frame)
                                                                  : resumed_session<D>(config, grid, out);
    print_header(config, !resume && options.config_path.empty(), options.overrides.size());
    const StopReason reason = session->run(InterruptSignals::flag());
    const nlohmann::json summary = session->finish(reason);
    const Simulation<D>& sim = session->simulation();
    const auto prerun = summary["prerun_collisions_this_invocation"].get<std::int64_t>();
    const std::string finished =
        fmt::format("{} ({}): t = {:.6g}, c = {:.6g}, {} collisions{} in {:.3g} s ({:.3g} collisions/s)\n",
                    reason == StopReason::kInterrupted ? "stopped" : "finished", stop_text(reason), sim.time(),
                    sim.collisions_per_particle(), sim.collisions(),
                    prerun > 0 ? fmt::format(" (+ {} in the elastic pre-run)", prerun) : std::string{},
                    summary["wall_seconds"].get<double>(), summary["collisions_per_second"].get<double>());
    const std::int64_t frames = session->snapshot_frames();
    const std::string collapse = reason == StopReason::kInelasticCollapse ? collapse_report(*session, out) : std::string{};
    session.reset();  // the picture reads the last frame back: of 10^8 disks, not beside the engine
    try {
      if (frames > 0) fmt::print("picture: {}\n", render::render_run_picture(out));
    } catch (const IoError&) {
      throw;  // the disk failed: exit 4, the data files written before stay complete
    } catch (const std::exception& error) {  // a missing picture must not lose the run's data
      fmt::print(stderr, "granule run: warning: could not draw the configuration picture: {}\n", error.what());
    }
    fmt::print("{}{} ({} snapshot frames)\n", finished, files_written_text(out, since), frames);
    if (reason == StopReason::kInterrupted) {
      const int signal = InterruptSignals::received();
      fmt::print(stderr, "granule run: interrupted by signal {}: checkpoint written; continue with\n  granule run --resume {}\n",
                 signal, out);
      return kExitInterruptedBase + signal;
    }
    if (reason == StopReason::kInelasticCollapse) {
      fmt::print(stderr, "{}", collapse);
      return kExitCollapse;
    }
    return kExitSuccess;
  } catch (const CommandFailure& failure) {
    fmt::print(stderr, "granule run: error: {}\n", failure.message);
    return failure.code;
  }
}

int run(const RunOptions& options) {
  const bool resume = !options.resume_dir.empty();
  const std::string out = resume ? options.resume_dir : options.out_dir;
  // From the start: a signal during set-up stops the run at its first event, checkpointed.
  const InterruptSignals signals;
  try {
    const RunConfig config = configuration(options, resume, out);
    const CellGrid grid = or_bad_input([&] { return driver::run_cell_grid(config); });
    return config.system.dimension == 3 ? run_in<3>(options, config, grid) : run_in<2>(options, config, grid);
  } catch (const CommandFailure& failure) {
    fmt::print(stderr, "granule run: error: {}\n", failure.message);
    return failure.code;
  }
}

}  // namespace

void add_run_command(CLI::App& root) {
  auto options = std::make_shared<RunOptions>();
  CLI::App* command = root.add_subcommand(
      "run", "Run a simulation from a TOML config (or the built-in example: free cooling of a scaled-down "
             "System II of Tan 1995, N = 40000, ν = 0.05, e = 0.6, with the TC model t_c = 1e-7).");
  command->add_option("config", options->config_path, "TOML configuration file (keys: see README.md)")
      ->check(CLI::ExistingFile);
  command->add_option("--set", options->overrides, "Override a config key, e.g. --set system.restitution=0.8 (repeatable)");
  command->add_option("--out", options->out_dir, "Output directory (must not exist, or be empty, unless --force)")
      ->default_val("granule-run");
  command->add_flag("--force", options->force, "Replace the outputs of an earlier run in --out");
  command->add_option("--resume", options->resume_dir,
                      "Continue the run in this output directory from its checkpoint, bit for bit (extend it with e.g. "
                      "--set run.until_collisions_per_particle=200)")
      ->check(CLI::ExistingDirectory);
  command->add_option("--from-frame", options->from_frame,
                      "With --resume: continue from snapshot frame K instead of the checkpoint (negative counts from "
                      "the end), e.g. with --set system.tc_duration=... after an inelastic collapse; the later outputs "
                      "are moved to set_aside_after_frame_K")
      ->needs("--resume");
  command->callback([options] { throw CLI::RuntimeError(run(*options)); });
}

}  // namespace granule::app
