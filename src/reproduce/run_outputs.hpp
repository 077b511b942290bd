// What the runs of a study left on disk, read back for its claims: each point's time series
// (timeseries.csv), summary.json and how it ended, and the statistics the claims need (means over
// seeds with standard errors, time averages, straight-line fits with the error of the slope).
#pragma once

#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "observers/global_diagnostics.hpp"

namespace granule::reproduce {

struct PointOutputs {
  std::string name;       // the sweep point's name
  std::string directory;  // its run directory (the outputs of PointAnalysis too)
  std::string status;     // finished, collapsed, failed, interrupted, pending (sweep/point_record.hpp)
  std::vector<DiagnosticsSample> samples;
  nlohmann::json summary;  // null when the run wrote none
  // The value of a swept key at this point as its readable text ("0.8"), "" when not swept.
  std::vector<std::pair<std::string, std::string>> settings;
  std::string setting(const std::string& key) const;
  bool usable() const { return (status == "finished" || status == "collapsed") && !samples.empty(); }
};

using GroupOutputs = std::vector<PointOutputs>;

// The usable points of a group whose setting `key` reads `value` (all usable points when `key` is
// empty): the seeds of one parameter set.
std::vector<const PointOutputs*> points_with(const GroupOutputs& group, const std::string& key = "",
                                             const std::string& value = "");

inline constexpr int kLeastValuesForAnError = 3;

struct Estimate {
  double mean = 0.0;
  double error = 0.0;  // standard error; NaN from fewer than three values (two give one degree of freedom)
  int count = 0;
};

// Mean and standard error of independent values (one per seed); NaN entries are skipped.  No error is
// quoted from fewer than kLeastValuesForAnError values: from two, the error's own uncertainty is as large as
// itself, and a verdict would lean on chance.
Estimate mean_over(const std::vector<double>& values);

// The mean of `value(sample)` over the samples with c in [c_from, c_to] (NaN if none).
template <typename Value>
double window_mean(const std::vector<DiagnosticsSample>& samples, double c_from, double c_to, Value value) {
  double sum = 0.0;
  int count = 0;
  for (const DiagnosticsSample& s : samples) {
    if (s.c >= c_from && s.c <= c_to) {
      sum += value(s);
      ++count;
    }
  }
  return count > 0 ? sum / count : std::numeric_limits<double>::quiet_NaN();
}

// The rows of a plain CSV file (no quoted commas: the analyses' own tables) as column → text;
// empty when the file is missing.
std::vector<std::map<std::string, std::string>> read_csv_rows(const std::string& path);

// Ordinary least-squares line y = a + b x; NaN with fewer than three points.
struct LineFit {
  double intercept = 0.0, slope = 0.0;
  double slope_error = 0.0;  // from the residual scatter (samples of a run are correlated: use seeds for errors)
};
LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y);

// The early exponential decay of a freely cooling gas and where it ends (thesis §2.4.2, Fig 2.5):
// the slope of ln T̄ (`temperature`) against c over c ∈ [1, early_to_c], and the first c > 1 at
// which the kinetic energy exceeds the extrapolation of its own exponential fit over that window
// by the factor `excess` (the change of slope of Fig 2.5; NaN if it never does).
struct EarlyDecay {
  double temperature_slope = std::numeric_limits<double>::quiet_NaN();
  double onset_c = std::numeric_limits<double>::quiet_NaN();
};
EarlyDecay early_decay(const std::vector<DiagnosticsSample>& samples, double early_to_c, double excess);

}  // namespace granule::reproduce
