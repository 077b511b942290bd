#include "io/config_restitution.hpp"

#include <fmt/format.h>

#include <iterator>

#include "io/input_ranges.hpp"

namespace granule {

namespace {

// The names of the laws, in the order of RestitutionKind.
constexpr const char* kKindNames[] = {"constant", "threshold", "viscoelastic"};

const char* kind_name(RestitutionKind kind) { return kKindNames[static_cast<int>(kind)]; }

}  // namespace

void resolve_restitution_law(const ConfigReader& in, RunConfig& c) {
  RestitutionLaw& law = c.system.restitution_law;
  const std::string kind = in.text("system.restitution_law", {std::begin(kKindNames), std::end(kKindNames)}).value_or("constant");
  for (int k = 0; k < static_cast<int>(std::size(kKindNames)); ++k) {
    if (kind == kKindNames[k]) law.kind = static_cast<RestitutionKind>(k);
  }
  law.reference_radius = 0.5 * c.system.diameter;
  const auto needs = [&](const char* key, RestitutionKind owner) {
    if (in.has(key) && law.kind != owner) {
      throw ConfigError{fmt::format("{} is for system.restitution_law = \"{}\" (this run's law is \"{}\")", key,
                                    kind_name(owner), kind)};
    }
  };
  needs("system.elastic_below", RestitutionKind::kThreshold);
  needs("system.viscoelastic_constant", RestitutionKind::kViscoelastic);
  if (law.kind == RestitutionKind::kThreshold) {
    const auto speed = in.number("system.elastic_below", kThresholdSpeeds,
                                 " (v_c: contacts whose normal impact speed is below it are elastic)");
    if (!speed) throw ConfigError{"system.restitution_law = \"threshold\" needs system.elastic_below = v_c > 0"};
    law.elastic_below = *speed;
  }
  if (law.kind == RestitutionKind::kViscoelastic) {
    if (in.has("system.restitution")) {
      throw ConfigError{"system.restitution cannot be combined with system.restitution_law = \"viscoelastic\": ẽ follows "
                        "from the impact speed and system.viscoelastic_constant"};
    }
    const auto delta = in.number("system.viscoelastic_constant", kViscoelasticConstants,
                                 " (δ = (3/2) A ρ^(2/5) of two grains of diameter σ and unit mass, in (time/length)^(1/5): "
                                 "ẽ = 1 − 1.15344 δ g^(1/5) + … at impact speed g)");
    if (!delta) throw ConfigError{"system.restitution_law = \"viscoelastic\" needs system.viscoelastic_constant = δ > 0"};
    law.viscoelastic_constant = *delta;
    // Every contact follows the law; the constant ẽ of the other laws has no part in it.
    c.system.restitution = 1.0;
  }
}

std::string restitution_law_to_toml(const RunConfig& c) {
  const RestitutionLaw& law = c.system.restitution_law;
  std::string out = fmt::format("restitution_law = \"{}\"\n", kind_name(law.kind));
  if (law.kind == RestitutionKind::kThreshold) out += fmt::format("elastic_below = {:.17g}\n", law.elastic_below);
  if (law.kind == RestitutionKind::kViscoelastic) out += fmt::format("viscoelastic_constant = {:.17g}\n", law.viscoelastic_constant);
  return out;
}

}  // namespace granule
