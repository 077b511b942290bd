#include "reproduce/rough_shear.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "io/spins_file.hpp"

namespace granule::reproduce {

namespace {

constexpr const char* kGroup = "rough_shear";
constexpr const char* kSpins = "spins.h5";
constexpr int kFramesAnalysed = 20;  // the last frames: the flow has left its start (c ≥ half the run)

}  // namespace

RunGroup rough_shear_runs(Scale scale, int seeds) {
  const double until_c = by_scale(scale, 10.0, 60.0, 200.0, 200.0);
  return {kGroup, fmt::format(R"(seed = 2244
[system]
particles = {0}
area_fraction = 0.05
box = [1.0, 1.0]
restitution = 0.6
tangential_restitution = -0.8
inertia_factor = 0.5
tc_duration = 1e-7   # TC model against inelastic collapse, far below the mean free time
[boundary]
kind = "lees-edwards"
shear_velocity = 100.0
[initial]
temperature = 1.0
equilibrate = 1
[run]
until_collisions_per_particle = {1}
[output]
every_collisions_per_particle = 1
snapshot_every_collisions_per_particle = {2}
[sweep]
seeds = {3}
)",
                              by_scale(scale, 600, 4000, 20000, 20000), until_c, until_c / (2.0 * kFramesAnalysed), seeds)};
}

PointAnalysis rough_shear_spins_analysis() {
  return {kGroup,
          {"analyze", "spins", "{run}", "--frames", fmt::format("-{}:", kFramesAnalysed), "--out", std::string("{run}/") + kSpins},
          kSpins};
}

void add_spin_claim(const GroupOutputs& group, StudyOutcome& out) {
  std::vector<SpinsSummary> runs;
  std::string unreadable;
  for (const PointOutputs* p : points_with(group)) {
    try {
      runs.push_back(read_spins_summary(p->directory + "/" + kSpins));
    } catch (const std::exception& error) {
      unreadable = error.what();  // the claim then counts fewer runs, and says so
    }
  }
  // The runs are independent: their mean, with the frames' standard errors combined.
  double sum = 0.0, variance = 0.0, pairs = 0.0;
  std::int64_t frames = 0;
  for (const SpinsSummary& s : runs) {
    sum += s.contact;
    variance += s.contact_error * s.contact_error;
    pairs += s.contact_pairs;
    frames += s.frames;
  }
  const double n = static_cast<double>(runs.size());
  Claim c;
  c.id = "appendix_c.fig_c4.neighbours_spin_opposite";
  c.statement = "Fig C.4: under shear, rough disks close together spin in opposite senses: the spin fluctuations of "
                "grains in contact are anticorrelated, C_contact < 0";
  c.location = "Fig C.4 caption (N = 20000, ν = 0.05, ẽ = 0.6, β = −0.8)";
  // The caption states a sign, not a number: any anticorrelation resolved at 2σ agrees.  −0.5 only
  // carries the sign (the middle of the possible anticorrelations, [−1, 0]).
  c.expected = -0.5;
  c.tolerance_kind = ToleranceKind::sign;
  c.tolerance_reason = "the caption claims a sign, not a number: C_contact < 0 beyond 2σ agrees, > 0 beyond 2σ disagrees";
  c.measured = runs.empty() ? NAN : sum / n;
  c.error = runs.empty() ? NAN : std::sqrt(variance) / n;
  c.checked = fmt::format(
      "C_contact = ⟨δω_i δω_j⟩/⟨δω²⟩ over pairs closer than 1.1 σ, δω = ω − the frame's mean spin (≈ −γ/2), from `granule "
      "analyze spins` of the last {} snapshots of each run (rough_shear: ν = 0.05, ẽ = 0.6, β = −0.8, U = 100); {} run(s), "
      "{} frames, {:.0f} pairs in contact; error: the standard error of the frames' values, frames taken as independent",
      kFramesAnalysed, runs.size(), frames, pairs);
  if (runs.empty()) c.unresolvable = unreadable.empty() ? "no run finished" : "no spins.h5 could be read: " + unreadable;
  out.claims.push_back(c);

  Figure f{.name = "appendix_c_fig_c4_spin_correlation", .thesis_figure = "Fig C.4",
           .caption = "Rough disks under shear (ν = 0.05, ẽ = 0.6, β = −0.8): the thesis colours the disks by their spin; here "
                      "the spin correlation of pairs against their distance, overall and along the flow and the gradient",
           .x_label = "r / σ", .y_label = "C(r) = ⟨δω_i δω_j⟩ / ⟨δω²⟩", .series = {}};
  if (!runs.empty()) {
    const char* labels[kPairDirections] = {"all pairs", "along the flow x", "along the gradient y"};
    for (std::size_t d = 0; d < kPairDirections; ++d) f.series.push_back({labels[d], runs.front().r, runs.front().correlation[d], {}, false});
    f.series.push_back({"0", {runs.front().r.front(), runs.front().r.back()}, {0.0, 0.0}, {}, true});
  }
  out.figures.push_back(f);
}

}  // namespace granule::reproduce
