#include "sweep/point_record.hpp"

#include <fmt/format.h>
#include <sys/wait.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "io/atomic_file.hpp"

namespace granule::sweep {

namespace {

constexpr int kExitCollapse = 3;  // src/app/exit_codes.hpp: outputs written

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
  std::ifstream file(dir.run(point) / "summary.json");
  if (!file) return std::nullopt;
  const nlohmann::json summary = nlohmann::json::parse(file, nullptr, false);
  if (summary.is_discarded() || !summary.contains("stop_reason")) return std::nullopt;
  const std::string reason = summary["stop_reason"].get<std::string>();
  if (reason == "interrupted") return std::nullopt;
  PointRecord r;
  r.status = reason == "inelastic collapse" ? "collapsed" : "finished";
  r.exit_code = reason == "inelastic collapse" ? kExitCollapse : 0;
  r.seconds = summary.value("wall_seconds", 0.0);
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
  std::ifstream file(dir.record(point));
  if (!file) return std::nullopt;
  const nlohmann::json j = nlohmann::json::parse(file, nullptr, false);
  if (j.is_discarded()) return std::nullopt;
  PointRecord r;
  r.status = j.value("status", "pending");
  r.exit_code = j.value("exit_code", -1);
  r.error = j.value("error", "");
  r.seconds = j.value("seconds", 0.0);
  return r;
}

PointRecord current_record(const SweepDirectory& dir, const SweepPoint& point) {
  if (std::optional<PointRecord> r = read_record(dir, point)) return *r;
  return record_from_summary(dir, point).value_or(PointRecord{});
}

bool is_done(const PointRecord& record) { return record.status == "finished" || record.status == "collapsed"; }

}  // namespace granule::sweep
