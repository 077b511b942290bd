// `granule sweep SPEC --out DIR`: validate the whole spec before anything is written, then run its
// points as child `granule run` processes of this very executable (src/sweep/point_runs.hpp says
// why processes), and write DIR/results.csv.  `granule sweep DIR --collect` gathers results.csv
// after array tasks.  Exit codes: exit_codes.hpp (6: some points failed or did not run).
#include "app/sweep/sweep_command.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <numeric>
#include <optional>
#include <vector>

#include "app/command_line.hpp"
#include "app/exit_codes.hpp"
#include "driver/interrupt_signals.hpp"
#include "sweep/array_tasks.hpp"
#include "sweep/point_runs.hpp"
#include "sweep/results_table.hpp"
#include "sweep/sweep_directory.hpp"
#ifdef GRANULE_HAVE_MPI
#include "sweep/mpi_points.hpp"
#endif

namespace granule::app {

namespace {

using driver::InterruptSignals;
using namespace granule::sweep;

struct SweepOptions {
  std::string input;  // SPEC.toml, or with --collect the sweep's DIR
  std::string out;
  int jobs = 1;
  bool mpi = false;
  bool collect = false;
  std::optional<int> array_task;
  std::optional<int> array_count;
};

int exit_code(const SweepTally& tally) {
  if (const int signal = InterruptSignals::received(); signal != 0) return kExitInterruptedBase + signal;
  return tally.complete() ? kExitSuccess : kExitSweepIncomplete;
}

int collect(const SweepOptions& o) {
  const SweepDirectory dir{o.input};
  const SweepSpec spec = sweep_in_directory(dir);
  const SweepTally tally = write_results(dir, spec);
  fmt::print("{}\n", tally_line(tally, dir));
  return tally.complete() ? kExitSuccess : kExitSweepIncomplete;
}

SweepSpec checked_spec(const SweepOptions& o) {
  if (o.out.empty())
    throw CommandFailure{kExitBadInput, "--out DIR is required (where the sweep's runs and results.csv go)"};
  if (o.jobs < 1 || o.jobs > 1024)
    throw CommandFailure{kExitBadInput, fmt::format("--jobs {} is outside [1, 1024]", o.jobs)};
  SweepSpecResult parsed = load_sweep_spec(o.input);
  if (!parsed.spec) throw CommandFailure{kExitBadInput, parsed.error};
  return std::move(*parsed.spec);
}

int run_locally(const SweepOptions& o, const SweepSpec& spec) {
  const std::optional<ArrayShare> share = array_share(o.array_task, o.array_count, o.mpi);
  const SweepRun run{own_executable(), SweepDirectory{o.out}, &spec, InterruptSignals::flag()};
  prepare_sweep_directory(run.dir, spec);
  const std::vector<PointRecord> records = run_points(run, share.value_or(ArrayShare{}).points(spec.points.size()), o.jobs, true);
  if (share && share->count > 1) {
    // Other tasks are still running: results.csv is gathered once they all ended.
    SweepTally mine;
    for (const PointRecord& r : records) mine.add(r.status);
    fmt::print(
        "sweep: array task {} of {} ran {} points ({} failed); gather results.csv with\n  granule sweep {} --collect\n",
        share->task, share->count, records.size(), mine.failed, o.out);
    return exit_code(mine);
  }
  const SweepTally tally = write_results(run.dir, spec);
  fmt::print("{}\n", tally_line(tally, run.dir));
  return exit_code(tally);
}

#ifdef GRANULE_HAVE_MPI
// Every rank validates the spec itself (the same answer everywhere); rank 0 alone prepares DIR and
// writes results.csv, and its exit code becomes every rank's.
int run_over_mpi(const SweepOptions& o) {
  const MpiSession mpi;
  const MpiWorld& world = mpi.world();
  int code = kExitSuccess;
  std::optional<SweepSpec> spec;
  try {
    if (o.jobs != 1)
      throw CommandFailure{kExitBadInput, "--jobs is for local runs: under --mpi each rank runs one point at a time"};
    if (o.array_task || o.array_count) throw CommandFailure{kExitBadInput, "--mpi and --array-task exclude each other"};
    spec = checked_spec(o);
    if (world.rank == 0) {
      prepare_sweep_directory(SweepDirectory{o.out}, *spec);
      // Rank 0 reads every point's record as it hands the points out: a damaged one is refused
      // here, before any rank starts a point.
      std::vector<std::size_t> all(spec->points.size());
      std::iota(all.begin(), all.end(), std::size_t{0});
      check_point_files(SweepDirectory{o.out}, *spec, all);
    }
  } catch (const CommandFailure& failure) {
    if (world.rank == 0) fmt::print(stderr, "granule sweep: error: {}\n", failure.message);
    code = failure.code;
  } catch (const InputError& error) {  // the spec, DIR, or a record or summary in DIR
    fmt::print(stderr, "granule sweep: error: {}\n", error.what());
    code = kExitBadInput;
  }
  code = mpi.broadcast(code);
  if (code != kExitSuccess) return code;
  const SweepRun run{own_executable(), SweepDirectory{o.out}, &*spec, InterruptSignals::flag()};
  run_points_over_mpi(run, world);
  if (world.rank == 0) {
    const SweepTally tally = write_results(run.dir, *spec);
    fmt::print("{} ({} ranks)\n", tally_line(tally, run.dir), world.size);
    code = exit_code(tally);
  }
  return mpi.broadcast(code);
}
#endif

int sweep(const SweepOptions& o) {
  // From the start: a signal stops the points running (they checkpoint) and starts no more.
  const InterruptSignals signals;
  try {
    if (o.collect) return collect(o);
    if (o.mpi) {
#ifdef GRANULE_HAVE_MPI
      return run_over_mpi(o);
#else
      throw CommandFailure{kExitBadInput,
                           "--mpi: this granule was built without MPI (install libopenmpi-dev and "
                           "reconfigure); use --jobs K or array tasks instead"};
#endif
    }
    const SweepSpec spec = checked_spec(o);
    return run_locally(o, spec);
  } catch (const CommandFailure& failure) {
    fmt::print(stderr, "granule sweep: error: {}\n", failure.message);
    return failure.code;
  } catch (const InputError& error) {  // the spec, DIR, or a record or summary in DIR
    fmt::print(stderr, "granule sweep: error: {}\n", error.what());
    return kExitBadInput;
  }
}

}  // namespace

void add_sweep_command(CLI::App& root) {
  auto options = std::make_shared<SweepOptions>();
  CLI::App* command = root.add_subcommand(
      "sweep",
      "Run a parameter sweep: a base config plus a [sweep] table of keys → lists (README.md, \"Sweeps\"); "
      "one run directory per point and DIR/results.csv.");
  command->add_option("spec", options->input, "Sweep spec (TOML), or with --collect the sweep's output directory")
      ->required();
  command->add_option("--out", options->out, "Output directory of the sweep (a restart gives the same one)");
  command->add_option("--jobs", options->jobs, "Points run at once on this machine, as child processes")
      ->capture_default_str();
  command->add_flag("--mpi", options->mpi,
                    "Share the points over the ranks of mpirun -n K (rank 0 hands them out; K − 1 ranks run them)");
  command->add_option(
      "--array-task", options->array_task,
      "Run only the share of array task I in [0, M): points I, I + M, ... (default: SLURM_ARRAY_TASK_ID)");
  command->add_option("--array-count", options->array_count,
                      "M, the number of array tasks (default: SLURM_ARRAY_TASK_COUNT)");
  command->add_flag("--collect", options->collect,
                    "Gather DIR/results.csv from the points' records (after array tasks)");
  command->callback([options] { throw CLI::RuntimeError(sweep(*options)); });
}

}  // namespace granule::app
