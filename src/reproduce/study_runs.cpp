#include "reproduce/study_runs.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <functional>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <utility>

#include "io/io_error.hpp"
#include "io/json_file.hpp"
#include "io/timeseries_csv.hpp"
#include "sweep/point_record.hpp"
#include "sweep/point_runs.hpp"
#include "sweep/point_summary.hpp"
#include "sweep/results_table.hpp"

namespace granule::reproduce {

namespace fs = std::filesystem;

namespace {

// Where a group's runs lie under the report's directory.
fs::path group_path(const Study& study, const std::string& group) { return fs::path("runs") / study.name / group; }

}  // namespace

std::vector<GroupRun> planned_groups(const std::vector<const Study*>& studies, Scale scale, const fs::path& out) {
  std::vector<GroupRun> groups;
  for (const Study* study : studies) {
    for (const RunGroup& g : study->runs(scale)) {
      sweep::SweepSpecResult parsed = sweep::parse_sweep_spec(g.sweep_toml);
      // The catalogue's own specs: a refusal is a bug of the study, not the user's input.
      if (!parsed.spec) throw std::logic_error(fmt::format("{}/{}: {}", study->name, g.name, parsed.error));
      groups.push_back({study, g.name, std::move(*parsed.spec), sweep::SweepDirectory{out / group_path(*study, g.name)}});
    }
  }
  return groups;
}

namespace {

// Runs all points of one group: K at a time locally, or over the MPI ranks.
using GroupRunner = std::function<void(const sweep::SweepRun&)>;

// Runs every group's points (skipping finished ones) with `run_all`.  Returns false when a signal
// stopped it.
bool run_groups(const std::vector<GroupRun>& groups, const GroupRunner& run_all, bool announce, const std::string& granule,
                const volatile std::sig_atomic_t* interrupt) {
  std::size_t total = 0;
  for (const GroupRun& g : groups) total += g.spec.points.size();
  std::size_t done = 0;
  for (const GroupRun& g : groups) {
    if (*interrupt != 0) return false;
    if (announce) {
      fmt::print("reproduce: [{}/{} runs] {}/{}: {} point(s)\n", done, total, g.study->name, g.group, g.spec.points.size());
      std::fflush(stdout);
    }
    run_all(sweep::SweepRun{granule, g.dir, &g.spec, interrupt});
    done += g.spec.points.size();
  }
  return *interrupt == 0;
}

}  // namespace

bool run_groups_locally(const std::vector<GroupRun>& groups, int jobs, const std::string& granule,
                        const volatile std::sig_atomic_t* interrupt) {
  for (const GroupRun& g : groups) sweep::prepare_sweep_directory(g.dir, g.spec);
  const GroupRunner local = [&](const sweep::SweepRun& run) {
    std::vector<std::size_t> indices(run.spec->points.size());
    for (std::size_t k = 0; k < indices.size(); ++k) indices[k] = k;
    sweep::run_points(run, indices, jobs, true);
  };
  return run_groups(groups, local, true, granule, interrupt);
}

#ifdef GRANULE_HAVE_MPI
bool run_groups_over_mpi(const std::vector<GroupRun>& groups, const sweep::MpiSession& mpi, const std::string& granule,
                         const volatile std::sig_atomic_t* interrupt) {
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
  return run_groups(groups, over_ranks, world.rank == 0, granule, interrupt);
}
#endif

GroupReading read_group(const GroupRun& g) {
  const sweep::SweepTally tally = sweep::write_results(g.dir, g.spec);
  GroupReading reading;
  reading.complete = tally.complete();
  // The results' path as the report's directory sees it: a report moved or committed elsewhere still
  // names its runs.
  std::string line = sweep::tally_line(tally, g.dir);
  const std::string absolute = g.dir.results().string();
  if (const std::size_t at = line.rfind(absolute); at != std::string::npos) {
    line.replace(at, absolute.size(), (group_path(*g.study, g.group) / g.dir.results().filename()).string());
  }
  reading.tally_line = fmt::format("{}/{}: {}", g.study->name, g.group, line);
  GroupOutputs& outputs = reading.outputs;
  for (const sweep::SweepPoint& point : g.spec.points) {
    PointOutputs p;
    p.name = point.name;
    p.directory = g.dir.run(point).string();
    const sweep::PointRecord record = sweep::current_record(g.dir, point);
    p.status = record.status;
    reading.run_seconds += record.seconds;
    for (const sweep::PointSetting& s : point.settings) p.settings.emplace_back(s.key, s.readable);
    const fs::path run = g.dir.run(point);
    if (fs::exists(run / "timeseries.csv")) p.samples = read_timeseries((run / "timeseries.csv").string());
    // Read as untrusted input: a damaged summary is refused by name (sweep::read_point_summary), and
    // a run that finished must have one, since its claims read it.
    if (const std::optional<JsonFile> summary = sweep::read_point_summary(g.dir, point)) p.summary = summary->json();
    if (p.usable() && p.summary.is_null()) {
      throw InputError(fmt::format("{}: the run {} but has no summary.json; delete {} to run the point again",
                                   p.directory, p.status, p.directory));
    }
    outputs.push_back(std::move(p));
  }
  return reading;
}


}  // namespace granule::reproduce
