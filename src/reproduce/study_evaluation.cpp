#include "reproduce/study_evaluation.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstdio>

#include "io/atomic_file.hpp"
#include "io/io_error.hpp"
#include "render/plot_scripts.hpp"

namespace granule::reproduce {

namespace {

namespace fs = std::filesystem;

// The study's analyses of every usable point of the group, each once (its output tells).  A failed
// analysis is reported; the claims that need it then find no number.
void run_point_analyses(const Study& study, Scale scale, const GroupRun& g, const GroupOutputs& outputs,
                        const std::string& granule) {
  if (!study.analyses) return;
  for (const PointAnalysis& analysis : study.analyses(scale)) {
    if (analysis.group != g.group) continue;
    for (const PointOutputs& p : outputs) {
      if (!p.usable() || fs::exists(fs::path(p.directory) / analysis.output)) continue;
      const std::string log = (fs::path(p.directory) / (analysis.output + ".log")).string();
      // The analysis's output goes to its log; the shell only redirects, with every word passed as an argument.
      std::vector<std::string> argv{"/bin/sh", "-c", "log=$1; shift; exec \"$@\" > \"$log\" 2>&1", "sh", log, granule};
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

}  // namespace

StudiesEvaluated evaluate_studies(const std::vector<const Study*>& studies, const std::vector<GroupRun>& groups, Scale scale,
                                  const fs::path& out, const std::string& granule) {
  StudiesEvaluated evaluated;
  for (const Study* study : studies) {
    StudySection section{study, {}, {}};
    StudyOutputs outputs;
    for (const GroupRun& g : groups) {
      if (g.study != study) continue;
      GroupReading reading = read_group(g);
      evaluated.complete = evaluated.complete && reading.complete;
      evaluated.run_seconds += reading.run_seconds;
      outputs[g.group] = std::move(reading.outputs);
      run_point_analyses(*study, scale, g, outputs[g.group], granule);
      section.run_lines.push_back(reading.tally_line);
    }
    fmt::print("reproduce: analysing {}\n", study->name);
    try {
      section.outcome = study->evaluate(scale, outputs);
    } catch (const InputError&) {
      throw;  // a damaged file the user must remove: no report is written from it
    } catch (const std::exception& error) {
      // Outputs the runs did not produce (failed runs): the study is reported as not evaluated, and
      // the report as incomplete.
      section.outcome.notes.push_back(fmt::format("the study could not be evaluated: {}", error.what()));
      fmt::print(stderr, "reproduce: {} could not be evaluated: {}\n", study->name, error.what());
      evaluated.complete = false;
    }
    draw_figures(out, section.outcome);
    evaluated.sections.push_back(std::move(section));
  }
  return evaluated;
}

}  // namespace granule::reproduce
