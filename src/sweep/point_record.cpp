#include "sweep/point_record.hpp"

#include <fmt/format.h>
#include <sys/wait.h>

#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <vector>

#include "engine/stop_reason_names.hpp"
#include "io/atomic_file.hpp"
#include "io/json_file.hpp"
#include "sweep/point_summary.hpp"

namespace granule::sweep {

namespace {

constexpr int kExitCollapse = 3;  // src/app/exit_codes.hpp: outputs written

// A record holds five short values (a run's error line is cut at 500 characters).
constexpr std::size_t kMaxRecordBytes = 64 * 1024;

// The statuses write_record writes: a point never run has no record.
const std::vector<std::string> kRecordedStatuses = {"finished", "collapsed", "interrupted", "failed"};

// How the run said it stopped (summary.json "stop_reason").
StopReason stop_reason_in(const JsonFile& summary) {
  std::vector<std::string> names;
  for (const auto& [reason, name] : kStopReasonNames) names.emplace_back(name);
  const std::string& text = summary.one_of("stop_reason", names);
  for (const auto& [reason, name] : kStopReasonNames) {
    if (text == name) return reason;
  }
  summary.refuse("stop_reason", "a stop reason");  // one_of accepted only the names above
}

// The run's own explanation: its first "error:" line, else the last line it printed.
std::string error_from_log(const std::string& log_path) {
  std::ifstream log(log_path);
  std::string last;
  for (std::string line; std::getline(log, line);) {
    if (line.find("error:") != std::string::npos) return line.substr(0, 500);
    if (!line.empty()) last = line;
  }
  return last.substr(0, 500);
}

}  // namespace

PointRecord record_of_exit(int wait_status, double seconds, const std::string& log_path) {
  PointRecord r;
  r.seconds = seconds;
  if (WIFSIGNALED(wait_status)) {
    r.status = "failed";
    r.exit_code = 128 + WTERMSIG(wait_status);
    r.error = fmt::format("the run died of signal {} ({})", WTERMSIG(wait_status), strsignal(WTERMSIG(wait_status)));
    return r;
  }
  r.exit_code = WEXITSTATUS(wait_status);
  if (r.exit_code == 0) {
    r.status = "finished";
  } else if (r.exit_code == kExitCollapse) {
    r.status = "collapsed";
  } else if (r.exit_code == 128 + SIGINT || r.exit_code == 128 + SIGTERM) {
    r.status = "interrupted";
  } else {
    r.status = "failed";
    r.error = error_from_log(log_path);
  }
  return r;
}

std::optional<PointRecord> record_from_summary(const SweepDirectory& dir, const SweepPoint& point) {
  const std::optional<JsonFile> summary = read_point_summary(dir, point);
  if (!summary) return std::nullopt;
  const StopReason reason = stop_reason_in(*summary);
  if (reason == StopReason::kInterrupted) return std::nullopt;
  PointRecord r;
  r.status = reason == StopReason::kInelasticCollapse ? "collapsed" : "finished";
  r.exit_code = reason == StopReason::kInelasticCollapse ? kExitCollapse : 0;
  r.seconds = summary->number("wall_seconds", 0.0, std::numeric_limits<double>::max());
  return r;
}

void write_record(const SweepDirectory& dir, const SweepPoint& point, const PointRecord& record) {
  const nlohmann::json j = {{"point", point.name},
                            {"status", record.status},
                            {"exit_code", record.exit_code},
                            {"error", record.error},
                            {"seconds", record.seconds}};
  write_file_atomically(dir.record(point).string(), j.dump(2) + "\n");
}

std::optional<PointRecord> read_record(const SweepDirectory& dir, const SweepPoint& point) {
  const std::optional<JsonFile> j = JsonFile::read(
      dir.record(point), kMaxRecordBytes, 1,
      fmt::format("the record is damaged: delete it to run point {} again (a run that finished is then "
                  "taken from its summary.json)",
                  point.name));
  if (!j) return std::nullopt;
  if (j->string("point") != point.name) j->refuse("point", fmt::format("\"{}\", the point the record is named after", point.name));
  PointRecord r;
  r.status = j->one_of("status", kRecordedStatuses);
  r.exit_code = static_cast<int>(j->integer("exit_code", 0, 255));
  r.error = j->string("error");
  r.seconds = j->number("seconds", 0.0, std::numeric_limits<double>::max());
  return r;
}

PointRecord current_record(const SweepDirectory& dir, const SweepPoint& point) {
  if (std::optional<PointRecord> r = read_record(dir, point)) return *r;
  return record_from_summary(dir, point).value_or(PointRecord{});
}

void check_point_files(const SweepDirectory& dir, const SweepSpec& spec, const std::vector<std::size_t>& indices) {
  for (const std::size_t k : indices) {
    read_record(dir, spec.points[k]);
    record_from_summary(dir, spec.points[k]);
  }
}

bool is_done(const PointRecord& record) { return record.status == "finished" || record.status == "collapsed"; }

}  // namespace granule::sweep
