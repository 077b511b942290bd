// `granule run`: validate a configuration and the output directory, prepare the initial state of
// thesis §1.4.2 (or continue a run from its checkpoint), run it (driver/run_session.hpp) and report.
// Exit codes are listed in README.md ("Exit codes") and in exit_codes.hpp.
#include "app/run/run_command.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>

#include "app/exit_codes.hpp"
#include "app/run/run_console.hpp"
#include "driver/interrupt_signals.hpp"
#include "driver/run_beginnings.hpp"
#include "io/io_error.hpp"
#include "render/snapshot_picture.hpp"

namespace granule::app {

namespace {

using driver::InterruptSignals;
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

// The driver's refusals as the command's exit codes: 2 for input, 5 for memory.
template <typename F>
auto or_failure(F&& f) {
  try {
    return f();
  } catch (const driver::ConfigError& error) {
    throw CommandFailure{kExitBadInput, error.what()};
  } catch (const driver::RunDirectoryRefused& refused) {
    throw CommandFailure{kExitBadInput, refused.what()};
  } catch (const driver::NotEnoughMemory& error) {
    throw CommandFailure{kExitOutOfMemory, error.what()};
  }
}

// A new run, the run resumed from its checkpoint, or continued from a frame, with what it says.
template <int D>
std::unique_ptr<RunSession<D>> begin(const RunOptions& options, const RunConfig& config, const CellGrid& grid,
                                     const std::string& out) {
  if (options.resume_dir.empty()) return driver::begin_new_run<D>(config, grid, out, options.force);
  if (!options.from_frame) {
    std::unique_ptr<RunSession<D>> session = driver::resume_run<D>(config, grid, out);
    const Simulation<D>& sim = session->simulation();
    fmt::print("resuming {} at t = {:.6g}, c = {:.6g}\n", out, sim.time(), sim.collisions_per_particle());
    return session;
  }
  driver::BranchedRun<D> branch = driver::branch_run_from_frame<D>(config, grid, out, *options.from_frame);
  fmt::print("continuing {} from frame {} (t = {:.6g}, c = {:.6g}); the later outputs are in {}\n", out, branch.frame,
             branch.time, branch.collisions_per_particle, branch.aside);
  return std::move(branch.session);
}

template <int D>
std::string collapse_report(const RunSession<D>& session, const std::string& out) {
  const Simulation<D>& sim = session.simulation();
  const CollapseReport& c = sim.collapse();
  const double free_time = session.mean_free_time();
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
    std::unique_ptr<RunSession<D>> session = or_failure([&] { return begin<D>(options, config, grid, out); });
    print_header(config, !resume && options.config_path.empty(), options.overrides.size());
    for (const std::string& warning : driver::run_warnings(config)) fmt::print(stderr, "granule run: warning: {}\n", warning);
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
    if (const int signal = InterruptSignals::received(); signal != 0) {  // it came after the last event
      fmt::print(stderr, "granule run: interrupted by signal {} during the final writes, which completed\n", signal);
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
    const RunConfig config = or_failure([&] {
      return driver::run_configuration(options.config_path, resume ? out : "", options.from_frame.has_value(), options.overrides);
    });
    const CellGrid grid = or_failure([&] { return driver::run_cell_grid(config); });
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
