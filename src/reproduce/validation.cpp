// The validation study: Granule against literature independent of the thesis (docs/reproduce.md).
// - Elastic hard disks: the virial pressure against Henderson's equation of state and the collision
//   rate against Enskog's with Henderson's contact value (both exact relations of equilibrium hard
//   disks given the true g(σ); Henderson, Mol. Phys. 30, 971 (1975)).
// - Homogeneous cooling of a dilute inelastic gas: Haff's law with the Sonine-corrected cooling rate
//   (van Noije and Ernst, Granular Matter 1, 57 (1998)), before clustering sets in.
// - Dilute steady shear: T̄ against the kinetic theory of Jenkins and Richman, (3.2).
// Every formula comes from src/theory.
#include <fmt/format.h>

#include <cmath>

#include "reproduce/study.hpp"
#include "theory/hard_spheres.hpp"
#include "theory/homogeneous_cooling.hpp"
#include "theory/kinetic_scales.hpp"
#include "theory/steady_shear.hpp"

namespace granule::reproduce {

namespace {

constexpr const char* kDensities[] = {"0.1", "0.3", "0.5"};
constexpr double kCoolingRestitution = 0.9;
constexpr double kShearRestitution = 0.9;

std::vector<RunGroup> validation_runs(Scale scale) {
  const int n = by_scale(scale, 400, 2000, 20000, 40000);
  const int seeds = by_scale(scale, 1, 3, 3, 3);
  const double elastic_c = by_scale(scale, 6.0, 40.0, 40.0, 40.0);
  const double cooling_c = by_scale(scale, 4.0, 8.0, 8.0, 8.0);
  const double shear_c = by_scale(scale, 30.0, 200.0, 200.0, 200.0);
  return {
      {"elastic", fmt::format(R"(seed = 1
[system]
particles = {0}
restitution = 1.0
[initial]
equilibrate = 5
[run]
until_collisions_per_particle = {1}
[output]
every_collisions_per_particle = 0.5
[sweep]
system.area_fraction = [{2}]
seeds = {3}
)",
                              n, elastic_c, fmt::join(kDensities, ", "), seeds)},
      {"cooling", fmt::format(R"(seed = 11
[system]
particles = {0}
area_fraction = 0.05
restitution = {1}
[initial]
equilibrate = 5
[run]
until_collisions_per_particle = {2}
[output]
every_collisions_per_particle = 0.25
[sweep]
seeds = {3}
)",
                              n, kCoolingRestitution, cooling_c, seeds)},
      {"shear", fmt::format(R"(seed = 21
[system]
particles = {0}
area_fraction = 0.05
restitution = {1}
tc_duration = 1e-7
[boundary]
kind = "lees-edwards"
shear_velocity = 100.0
[initial]
temperature_over_steady = 1.0
equilibrate = 5
[run]
until_collisions_per_particle = {2}
[output]
every_collisions_per_particle = 2
[sweep]
seeds = {3}
)",
                            by_scale(scale, 400, 2000, 20000, 20000), kShearRestitution, shear_c, seeds)},
  };
}

// Samples after the first fifth of the run: the pre-run equilibrated the gas, the rest is margin.
double settled_from(const PointOutputs& p) { return p.samples.back().c / 5.0; }

void add_elastic_claims(const GroupOutputs& group, StudyOutcome& out) {
  FigureSeries z_measured{"Granule: 1 + P_coll/P_kin", {}, {}, {}, false}, z_henderson{"Henderson (1975)", {}, {}, {}, true};
  for (double nu = 0.02; nu <= 0.62; nu += 0.02) {
    z_henderson.x.push_back(nu);
    z_henderson.y.push_back(theory::hard_sphere_compressibility(2, nu));
  }
  for (const char* density : kDensities) {
    const double nu = std::stod(density);
    std::vector<double> z, rate_ratio;
    for (const PointOutputs* p : points_with(group, "system.area_fraction", density)) {
      const double from = settled_from(*p), to = p->samples.back().c;
      const double kinetic = window_mean(p->samples, from, to, [](const DiagnosticsSample& s) { return s.pressure_kinetic; });
      const double collisional =
          window_mean(p->samples, from, to, [](const DiagnosticsSample& s) { return s.pressure_collisional; });
      z.push_back(1.0 + collisional / kinetic);
      const double temperature =
          window_mean(p->samples, from, to, [](const DiagnosticsSample& s) { return s.temperature_global; });
      const double measured_rate = window_mean(p->samples, from, to, [](const DiagnosticsSample& s) { return s.collision_rate; });
      const double diameter = summary_number(*p, "diameter");
      const double enskog = theory::hard_sphere_collision_frequency(2, theory::number_density(2, nu, diameter), diameter,
                                                                    theory::hard_sphere_contact_value(2, nu), temperature, 1.0);
      rate_ratio.push_back(measured_rate / (enskog / 2.0));  // c grows at ω/2: two disks per collision
    }
    const Estimate zm = mean_over(z), rm = mean_over(rate_ratio);
    z_measured.x.push_back(nu);
    z_measured.y.push_back(zm.mean);
    z_measured.error.push_back(zm.error);
    Claim pressure = estimate_claim(
        fmt::format("validation.henderson_pressure.nu={}", density),
        fmt::format("compressibility Z = P/(nT) of elastic hard disks at ν = {}", density),
        "Henderson, Mol. Phys. 30, 971 (1975): Z = (1 + ν²/8)/(1 − ν)²", theory::hard_sphere_compressibility(2, nu), zm, 0.02,
        "Henderson's formula is within ~1 % of simulated hard-disk pressures below freezing; +1 % for N of 10³",
        fmt::format("1 + ⟨pressure_collisional⟩/⟨pressure_kinetic⟩ over c ∈ [c_end/5, c_end] of {} elastic runs (seeds)",
                    zm.count));
    out.claims.push_back(pressure);
    Claim rate = estimate_claim(
        fmt::format("validation.enskog_collision_rate.nu={}", density),
        fmt::format("collision rate of elastic hard disks at ν = {} over Enskog's 2nσχ√(πT), χ Henderson's", density),
        "Enskog collision frequency (Chapman & Cowling); χ(ν) = (1 − 7ν/16)/(1 − ν)², Henderson (1975)", 1.0, rm, 0.02,
        "exact given the true contact value; Henderson's χ is within ~1 % below freezing, +1 % for N of 10³",
        "collision_rate (Δc/Δt) over ω/2 at the run's temperature_global, same window and runs as Z");
    out.claims.push_back(rate);
  }
  out.figures.push_back(
      Figure{.name = "validation_henderson",
             .thesis_figure = "Validation",
             .caption = "Equation of state of elastic hard disks: Granule's virial pressure against Henderson's formula",
             .x_label = "area fraction ν",
             .y_label = "Z = P/(nT)",
             .series = {z_henderson, z_measured}});
}

void add_cooling_claims(const GroupOutputs& group, StudyOutcome& out) {
  const double e = kCoolingRestitution;
  const double a2 = theory::sonine_a2(e, 2);
  std::vector<double> t0_ratio;
  FigureSeries measured{"Granule (seed 1): √(T(0)/T(t)) − 1", {}, {}, {}, false},
      haff{"Haff, Sonine-corrected ζ", {}, {}, {}, true};
  for (const PointOutputs* p : points_with(group)) {
    const DiagnosticsSample& first = p->samples.front();
    const double nu = summary_number(*p, "area_fraction"), diameter = summary_number(*p, "diameter");
    const double omega0 =
        theory::hard_sphere_collision_frequency(2, theory::number_density(2, nu, diameter), diameter,
                                                theory::hard_sphere_contact_value(2, nu), first.temperature_global, 1.0);
    const double t0 = theory::homogeneous_cooling_time(2, e, omega0, a2);
    std::vector<double> t, inverse_root;
    for (const DiagnosticsSample& s : p->samples) {
      t.push_back(s.t / t0);
      inverse_root.push_back(std::sqrt(first.temperature_global / s.temperature_global) - 1.0);
    }
    // Haff: √(T0/T) − 1 = t/t0, a line of slope 1 in t/t0.
    t0_ratio.push_back(fit_line(t, inverse_root).slope);
    if (measured.x.empty()) {
      measured.x = t;
      measured.y = inverse_root;
      haff.x = {0.0, t.back()};
      haff.y = {0.0, t.back()};
    }
  }
  const Estimate r = mean_over(t0_ratio);
  Claim claim = estimate_claim(
      "validation.haff_sonine",
      fmt::format(
          "Haff's law in a dilute inelastic gas (ẽ = {}, ν = 0.05): the cooling time t0 = 2/ζ(T0) with the Sonine-corrected ζ",
          e),
      "Haff, J. Fluid Mech. 134, 401 (1983); ζ and a2: van Noije & Ernst, Granular Matter 1, 57 (1998)", 1.0, r, 0.03,
      fmt::format(
          "Enskog χ at ν = 0.05 and velocity correlations before clustering, ~2 %; the Sonine term itself is {:.2g} %, so this "
          "tests Haff's law with Enskog rates, not the Sonine term",
          100.0 * (theory::sonine_cooling_rate_factor(a2) - 1.0)),
      fmt::format("slope of √(T(0)/T(t)) − 1 against t/t0 (temperature_global) over the whole run ({} seeds), "
                  "before the clustering onset",
                  r.count));
  out.claims.push_back(claim);
  out.figures.push_back(Figure{.name = "validation_haff",
                               .thesis_figure = "Validation",
                               .caption = "Homogeneous cooling: √(T(0)/T) − 1 against t/t0, Haff's law is the diagonal",
                               .x_label = "t / t0",
                               .y_label = "√(T(0)/T(t)) − 1",
                               .series = {haff, measured}});
}

void add_shear_claims(const GroupOutputs& group, StudyOutcome& out) {
  std::vector<double> ratio;
  for (const PointOutputs* p : points_with(group)) {
    const std::size_t half = p->samples.size() / 2;
    const double temperature = window_mean(p->samples, p->samples[half].c, p->samples.back().c,
                                           [](const DiagnosticsSample& s) { return s.temperature_global; });
    const double gamma = summary_number(*p, "shear_velocity") / summary_number(*p, "box.1");
    ratio.push_back(temperature / theory::steady_shear_temperature_jenkins_richman(kShearRestitution, gamma,
                                                                                   summary_number(*p, "diameter"),
                                                                                   summary_number(*p, "area_fraction")));
  }
  const Estimate r = mean_over(ratio);
  Claim claim = estimate_claim(
      "validation.dilute_shear_temperature",
      fmt::format("steady T of a dilute sheared gas (ẽ = {}, ν = 0.05) over the Jenkins–Richman dilute limit (3.2)",
                  kShearRestitution),
      "Jenkins & Richman, J. Fluid Mech. 192, 313 (1988), eqs (70)–(71); thesis (3.2)", 1.0, r, 0.10,
      "(3.2) is the ν → 0, nearly elastic limit; at ν = 0.05 (χ = 1.085) and ẽ = 0.9 corrections of ~10 % are expected",
      fmt::format("temperature_global (½⟨(v − u(y))²⟩) over the second half of {} Lees–Edwards runs, γ = 100", r.count));
  out.claims.push_back(claim);
}

StudyOutcome evaluate_validation(Scale, const StudyOutputs& outputs) {
  StudyOutcome out;
  add_elastic_claims(outputs.at("elastic"), out);
  add_cooling_claims(outputs.at("cooling"), out);
  add_shear_claims(outputs.at("shear"), out);
  return out;
}

}  // namespace

Study validation_study() {
  return {"validation",
          "Validation against independent literature",
          "beside the thesis: hard-disk equilibrium, Haff cooling, dilute shear",
          validation_runs,
          evaluate_validation,
          {}};
}

}  // namespace granule::reproduce
