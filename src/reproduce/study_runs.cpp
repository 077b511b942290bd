#include "reproduce/study_runs.hpp"

#include <fmt/format.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <utility>

#include "io/timeseries_csv.hpp"
#include "sweep/point_record.hpp"
#include "sweep/results_table.hpp"

namespace granule::reproduce {

namespace fs = std::filesystem;

std::vector<GroupRun> planned_groups(const std::vector<const Study*>& studies, Scale scale, const fs::path& out) {
  std::vector<GroupRun> groups;
  for (const Study* study : studies) {
    for (const RunGroup& g : study->runs(scale)) {
      sweep::SweepSpecResult parsed = sweep::parse_sweep_spec(g.sweep_toml);
      // The catalogue's own specs: a refusal is a bug of the study, not the user's input.
      if (!parsed.spec) throw std::logic_error(fmt::format("{}/{}: {}", study->name, g.name, parsed.error));
      groups.push_back({study, g.name, std::move(*parsed.spec), sweep::SweepDirectory{out / "runs" / study->name / g.name}});
    }
  }
  return groups;
}

GroupReading read_group(const GroupRun& g) {
  const sweep::SweepTally tally = sweep::write_results(g.dir, g.spec);
  GroupReading reading;
  reading.complete = tally.complete();
  reading.tally_line = fmt::format("{}/{}: {}", g.study->name, g.group, sweep::tally_line(tally, g.dir));
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
    std::ifstream summary(run / "summary.json");
    if (summary) p.summary = nlohmann::json::parse(summary, nullptr, false);
    if (p.summary.is_discarded()) p.summary = nullptr;
    outputs.push_back(std::move(p));
  }
  return reading;
}


}  // namespace granule::reproduce
