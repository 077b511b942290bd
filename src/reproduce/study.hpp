// A study: one part of the thesis (or the independent validation) as `granule reproduce` runs it
// (docs/reproduce.md).  It declares the runs it needs at each scale as sweep specs (README.md,
// "Sweeps"), and turns their outputs into claims (claim.hpp) and figures.  Studies are plain
// data plus two functions; the command (src/app/reproduce/reproduce_command.cpp) runs, draws and reports.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "reproduce/claim.hpp"
#include "reproduce/run_outputs.hpp"

namespace granule::reproduce {

// tiny: seconds in all, for the tests only; small: minutes on two cores for `all`; medium: ~10×
// small; thesis: the thesis's N.
enum class Scale { tiny, small, medium, thesis };

std::string scale_name(Scale scale);
// The scale of that name (scale_name), none if unknown.
std::optional<Scale> scale_named(const std::string& name);

// The value a study uses at each scale.
template <typename T>
T by_scale(Scale scale, T tiny, T small, T medium, T thesis) {
  switch (scale) {
    case Scale::tiny:
      return tiny;
    case Scale::small:
      return small;
    case Scale::medium:
      return medium;
    case Scale::thesis:
      return thesis;
  }
  return small;
}

// Runs of one study that share a base configuration: a sweep spec (TOML with a [sweep] table).
struct RunGroup {
  std::string name;  // a folder name: DIR/runs/<study>/<name>
  std::string sweep_toml;
};

// One curve or set of points of a figure; `error` empty or one standard error per point.
struct FigureSeries {
  std::string label;
  std::vector<double> x, y, error;
  bool line = false;  // a theory curve (a line), else measured points
};

struct Figure {
  std::string name;           // file stem: DIR/figures/<name>.png
  std::string thesis_figure;  // "Fig 2.5(F)", or "Validation" for a figure outside the thesis
  std::string caption;        // what it shows (the thesis's caption where it has one)
  std::string x_label, y_label;
  bool log_x = false, log_y = false;
  std::vector<FigureSeries> series;
};

// A `granule` analysis run on every usable point of a group once its runs ended, e.g. `analyze
// spectra`: "{run}" in the arguments stands for the point's run directory; skipped when `output`
// (relative to it) exists, so a second call does not repeat it.
struct PointAnalysis {
  std::string group;
  std::vector<std::string> arguments;
  std::string output;
};

struct StudyOutcome {
  std::vector<Claim> claims;
  std::vector<Figure> figures;
  std::vector<std::string> notes;  // what a reader must know beside the claims (scale, caveats)
};

// The outputs of every group of a study, by group name.
using StudyOutputs = std::map<std::string, GroupOutputs>;

struct Study {
  std::string name;  // the command's word: "validation", "chapter2", ...
  std::string title;
  std::string thesis_part;  // "Chapter 2 (free cooling, Systems I and II)"
  std::function<std::vector<RunGroup>(Scale)> runs;
  std::function<StudyOutcome(Scale, const StudyOutputs&)> evaluate;
  // By scale, since an analysis's arguments may be in the run's units (the f1 windows of chapter5).
  std::function<std::vector<PointAnalysis>(Scale)> analyses;
};

// The catalogue, in the report's order (catalogue.cpp).
const std::vector<Study>& all_studies();
// The study named `what`, or every study for "all"; empty when no study has that name.
std::vector<const Study*> studies_named(const std::string& what);

// The run's number `key` of summary.json ("a.b", "box.0"); InputError, naming the file and the key,
// when it is absent or not a number.
double summary_number(const PointOutputs& point, const char* key);

// A claim about a number estimated over seeds (its mean and standard error).
Claim estimate_claim(std::string id, std::string statement, std::string location, double expected, const Estimate& measured,
                     double tolerance, std::string tolerance_reason, std::string checked,
                     ToleranceKind kind = ToleranceKind::relative);

// A hypothesis for a disagreement, tested as the claim `base` measured another way: id
// `base.id.suffix`, the hypothesis in parentheses after the statement, `how` after the check, the
// other measurement, and its own reason when it cannot be judged (empty: it can).
Claim hypothesis_claim(const Claim& base, const std::string& suffix, const std::string& hypothesis, const Estimate& measured,
                       const std::string& how, std::string unresolvable);

// One per file.
Study validation_study();
Study chapter2_study();
Study chapter3_study();
Study chapter4_study();
Study chapter5_study();
Study appendix_b_study();
Study appendix_c_study();

}  // namespace granule::reproduce
