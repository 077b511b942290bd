// `granule reproduce`: every run of the chosen studies goes through the sweep engine (one sweep
// directory per run group under DIR/runs/<study>/<group>), so --jobs/--mpi parallelise and a
// second call skips what finished; then each study turns its outputs into claims and figures, the
// figures are drawn by python/granule_plots/reproduce_figure.py, and src/reproduce/report.hpp
// writes the report.  Disagreements are findings, not failures: the exit code is 0 unless runs
// failed (6), the input was bad (2) or a signal stopped it (128 + signal).
#include "app/reproduce/reproduce_command.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <chrono>
#include <functional>
#include <memory>

#include "app/command_line.hpp"
#include "app/exit_codes.hpp"
#include "driver/interrupt_signals.hpp"
#include "io/io_error.hpp"
#include "reproduce/study_evaluation.hpp"

namespace granule::app {

namespace {

using driver::InterruptSignals;
using namespace granule::reproduce;

struct ReproduceOptions {
  std::string what = "all";
  std::string scale = "small";
  std::string out;
  int jobs = 1;
  bool mpi = false;
};

// The studies asked for: one by name, or all of them (those not built yet are listed as such).
std::vector<const Study*> selected_studies(const std::string& what) {
  std::vector<const Study*> chosen = studies_named(what);
  if (chosen.empty()) {
    std::vector<std::string> names;
    for (const Study& s : all_studies()) names.push_back(s.name);
    throw CommandFailure{kExitBadInput, fmt::format("unknown study \"{}\": allowed all, {}", what, fmt::join(names, ", "))};
  }
  return chosen;
}

Scale parse_scale(const std::string& text) {
  if (const std::optional<Scale> scale = scale_named(text)) return *scale;
  throw CommandFailure{kExitBadInput, fmt::format("--scale {}: allowed small, medium, thesis (tiny: for the tests)", text)};
}

std::string command_line(const ReproduceOptions& o) {
  std::string line = fmt::format("granule reproduce {} --scale {} --out {}", o.what, o.scale, o.out);
  if (o.mpi) return "mpirun -n K " + line + " --mpi";
  return o.jobs > 1 ? line + fmt::format(" --jobs {}", o.jobs) : line;
}

// Rank 0 (or the only process): read, judge, draw and write.
int report(const std::vector<const Study*>& studies, const std::vector<GroupRun>& groups, Scale scale, const ReproduceOptions& o,
           const std::function<double()>& elapsed) {
  StudiesEvaluated evaluated = evaluate_studies(studies, groups, scale, o.out, own_executable());
  // The wall time covers the runs, analyses and figures of this call.
  const Report r{scale_name(scale), command_line(o), elapsed(), evaluated.run_seconds, std::move(evaluated.sections)};
  write_report(o.out, r);
  fmt::print("\nclaims ({} scale):\n", r.scale);
  for (const std::string& line : claim_summary_lines(r)) fmt::print("  {}\n", line);
  fmt::print("wrote {0}/report.html, {0}/report.md, {0}/claims.csv, {0}/claims.json and {0}/figures/\n", o.out);
  return evaluated.complete ? kExitSuccess : kExitSweepIncomplete;
}

int reproduce(const ReproduceOptions& o) {
  const InterruptSignals signals;
  const auto start = std::chrono::steady_clock::now();
  try {
    if (o.out.empty()) throw CommandFailure{kExitBadInput, "--out DIR is required (where the runs, figures and report go)"};
    if (o.jobs < 1 || o.jobs > 1024) throw CommandFailure{kExitBadInput, fmt::format("--jobs {} is outside [1, 1024]", o.jobs)};
    const Scale scale = parse_scale(o.scale);
    const std::vector<const Study*> studies = selected_studies(o.what);
    const std::vector<GroupRun> groups = planned_groups(studies, scale, o.out);
    const std::function<double()> elapsed = [&] {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    if (o.mpi) {
#ifdef GRANULE_HAVE_MPI
      if (o.jobs != 1)
        throw CommandFailure{kExitBadInput, "--jobs is for local runs: under --mpi each rank runs one point at a time"};
      const sweep::MpiSession mpi;
      const bool whole = run_groups_over_mpi(groups, mpi, own_executable(), InterruptSignals::flag());
      const int code = mpi.world().rank != 0 ? kExitSuccess
                       : whole               ? report(studies, groups, scale, o, elapsed)
                                             : kExitInterruptedBase + InterruptSignals::received();
      return mpi.broadcast(code);
#else
      throw CommandFailure{kExitBadInput,
                           "--mpi: this granule was built without MPI (install libopenmpi-dev and reconfigure); use --jobs K"};
#endif
    }
    if (!run_groups_locally(groups, o.jobs, own_executable(), InterruptSignals::flag())) {
      fmt::print(stderr, "granule reproduce: interrupted; the same command resumes the runs\n");
      return kExitInterruptedBase + InterruptSignals::received();
    }
    return report(studies, groups, scale, o, elapsed);
  } catch (const CommandFailure& failure) {
    fmt::print(stderr, "granule reproduce: error: {}\n", failure.message);
    return failure.code;
  } catch (const sweep::BadSweepInput& error) {
    fmt::print(stderr, "granule reproduce: error: {} (a DIR of another scale or study set: use another --out)\n", error.what());
    return kExitBadInput;
  } catch (const IoError& error) {
    fmt::print(stderr, "granule reproduce: error: {}\n", error.what());
    return kExitIoError;
  }
}

}  // namespace

void add_reproduce_command(CLI::App& root) {
  auto options = std::make_shared<ReproduceOptions>();
  CLI::App* command = root.add_subcommand(
      "reproduce",
      "Reproduce the thesis: run the scaled Systems through the sweep engine, draw the figures and write DIR/report.html, "
      "report.md and the claims table claims.csv/claims.json (docs/reproduce.md)");
  command
      ->add_option("study", options->what,
                   "all, validation, chapter2, chapter3, chapter4, chapter5, appendix-b, appendix-c (those not built yet say so)")
      ->capture_default_str();
  command->add_option("--scale", options->scale, "small (minutes on 2 cores for all), medium, thesis (the thesis's N)")
      ->capture_default_str();
  command->add_option("--out", options->out, "Output directory: runs/, figures/, the report (a second call resumes and skips)");
  command->add_option("--jobs", options->jobs, "Runs at once on this machine (child processes)")->capture_default_str();
  command->add_flag("--mpi", options->mpi, "Share the runs over the ranks of mpirun -n K (rank 0 hands them out and reports)");
  command->callback([options] { throw CLI::RuntimeError(reproduce(*options)); });
}

}  // namespace granule::app
