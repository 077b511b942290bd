#include "fuzz/text_readers.hpp"

#include <filesystem>

#include "fuzz/text_mutator.hpp"
#include "io/timeseries_csv.hpp"
#include "sweep/point_record.hpp"
#include "sweep/results_table.hpp"

namespace granule::fuzz {

namespace {

namespace fs = std::filesystem;

// The one-point sweep under WORK whose point is ORIGINAL's (points/NAME.json → NAME).
struct RecordSweep {
  sweep::SweepDirectory dir;
  sweep::SweepSpec spec;
};

RecordSweep record_sweep(const std::string& original, const std::string& work) {
  RecordSweep s{sweep::SweepDirectory{fs::path(work) / "sweep"}, {}};
  s.spec.points.push_back(sweep::SweepPoint{fs::path(original).stem().string(), {}});
  return s;
}

// ORIGINAL's sweep directory: DIR/points/NAME.json → DIR.
fs::path original_sweep(const std::string& original) { return fs::path(original).parent_path().parent_path(); }

}  // namespace

bool is_text_reader(const std::string& reader) { return reader == "sweep-record" || reader == "timeseries"; }

std::string prepare_text_mutant(const std::string& reader, const std::string& original, const std::string& work,
                                std::uint64_t seed, std::uint64_t index) {
  if (reader == "timeseries") return write_text_mutant(original, work + "/timeseries.csv", seed, index);
  const RecordSweep s = record_sweep(original, work);
  const sweep::SweepPoint& point = s.spec.points.front();
  const fs::path summary = s.dir.run(point) / "summary.json";
  fs::create_directories(s.dir.record(point).parent_path());
  fs::create_directories(summary.parent_path());
  fs::copy_file(original_sweep(original) / "runs" / point.name / "summary.json", summary,
                fs::copy_options::overwrite_existing);
  fs::remove(s.dir.record(point));
  if (index % 2 == 1) return "summary.json: " + write_text_mutant(summary.string(), summary.string(), seed, index);
  return "record: " + write_text_mutant(original, s.dir.record(point).string(), seed, index);
}

void read_text_mutant(const std::string& reader, const std::string& original, const std::string& work) {
  if (reader == "timeseries") {
    read_timeseries(work + "/timeseries.csv");
    return;
  }
  // What a restart does before it starts a point, then what it and --collect read; results.csv
  // (synced to disk, the slow part) only where it reads more: every scalar of a summary.
  const RecordSweep s = record_sweep(original, work);
  sweep::check_point_files(s.dir, s.spec, {0});
  sweep::current_record(s.dir, s.spec.points.front());
  if (!fs::exists(s.dir.record(s.spec.points.front()))) sweep::write_results(s.dir, s.spec);
}

}  // namespace granule::fuzz
