// The report of `granule reproduce` (docs/reproduce.md, "Report"): DIR/report.md, a
// self-contained DIR/report.html (figures inline as base64 PNG, no external resources), and the
// claims table as DIR/claims.csv and DIR/claims.json.  Every file is written atomically.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "reproduce/study.hpp"

namespace granule::reproduce {

struct StudySection {
  const Study* study = nullptr;
  StudyOutcome outcome;                // empty for a study not built yet
  std::vector<std::string> run_lines;  // how its runs ended ("chapter2/system_I: 2 points: 2 finished")
};

struct Report {
  std::string scale;
  std::string command;        // the command line, to repeat the report
  double wall_seconds = 0.0;  // of this call (runs that finished before are skipped)
  double run_seconds = 0.0;   // the runs' own wall times, summed (their last attempts)
  std::vector<StudySection> sections;
};

// Writes the four files into `dir`; figures are read from dir/figures/<name>.png (a figure whose
// picture is missing is listed with its caption and "not drawn").
void write_report(const std::filesystem::path& dir, const Report& report);

// One line per claim for the terminal: "agrees      validation.haff_sonine: 1.004 ± 0.003 (expected 1, ±3 %)".
std::vector<std::string> claim_summary_lines(const Report& report);

// The numbers of one figure as the JSON text of figures/<name>.json, which
// python/granule_plots/reproduce_figure.py draws.  NaN is not JSON: it is written as null, which
// the script reads as a missing point.
std::string figure_json(const Figure& figure);

// RFC 4648 base64 of `bytes` (the inline pictures of report.html).
std::string base64(const std::string& bytes);

}  // namespace granule::reproduce
