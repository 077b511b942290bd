// The studies `granule reproduce` knows, in the report's order, and the helpers they share.
#include <fmt/format.h>

#include "io/io_error.hpp"
#include "reproduce/study.hpp"

namespace granule::reproduce {

std::string scale_name(Scale scale) {
  switch (scale) {
    case Scale::tiny:
      return "tiny";
    case Scale::small:
      return "small";
    case Scale::medium:
      return "medium";
    case Scale::thesis:
      return "thesis";
  }
  return "";
}

std::optional<Scale> scale_named(const std::string& name) {
  for (Scale s : {Scale::tiny, Scale::small, Scale::medium, Scale::thesis}) {
    if (scale_name(s) == name) return s;
  }
  return std::nullopt;
}

double summary_number(const PointOutputs& point, const char* key) {
  const nlohmann::json* node = &point.summary;
  std::string path = key;
  std::size_t start = 0;
  while (node != nullptr && start <= path.size()) {
    const std::size_t dot = path.find('.', start);
    const std::string part = path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (node->is_object() && node->contains(part)) {
      node = &(*node)[part];
    } else if (node->is_array() && !part.empty() && part.find_first_not_of("0123456789") == std::string::npos &&
               std::stoul(part) < node->size()) {
      node = &(*node)[std::stoul(part)];
    } else {
      node = nullptr;
    }
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  if (node == nullptr || !node->is_number()) {
    throw InputError(fmt::format("{}/summary.json: \"{}\" is missing or not a number, which the study reads; delete {} to run "
                                 "the point again",
                                 point.directory, key, point.directory));
  }
  return node->get<double>();
}

Claim hypothesis_claim(const Claim& base, const std::string& suffix, const std::string& hypothesis, const Estimate& measured,
                       const std::string& how, std::string unresolvable) {
  Claim c = base;
  c.id += "." + suffix;
  c.statement += " (hypothesis: " + hypothesis + ")";
  c.measured = measured.mean;
  c.error = measured.error;
  c.checked += "; " + how;
  c.unresolvable = std::move(unresolvable);
  return c;
}

Claim estimate_claim(std::string id, std::string statement, std::string location, double expected, const Estimate& measured,
                     double tolerance, std::string tolerance_reason, std::string checked, ToleranceKind kind) {
  Claim c;
  c.id = std::move(id);
  c.statement = std::move(statement);
  c.location = std::move(location);
  c.expected = expected;
  c.measured = measured.mean;
  c.error = measured.error;
  c.tolerance = tolerance;
  c.tolerance_kind = kind;
  c.tolerance_reason = std::move(tolerance_reason);
  c.checked = std::move(checked);
  return c;
}

const std::vector<Study>& all_studies() {
  static const std::vector<Study> studies{
      validation_study(),
      chapter2_study(),
      chapter3_study(),
      chapter4_study(),
      chapter5_study(),
      appendix_b_study(),
      appendix_c_study(),
  };
  return studies;
}

std::vector<const Study*> studies_named(const std::string& what) {
  std::vector<const Study*> chosen;
  for (const Study& s : all_studies()) {
    if (what == "all" || what == s.name) chosen.push_back(&s);
  }
  return chosen;
}

}  // namespace granule::reproduce
