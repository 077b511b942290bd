#include "reproduce/cooling_sizes.hpp"

#include <fmt/format.h>

#include <array>
#include <string>
#include <vector>

#include "reproduce/free_cooling.hpp"

namespace granule::reproduce {

namespace {

constexpr double kRestitution = 0.6;
constexpr double kUntilC = 100.0;  // Fig 2.10's frame

std::array<int, 2> sizes(Scale scale) {
  return by_scale(scale, std::array{2000, 8000}, std::array{16000, 64000}, std::array{80000, 320000},
                  std::array{160000, 1000000});
}

}  // namespace

RunGroup cooling_sizes_runs(Scale scale) {
  const std::array<int, 2> n = sizes(scale);
  return {"system_II_sizes", fmt::format(R"(seed = 1995
[system]
particles = {0}
area_fraction = {1}
restitution = {2}
tc_duration = 1e-7   # TC model against inelastic collapse
[initial]
temperature = 1.0
equilibrate = 5
[run]
until_collisions_per_particle = {3}
[output]
every_collisions_per_particle = 0.5
[sweep]
system.particles = [{0}, {4}]
seeds = {5}
)",
                                         n[0], kFreeCoolingAreaFraction, kRestitution, kUntilC, n[1],
                                         by_scale(scale, 1, 3, 3, 3))};
}

void add_cooling_size_claims(Scale scale, const GroupOutputs& group, StudyOutcome& out) {
  for (const int particles : sizes(scale)) {
    const std::vector<const PointOutputs*> points = points_with(group, "system.particles", std::to_string(particles));
    if (points.empty()) continue;
    const PointOutputs& first = *points.front();
    const double estimate = linear_stability_onset_c(kRestitution, particles, summary_number(first, "diameter"),
                                                     summary_number(first, "box.0"));
    std::vector<double> temperature, energy;
    int without_onset = 0;
    for (const PointOutputs* p : points) {
      const CoolingMeasures m = measure_cooling(*p, estimate / 3.0);
      without_onset += std::isfinite(m.onset_c) ? 0 : 1;
      temperature.push_back(m.late_exponent);
      energy.push_back(m.late_energy_exponent);
    }
    const std::string id = fmt::format("chapter2.system_II.n={}", particles);
    const std::string checked = fmt::format("slope of ln {{}} against ln t over c ∈ [2 × onset, {}] of {} run(s) of N = {}, "
                                            "ẽ = 0.6, ν = 0.05",
                                            kUntilC, points.size(), particles);
    Claim late = estimate_claim(
        id + ".late_power_law",
        fmt::format("System II at N = {}: after the transition T̄ keeps its t⁻² decay (hypothesis: a larger box, whose "
                    "clusters take longer to reach its size, shows the thesis's exponent)",
                    particles),
        "thesis §2.1, text before Fig 2.6; Figs 2.6(C), 2.7(C)", -2.0, mean_over(temperature), 0.2,
        "an exponent read off a log-log plot over about a decade of t", fmt::format(fmt::runtime(checked), "T̄"),
        ToleranceKind::absolute);
    Claim clustering = estimate_claim(
        id + ".late_energy_clustering_regime",
        fmt::format("System II at N = {}: late in the clustering regime the kinetic energy decays as E ~ t⁻¹ (dilute disks)",
                    particles),
        "X. Nie, E. Ben-Naim and S. Chen, Phys. Rev. Lett. 89, 204301 (2002), molecular dynamics of 2D free cooling", -1.0,
        mean_over(energy), 0.2, "the exponent of a long-time limit that finite runs approach from their transient",
        fmt::format(fmt::runtime(checked), "E"), ToleranceKind::absolute);
    // Their local velocity fluctuations shrink against the typical velocity as Δv/v ~ t^(−1/4): the
    // fluctuation energy T̄ ~ E (Δv/v)² ~ t^(−3/2).
    Claim local = estimate_claim(
        id + ".late_temperature_clustering_regime",
        fmt::format("System II at N = {}: late in the clustering regime the local fluctuation energy decays as T̄ ~ t^(−3/2) "
                    "(E ~ t⁻¹ with Δv/v ~ t^(−1/4))",
                    particles),
        "X. Nie, E. Ben-Naim and S. Chen, Phys. Rev. Lett. 89, 204301 (2002): E ~ t⁻¹ and Δv/v ~ t^(−1/4)", -1.5,
        mean_over(temperature), 0.2,
        "the exponent of a long-time limit that finite runs approach from their transient; Δv of cells of about 20 grains",
        fmt::format(fmt::runtime(checked), "T̄ (velocities relative to each cell's mean)"), ToleranceKind::absolute);
    if (without_onset > 0) {
      late.unresolvable = clustering.unresolvable = local.unresolvable =
          "no clustering onset within the run, so no post-transition decay to fit";
    }
    out.claims.push_back(late);
    out.claims.push_back(clustering);
    out.claims.push_back(local);
  }
}

}  // namespace granule::reproduce
