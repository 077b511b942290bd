#include "io/config_geometry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "init/placement.hpp"
#include "io/input_ranges.hpp"

namespace granule {

namespace {

constexpr double kDefaultPackingFraction = 0.05;
// Size ratio σ_B/σ_A and log-normal width: beyond them a cell sized by the largest diameter holds
// thousands of the smallest particles.
constexpr NumberRange kSizeRatios{1e-2, 1e2};
constexpr NumberRange kUniformWidths{0.0, 1.0, true, true};   // σ̄ (1 − w) > 0
constexpr NumberRange kLogNormalWidths{0.0, 1.0, true, false};
constexpr NumberRange kFractions{0.0, 1.0, true, true};
// The lattice must clear the largest diameter by the placement's margin (10⁻⁹ on the spacing)
// with room for the round-off of σ̄ · r_max.
constexpr double kLatticeMargin = 1.0 + 2e-9;

std::string box_text(const SystemParams& s) {
  return s.dimension == 3 ? fmt::format("[{}, {}, {}]", s.length_x, s.length_y, s.length_z)
                          : fmt::format("[{}, {}]", s.length_x, s.length_y);
}

SizeDistribution resolve_distribution(const ConfigReader& in, int dimension) {
  SizeDistribution dist;
  if (in.table_with_keys("system.diameters", {"distribution", "ratio", "fraction", "width"})) {
    const auto kind = in.text("system.diameters.distribution", {"monodisperse", "bidisperse", "uniform", "lognormal"});
    if (!kind) {
      throw ConfigError{"system.diameters needs a distribution: { distribution = \"monodisperse\" }, "
                        "{ distribution = \"bidisperse\", ratio = σ_B/σ_A, fraction = x_B }, "
                        "{ distribution = \"uniform\", width = w } or { distribution = \"lognormal\", width = s }"};
    }
    const std::set<std::string> parameters = *kind == "bidisperse" ? std::set<std::string>{"ratio", "fraction"}
                                             : *kind == "monodisperse" ? std::set<std::string>{}
                                                                       : std::set<std::string>{"width"};
    for (const char* key : {"ratio", "fraction", "width"}) {
      const std::string path = std::string("system.diameters.") + key;
      if (in.has(path) && !parameters.count(key)) {
        throw ConfigError{fmt::format("{} is not a parameter of the {} distribution (it takes {})", path, *kind,
                                      parameters.empty() ? "none" : *kind == "bidisperse" ? "ratio and fraction" : "width")};
      }
    }
    for (const std::string& key : parameters) {
      if (!in.has("system.diameters." + key)) {
        throw ConfigError{fmt::format("system.diameters.{} is missing: the {} distribution needs it", key, *kind)};
      }
    }
    if (*kind == "bidisperse") {
      dist.kind = SizeDistributionKind::kBidisperse;
      dist.ratio = *in.number("system.diameters.ratio", kSizeRatios, " (σ_B/σ_A)");
      dist.fraction = *in.number("system.diameters.fraction", kFractions, " (x_B, the number fraction of species B)");
    } else if (*kind == "uniform") {
      dist.kind = SizeDistributionKind::kUniform;
      dist.width = *in.number("system.diameters.width", kUniformWidths, " (σ uniform in [σ̄ (1 − w), σ̄ (1 + w)])");
    } else if (*kind == "lognormal") {
      dist.kind = SizeDistributionKind::kLogNormal;
      dist.width = *in.number("system.diameters.width", kLogNormalWidths, " (the standard deviation s of ln σ)");
    }
  }
  if (in.holds_text("system.masses")) {
    in.text("system.masses", {"volume"});
  } else if (in.has("system.masses")) {
    if (dist.kind != SizeDistributionKind::kBidisperse) {
      throw ConfigError{"system.masses as species masses [m_A, m_B] needs system.diameters = { distribution = "
                        "\"bidisperse\", ... }; allowed otherwise: \"volume\" (m ∝ σ^" + std::to_string(dimension) +
                        ", mean mass 1)"};
    }
    const auto masses = in.number_list("system.masses", 2, kMassRange, "\"volume\" or [m_A, m_B]");
    dist.species_masses = std::pair{(*masses)[0], (*masses)[1]};
  }
  return dist;
}

// The largest packing fraction a run may have, and why.  Monodisperse: close packing (exclusive).
// Polydisperse: what the placement reaches — `auto` random sequential addition up to its limit
// and above it the densest lattice of N sites this box holds, its spacing set by the largest
// diameter; `lattice` that lattice alone; `random` and a state taken from another run are bounded
// by the close packing of equal particles only (random addition reports jamming when it starts).
struct PackingLimit {
  double value = 0.0;
  bool inclusive = false;
  std::string reason;
};

PackingLimit packing_limit(const RunConfig& c, const RelativeSizeSummary& sizes, double volume, bool new_gas) {
  const SystemParams& s = c.system;
  const int d = s.dimension;
  const std::string close = d == 3 ? "FCC close packing π/(3√2)" : "hexagonal close packing π/(2√3)";
  if (c.diameters.monodisperse() || !new_gas || c.placement == Placement::kRandom) {
    return {close_packing(d), false, "below " + close};
  }
  const double lattice_reach =
      packing_fraction(d, sizes.sum_of_powers, densest_lattice(s).spacing / (sizes.largest * kLatticeMargin), volume);
  const std::string lattice = fmt::format("a {} lattice of {} sites in this box, its spacing set by the largest diameter, "
                                          "reaches {}", d == 3 ? "FCC" : "triangular", s.particles, lattice_reach);
  if (c.placement == Placement::kLattice) return {lattice_reach, true, "placement \"lattice\": " + lattice};
  const double random = random_placement_limit(d);
  return {std::max(random, lattice_reach), true,
          fmt::format("placement \"auto\": random addition up to {}, {}", random, lattice)};
}

}  // namespace

void resolve_geometry(const ConfigReader& in, RunConfig& c) {
  SystemParams& s = c.system;
  s.dimension = static_cast<int>(in.integer("system.dimension", 2, 3).value_or(2));
  const int d = s.dimension;
  const std::string shape = d == 3 ? "[Lx, Ly, Lz]" : "[Lx, Ly]";
  const auto box = in.number_list("system.box", static_cast<std::size_t>(d), kLengthRange, shape,
                                  fmt::format(" for system.dimension = {}", d))
                       .value_or(std::vector<double>(static_cast<std::size_t>(d), 1.0));
  s.length_x = box[0];
  s.length_y = box[1];
  s.length_z = d == 3 ? box[2] : 1.0;

  if (d == 3 && in.has("system.area_fraction")) {
    throw ConfigError{"system.area_fraction is the 2D name of the packing fraction: with system.dimension = 3 give "
                      "the volume fraction as system.packing_fraction"};
  }
  if (in.has("system.area_fraction") && in.has("system.packing_fraction")) {
    throw ConfigError{"system.area_fraction and system.packing_fraction are both set: in 2D they are the same "
                      "(the area fraction); give one"};
  }
  const std::string nu_key = d == 2 && !in.has("system.packing_fraction") ? "system.area_fraction" : "system.packing_fraction";
  c.diameters = resolve_distribution(in, d);
  const RelativeSizeSummary sizes = summarize_relative_sizes(c.diameters, d, s.particles, c.seed);

  // Every diameter at least L_max / 10⁹ (positions resolve contacts) and ν below the limit.
  const double volume = box_volume(s);
  const double longest = std::max({s.length_x, s.length_y, d == 3 ? s.length_z : 0.0});
  const PackingLimit limit = packing_limit(c, sizes, volume, !in.has("initial.from"));
  const double sigma_min = longest / (kMaxBoxOverDiameter * sizes.smallest);
  const double sigma_max = reference_diameter_for(d, limit.value, sizes.sum_of_powers, volume);
  const std::string context = fmt::format(
      " for N = {} and system.box = {} (at most {:g} diameters across the box, so that positions resolve contacts; {})",
      s.particles, box_text(s), kMaxBoxOverDiameter, limit.reason);
  if (!(sigma_min < sigma_max)) {
    throw ConfigError{fmt::format("system.box = {} is too elongated for N = {}: no diameter keeps every side within {:g} "
                                  "diameters below the packing limit {}; allowed aspect ratios up to {:g}",
                                  box_text(s), s.particles, kMaxBoxOverDiameter, limit.value,
                                  d == 2 ? 4.0 * limit.value * std::pow(kMaxBoxOverDiameter * sizes.smallest, 2) /
                                               (M_PI * sizes.sum_of_powers)
                                         : std::sqrt(6.0 * limit.value * std::pow(kMaxBoxOverDiameter * sizes.smallest, 3) /
                                                     (M_PI * sizes.sum_of_powers)))};
  }
  const NumberRange diameters{sigma_min, sigma_max, false, !limit.inclusive};
  const NumberRange fractions{packing_fraction(d, sizes.sum_of_powers, sigma_min, volume), limit.value, false,
                              !limit.inclusive};
  const auto nu = in.number(nu_key, fractions, context);
  const auto diameter = in.number("system.diameter", diameters, context);
  if (nu && diameter) {
    throw ConfigError{fmt::format("{} and system.diameter are both set: give one of them (the other follows from ν = "
                                  "π Σσ^d/({} V))", nu_key, d == 3 ? 6 : 4)};
  }
  const double given = diameter ? *diameter : nu.value_or(kDefaultPackingFraction);
  if (!diameter && !fractions.contains(given)) {  // only the default can be out of range here
    throw ConfigError{fmt::format("{} = {} (the default) is out of range: allowed {}{}", nu_key, given,
                                  fractions.text(), context)};
  }
  c.reference_diameter = diameter ? given : reference_diameter_for(d, given, sizes.sum_of_powers, volume);
  // ν → σ̄ → ν rounds: a ν at the limit (allowed) may come back an ulp above it.  σ̄ steps down by
  // ulps until it does not, so that a ν the range allows is never refused for round-off.
  for (int step = 0; !diameter && step < 16 && limit.inclusive &&
                     packing_fraction(d, sizes.sum_of_powers, c.reference_diameter, volume) > limit.value;
       ++step) {
    c.reference_diameter = std::nextafter(c.reference_diameter, 0.0);
  }
  s.diameter = c.reference_diameter * sizes.largest;  // the engine sizes its cells by the largest
  // ν is always the one of σ̄, so that a configuration re-read from to_toml() (which stores σ̄) is
  // identical in every field.
  c.packing_fraction = packing_fraction(d, sizes.sum_of_powers, c.reference_diameter, volume);
  if (!(limit.inclusive ? c.packing_fraction <= limit.value : c.packing_fraction < limit.value)) {
    // A value just inside a rounded bound can still reach it.
    const std::string key = diameter ? "system.diameter" : nu_key;
    throw ConfigError{fmt::format("{} = {} gives packing fraction {}, beyond the limit {}: allowed {}{}", key, given,
                                  c.packing_fraction, limit.value, (diameter ? diameters : fractions).text(), context)};
  }
}

std::string geometry_to_toml(const RunConfig& c) {
  const SystemParams& s = c.system;
  const SizeDistribution& dist = c.diameters;
  std::string out = fmt::format("dimension = {}\nparticles = {}\ndiameter = {:.17g}  # {} = {:.17g}", s.dimension,
                                s.particles, c.reference_diameter,
                                s.dimension == 2 ? "area_fraction" : "packing_fraction (volume)", c.packing_fraction);
  if (!dist.monodisperse()) out += fmt::format(", largest diameter {:.17g}", s.diameter);
  switch (dist.kind) {
    case SizeDistributionKind::kMonodisperse:
      out += "\ndiameters = { distribution = \"monodisperse\" }\n";
      break;
    case SizeDistributionKind::kBidisperse:
      out += fmt::format("\ndiameters = {{ distribution = \"bidisperse\", ratio = {:.17g}, fraction = {:.17g} }}\n",
                         dist.ratio, dist.fraction);
      break;
    case SizeDistributionKind::kUniform:
    case SizeDistributionKind::kLogNormal:
      out += fmt::format("\ndiameters = {{ distribution = \"{}\", width = {:.17g} }}\n",
                         dist.kind == SizeDistributionKind::kUniform ? "uniform" : "lognormal", dist.width);
      break;
  }
  out += dist.species_masses ? fmt::format("masses = [{:.17g}, {:.17g}]\n", dist.species_masses->first,
                                           dist.species_masses->second)
                             : "masses = \"volume\"\n";
  out += s.dimension == 3 ? fmt::format("box = [{:.17g}, {:.17g}, {:.17g}]\n", s.length_x, s.length_y, s.length_z)
                          : fmt::format("box = [{:.17g}, {:.17g}]\n", s.length_x, s.length_y);
  return out;
}

ParticleSizes particle_sizes(const RunConfig& c) {
  return particle_sizes(c.diameters, c.system.dimension, c.system.particles, c.reference_diameter, c.seed);
}

}  // namespace granule
