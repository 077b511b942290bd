// `granule reproduce`: every run of the chosen studies goes through the sweep engine (one sweep
// directory per run group under DIR/runs/<study>/<group>), so --jobs/--mpi parallelise and a
// second call skips what finished; then each study turns its outputs into claims and figures, the
// figures are drawn by python/granule_plots/reproduce_figure.py, and src/reproduce/report.hpp
// writes the report.  Disagreements are findings, not failures: the exit code is 0 unless runs
// failed (6), the input was bad (2) or a signal stopped it (128 + signal).
#include "app/reproduce/reproduce_command.hpp"

#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>

#include "app/command_line.hpp"
#include "app/exit_codes.hpp"
#include "app/interrupt_signals.hpp"
#include "render/plot_scripts.hpp"
#include "io/atomic_file.hpp"
#include "io/io_error.hpp"
#include "reproduce/report.hpp"
#include "reproduce/study_runs.hpp"
#include "sweep/point_runs.hpp"
#include "sweep/sweep_directory.hpp"
#ifdef GRANULE_HAVE_MPI
#include "sweep/mpi_points.hpp"
#endif

namespace granule::app {

namespace {

namespace fs = std::filesystem;
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
  std::vector<const Study*> chosen;
  std::vector<std::string> names;
  for (const Study& s : all_studies()) {
    names.push_back(s.name);
    if (what == "all" || what == s.name) chosen.push_back(&s);
  }
  if (chosen.empty()) {
    throw CommandFailure{kExitBadInput, fmt::format("unknown study \"{}\": allowed all, {}", what, fmt::join(names, ", "))};
  }
  return chosen;
}

Scale parse_scale(const std::string& text) {
  for (Scale s : {Scale::tiny, Scale::small, Scale::medium, Scale::thesis}) {
    if (scale_name(s) == text) return s;
  }
  throw CommandFailure{kExitBadInput, fmt::format("--scale {}: allowed small, medium, thesis (tiny: for the tests)", text)};
}

// Runs all points of one group: K at a time locally, or over the MPI ranks.
using GroupRunner = std::function<void(const sweep::SweepRun&)>;

// Runs every group's points (skipping finished ones) with `run_all`.  Returns false when a signal
// stopped it.
bool run_groups(const std::vector<GroupRun>& groups, const GroupRunner& run_all, bool announce) {
  std::size_t total = 0;
  for (const GroupRun& g : groups) total += g.spec.points.size();
  std::size_t done = 0;
  for (const GroupRun& g : groups) {
    if (InterruptSignals::received() != 0) return false;
    if (announce) {
      fmt::print("reproduce: [{}/{} runs] {}/{}: {} point(s)\n", done, total, g.study->name, g.group, g.spec.points.size());
      std::fflush(stdout);
    }
    run_all(sweep::SweepRun{own_executable(), g.dir, &g.spec, InterruptSignals::flag()});
    done += g.spec.points.size();
  }
  return InterruptSignals::received() == 0;
}

// The study's analyses of every usable point of the group, each once (its output tells).  A failed
// analysis is reported; the claims that need it then find no number.
void run_point_analyses(const Study& study, Scale scale, const GroupRun& g, const GroupOutputs& outputs) {
  if (!study.analyses) return;
  for (const PointAnalysis& analysis : study.analyses(scale)) {
    if (analysis.group != g.group) continue;
    for (const PointOutputs& p : outputs) {
      if (!p.usable() || fs::exists(fs::path(p.directory) / analysis.output)) continue;
      const std::string log = (fs::path(p.directory) / (analysis.output + ".log")).string();
      // The analysis's output goes to its log; the shell only redirects, with every word passed as an argument.
      std::vector<std::string> argv{"/bin/sh", "-c", "log=$1; shift; exec \"$@\" > \"$log\" 2>&1", "sh", log, own_executable()};
      for (std::string a : analysis.arguments) {
        if (const std::size_t at = a.find("{run}"); at != std::string::npos) a.replace(at, 5, p.directory);
        argv.push_back(a);
      }
      fmt::print("reproduce: {}/{}/{}: granule {}\n", study.name, g.group, p.name, fmt::join(analysis.arguments, " "));
      std::fflush(stdout);
      if (render::run_program(argv) != 0)
        fmt::print(stderr, "granule reproduce: warning: the analysis of {} failed (see {})\n", p.name, log);
    }
  }
}

// figures/<name>.json (the numbers drawn) and figures/<name>.png; a figure that fails to draw is
// reported and left out of the report's pictures, not fatal.
void draw_figures(const fs::path& out, const StudyOutcome& outcome) {
  fs::create_directories(out / "figures");
  std::fflush(stdout);  // our lines before the script's messages
  for (const Figure& f : outcome.figures) {
    const fs::path data = out / "figures" / (f.name + ".json"), picture = out / "figures" / (f.name + ".png");
    write_file_atomically(data.string(), figure_json(f));
    if (render::run_plot_script("reproduce_figure", {data.string(), "--out", picture.string()}) != 0) {
      fmt::print(stderr, "granule reproduce: warning: figure {} was not drawn\n", f.name);
    }
  }
}

std::string command_line(const ReproduceOptions& o) {
  std::string line = fmt::format("granule reproduce {} --scale {} --out {}", o.what, o.scale, o.out);
  if (o.mpi) return "mpirun -n K " + line + " --mpi";
  return o.jobs > 1 ? line + fmt::format(" --jobs {}", o.jobs) : line;
}

// Rank 0 (or the only process): read, judge, draw and write.
int report(const std::vector<const Study*>& studies, const std::vector<GroupRun>& groups, Scale scale, const ReproduceOptions& o,
           const std::function<double()>& elapsed) {
  const fs::path out = o.out;
  Report r{scale_name(scale), command_line(o), 0.0, 0.0, {}};
  bool complete = true;
  for (const Study* study : studies) {
    StudySection section{study, {}, {}};
    StudyOutputs outputs;
    for (const GroupRun& g : groups) {
      if (g.study != study) continue;
      GroupReading reading = read_group(g);
      complete = complete && reading.complete;
      r.run_seconds += reading.run_seconds;
      outputs[g.group] = std::move(reading.outputs);
      run_point_analyses(*study, scale, g, outputs[g.group]);
      section.run_lines.push_back(reading.tally_line);
    }
    fmt::print("reproduce: analysing {}\n", study->name);
    try {
      section.outcome = study->evaluate(scale, outputs);
    } catch (const std::exception& error) {
      // Missing or unreadable outputs (failed runs): the study is reported as not evaluated.
      section.outcome.notes.push_back(fmt::format("the study could not be evaluated: {}", error.what()));
    }
    draw_figures(out, section.outcome);
    r.sections.push_back(std::move(section));
  }
  r.wall_seconds = elapsed();  // runs, analyses and figures of this call
  write_report(out, r);
  fmt::print("\nclaims ({} scale):\n", r.scale);
  for (const std::string& line : claim_summary_lines(r)) fmt::print("  {}\n", line);
  fmt::print("wrote {0}/report.html, {0}/report.md, {0}/claims.csv, {0}/claims.json and {0}/figures/\n", out.string());
  return complete ? kExitSuccess : kExitSweepIncomplete;
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
      const sweep::MpiWorld& world = mpi.world();
      if (world.rank == 0) {
        for (const GroupRun& g : groups) sweep::prepare_sweep_directory(g.dir, g.spec);
      }
      mpi.broadcast(0);  // every directory exists before any rank runs a point
      // Every rank ends a group before any starts the next: a worker's first request of the next
      // group must not reach rank 0 while it still hands out the points of this one.
      const GroupRunner over_ranks = [&](const sweep::SweepRun& run) {
        sweep::run_points_over_mpi(run, world);
        mpi.broadcast(0);
      };
      const bool whole = run_groups(groups, over_ranks, world.rank == 0);
      const int code = world.rank != 0 ? kExitSuccess
                       : whole         ? report(studies, groups, scale, o, elapsed)
                                       : kExitInterruptedBase + InterruptSignals::received();
      return mpi.broadcast(code);
#else
      throw CommandFailure{kExitBadInput,
                           "--mpi: this granule was built without MPI (install libopenmpi-dev and reconfigure); use --jobs K"};
#endif
    }
    for (const GroupRun& g : groups) sweep::prepare_sweep_directory(g.dir, g.spec);
    const GroupRunner local = [&](const sweep::SweepRun& run) {
      std::vector<std::size_t> indices(run.spec->points.size());
      for (std::size_t k = 0; k < indices.size(); ++k) indices[k] = k;
      sweep::run_points(run, indices, o.jobs, true);
    };
    if (!run_groups(groups, local, true)) {
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
