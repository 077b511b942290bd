// The studies of `granule reproduce` judged once their runs ended: every group's outputs read back
// (study_runs.hpp), the studies' own analyses of each usable point run once (`granule analyze …`
// as a child of the executable, its output in a log beside the analysis's), the claims judged and
// the figures drawn into DIR/figures (their numbers as JSON, the pictures by
// python/granule_plots/reproduce_figure.py).  A study that cannot be evaluated, an analysis or a
// figure that fails, is reported and left out, never fatal.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "reproduce/report.hpp"
#include "reproduce/study_runs.hpp"

namespace granule::reproduce {

struct StudiesEvaluated {
  std::vector<StudySection> sections;  // in the order of `studies`
  double run_seconds = 0.0;            // the runs' own wall times, summed (their last attempts)
  bool complete = true;                // every point of every group finished, every study evaluated
};

StudiesEvaluated evaluate_studies(const std::vector<const Study*>& studies, const std::vector<GroupRun>& groups, Scale scale,
                                  const std::filesystem::path& out, const std::string& granule);

}  // namespace granule::reproduce
