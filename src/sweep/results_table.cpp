#include "sweep/results_table.hpp"

#include <fmt/format.h>

#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>

#include "io/atomic_file.hpp"
#include "sweep/point_record.hpp"
#include "sweep/point_summary.hpp"

namespace granule::sweep {

namespace {

using Row = std::map<std::string, std::string>;

// The scalars of a summary, numbers as JSON writes them (exact, shortest); list items by index
// (box.1 is L_y).  The recursion is as deep as the summary, which its reader bounds.
void flatten(const nlohmann::json& value, const std::string& prefix, Row& row) {
  if (value.is_structured()) {
    for (const auto& [key, inner] : value.items()) flatten(inner, prefix.empty() ? key : prefix + "." + key, row);
  } else if (value.is_string()) {
    row[prefix] = value.get<std::string>();
  } else if (value.is_number() || value.is_boolean()) {
    row[prefix] = value.dump();
  }
}

Row summary_row(const SweepDirectory& dir, const SweepPoint& point) {
  Row row;
  if (const std::optional<JsonFile> summary = read_point_summary(dir, point)) flatten(summary->json(), "", row);
  return row;
}

// RFC 4180: fields holding a comma, a quote or a line break are quoted, quotes doubled.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string out = "\"";
  for (const char ch : text) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return out + "\"";
}

// Appends ",field" (GCC 12 warns falsely, -Wrestrict, on "," + std::string at -O3).
void add_field(std::string& line, const std::string& text) {
  line += ',';
  line += csv_field(text);
}

}  // namespace

void SweepTally::add(const std::string& status) {
  if (status == "finished")
    ++finished;
  else if (status == "collapsed")
    ++collapsed;
  else if (status == "failed")
    ++failed;
  else if (status == "interrupted")
    ++interrupted;
  else
    ++pending;
}

SweepTally write_results(const SweepDirectory& dir, const SweepSpec& spec) {
  SweepTally tally;
  std::vector<Row> summaries;
  std::set<std::string> summary_columns;  // sorted: the columns do not depend on which point ended first
  std::vector<std::string> lines;
  for (const SweepPoint& point : spec.points) {
    const PointRecord record = current_record(dir, point);
    tally.add(record.status);
    Row row = record.status == "pending" ? Row{} : summary_row(dir, point);
    for (const auto& [key, value] : row) summary_columns.insert(key);
    std::string line = csv_field(point.name);
    for (const PointSetting& s : point.settings) add_field(line, s.readable);
    line += fmt::format(",{},{},{},{}", record.status, record.exit_code, csv_field(record.error), record.seconds);
    lines.push_back(line);
    summaries.push_back(std::move(row));
  }
  std::string header = "point";
  for (const std::string& key : spec.keys) add_field(header, key);
  header += ",status,exit_code,error,point_seconds";
  for (const std::string& key : summary_columns) add_field(header, "summary." + key);
  std::string csv = header + "\n";
  for (std::size_t k = 0; k < lines.size(); ++k) {
    csv += lines[k];
    for (const std::string& key : summary_columns) {
      const auto found = summaries[k].find(key);
      add_field(csv, found == summaries[k].end() ? std::string{} : found->second);
    }
    csv += "\n";
  }
  write_file_atomically(dir.results().string(), csv);
  return tally;
}

std::string tally_line(const SweepTally& t, const SweepDirectory& dir) {
  std::string parts;
  const std::pair<const char*, int> counts[] = {{"finished", t.finished},
                                                {"collapsed", t.collapsed},
                                                {"failed", t.failed},
                                                {"interrupted", t.interrupted},
                                                {"pending", t.pending}};
  for (const auto& [name, n] : counts) {
    if (n > 0) parts += fmt::format("{}{} {}", parts.empty() ? "" : ", ", n, name);
  }
  const int total = t.finished + t.collapsed + t.failed + t.interrupted + t.pending;
  return fmt::format("sweep: {} points: {}; results in {}", total, parts, dir.results().string());
}

}  // namespace granule::sweep
