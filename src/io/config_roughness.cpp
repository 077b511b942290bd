#include "io/config_roughness.hpp"

#include <fmt/format.h>

#include <cmath>

#include "io/input_ranges.hpp"

namespace granule {

namespace {

// Uniform disks and spheres: I = m σ²/8 and m σ²/10, i.e. q = ½ and 2/5 of m σ²/4.
constexpr double kUniformDiskInertia = 0.5;
constexpr double kUniformSphereInertia = 0.4;

}  // namespace

void resolve_roughness(const ConfigReader& in, RunConfig& c) {
  RoughnessParams& r = c.system.roughness;
  const auto beta = in.number("system.tangential_restitution", kTangentialRestitutions,
                              " (β of the contact points' tangential velocity: −1 smooth, +1 perfectly rough)");
  r.rough = beta.has_value();
  if (!r.rough) {
    for (const char* key : {"system.inertia_factor", "system.friction", "initial.rotational_temperature"}) {
      if (in.has(key)) {
        throw ConfigError{fmt::format("{} is for rough grains: set system.tangential_restitution = β in [-1, 1] "
                                      "(grains with spin) to use it", key)};
      }
    }
    return;
  }
  r.tangential_restitution = *beta;
  const double uniform = c.system.dimension == 3 ? kUniformSphereInertia : kUniformDiskInertia;
  r.inertia_factor = in.number("system.inertia_factor", kInertiaFactors,
                               fmt::format(" (q of I = q m σ²/4: {} for uniform {})", uniform,
                                           c.system.dimension == 3 ? "spheres" : "disks"))
                         .value_or(uniform);
  r.friction = in.number("system.friction", kFrictions, " (Coulomb μ: the tangential impulse is at most μ times the "
                                                        "normal one; absent: no limit)")
                   .value_or(r.friction);
  if (const auto ratio = c.initial_temperature_over_steady) {
    throw ConfigError{fmt::format("initial.temperature_over_steady = {} needs the T₀ of thesis eq (4.5), which is for "
                                  "smooth disks: with system.tangential_restitution give initial.temperature", *ratio)};
  }
  if (c.initial_from) return;  // the spins come with the state
  const auto rotational = in.number_if("initial.rotational_temperature",
                                       [](double t) { return t == 0.0 || kTemperatureRange.contains(t); },
                                       "0 (no spin) or " + kTemperatureRange.text() + " (T_rot per rotational degree "
                                       "of freedom, ⟨I ω²⟩ for disks, ⟨I |ω|²⟩/3 for spheres)");
  c.initial_rotational_temperature = rotational.value_or(c.initial_temperature);
}

std::string roughness_to_toml(const RunConfig& c) {
  const RoughnessParams& r = c.system.roughness;
  if (!r.rough) return {};
  std::string out = fmt::format("tangential_restitution = {:.17g}\ninertia_factor = {:.17g}\n", r.tangential_restitution,
                                r.inertia_factor);
  if (std::isfinite(r.friction)) out += fmt::format("friction = {:.17g}\n", r.friction);
  return out;
}

std::string rotational_temperature_to_toml(const RunConfig& c) {
  if (!c.system.roughness.rough || c.initial_from) return {};
  return fmt::format("rotational_temperature = {:.17g}\n", c.initial_rotational_temperature);
}

}  // namespace granule
